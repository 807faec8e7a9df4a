// SPDX-License-Identifier: MIT
#pragma once

#include <QCoreApplication>
#include <QDateTime>
#include <QString>
#include <QStringList>

/// What a recording or a watch says while nothing has arrived: what it waits for (which topics, on
/// which broker and ROS master) and since when. One wording for `record`, `watch` and the Measure
/// page's recording.
class WaitingText
{
    Q_DECLARE_TR_FUNCTIONS(WaitingText)
public:
    static constexpr int kNamedTopics = 4; ///< topics named; the rest are counted
    static constexpr qint64 kGraceMs = 5000; ///< silence before it is said

    QString what; ///< "stamp", "MQTT message"
    QStringList topics; ///< where it should come from (empty: any)
    QString broker; ///< without credentials; empty: not waited on
    QString master; ///< without credentials; empty: not waited on
    QDateTime since;

    /// "nothing has arrived since 12:03:04 (5 s): no stamp yet on 12 topics under
    /// /benchmarking_suite/timestamps/ (pointcloud, …, and 8 more) from the broker tcp://… and
    /// the ROS master http://…"
    QString text(const QDateTime& now) const;
    /// "12 topics under /a/ (x, y, …, and 8 more)", "/a/b", or "" for none.
    static QString topicsText(const QStringList& topics);
};
