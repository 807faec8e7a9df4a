// SPDX-License-Identifier: MIT
#pragma once

#include "watch/linkdef.h"

#include <deque>
#include <optional>
#include <QHash>

/// The events of a watch: those open now (one per subject) and the last 1,000 that ended.
class EventJournal
{
public:
    static constexpr std::size_t kEndedEvents = 1000;

    /// Ends the open event of `subject` at `nowNs` with `figures`, and returns it (none open: nothing).
    std::optional<WatchEvent> end(const QString& subject, qint64 nowNs, const LinkFigures& figures);
    /// Opens `event` (its subject had none open).
    void open(const WatchEvent& event);
    /// The open event of `subject` gathers the reasons it did not have yet.
    void gather(const QString& subject, const QStringList& reasons);

    /// Open events, oldest first.
    QList<WatchEvent> openEvents() const;
    QList<WatchEvent> endedEvents() const { return {m_ended.begin(), m_ended.end()}; }
    QStringList openSubjects() const { return m_open.keys(); }

private:
    QHash<QString, WatchEvent> m_open; ///< by subject
    std::deque<WatchEvent> m_ended;
};
