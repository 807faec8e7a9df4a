// SPDX-License-Identifier: MIT
#pragma once

#include "watch/linkdef.h"

#include <map>
#include <optional>
#include <QJsonObject>

/// The bound of an event storm: how many event lines a watch writes (stdout, --events-jsonl).
///
/// A bridge of 10,000 links that falls behind puts thousands of links into stalls and out again
/// every few seconds; every change is an event, and the lines ran to hundreds of megabytes. The
/// lines follow a token bucket (a burst of kBurst, then kPerSecond); what it holds back is counted by
/// kind and reason, and said once a second in one line ({"event": "held_back", ...}), so that the
/// output never says less than the watch saw without saying so. The monitor's journal (what is
/// open, the last ended; bounded on its own) and a run file (the record) are not thinned.
class EventThrottle
{
public:
    static constexpr int kBurst = 1000;
    static constexpr int kPerSecond = 100;

    explicit EventThrottle(int burst = kBurst, int perSecond = kPerSecond);
    /// Whether `event`, seen at `nowNs`, gets its line (else it is counted as held back).
    bool admit(const WatchEvent& event, qint64 nowNs);
    enum class Line { Paced, Last };
    /// The line that says what was held back since the last one, at most once a second unless it
    /// is the Last (none when nothing was).
    std::optional<QJsonObject> heldBackLine(qint64 nowNs, Line line = Line::Paced);
    /// Events held back so far, in all.
    quint64 heldBack() const { return m_heldBackTotal; }

private:
    void refill(qint64 nowNs);

    const int m_burst;
    const int m_perSecond;
    double m_tokens;
    qint64 m_refilledNs = 0;
    qint64 m_saidNs = 0;
    qint64 m_firstHeldNs = 0;
    quint64 m_heldBackTotal = 0;
    quint64 m_started = 0; ///< held back since the last line
    quint64 m_ended = 0;
    std::map<QString, quint64> m_reasons;
};
