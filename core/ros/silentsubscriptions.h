// SPDX-License-Identifier: MIT
#pragma once

#include <functional>
#include <QHash>
#include <QList>
#include <QSet>
#include <QString>

/// Which silent ROS 1 subscriptions to ask their publishers again for, within bounds.
///
/// roscpp asks a publisher for a topic (requestTopic) once, when the master names it; when that
/// request fails (the publisher's node is busy with 10,000 other requests, out of descriptors, a
/// moment away), roscpp does not ask again until the master names a publisher of the topic anew.
/// The subscription then stays silent while the publisher talks to everyone else. A candidate (a
/// subscription that has heard nothing yet, see RosMonitor) is silent while the master lists a
/// publisher of its topic (other than this process); once silent for kSilentNs it is checked
/// (roscpp's count of connected publishers, which walks every subscription of the process, so at
/// most kMaxChecksPerPass a pass, in turn) and, with none connected (a request on its way counts
/// as none: roscpp does not say), asked about again; the next time after twice as long (at most
/// kMaxBackoffNs), at most kMaxPerPass a pass, so that a publisher that refuses every request costs
/// one request every five minutes, not a loop. Plain bookkeeping: the caller asks roscpp.
class SilentSubscriptions
{
public:
    static constexpr qint64 kSilentNs = 10'000'000'000;
    static constexpr qint64 kMaxBackoffNs = 300'000'000'000;
    static constexpr int kMaxPerPass = 50;
    static constexpr int kMaxChecksPerPass = 100;

    /// The topics the master lists a publisher of, not counting this process.
    void setListed(QSet<QString> topics) { m_listed = std::move(topics); }
    /// One pass over the candidates at `nowNs`; `connected(topic)` tells the publishers connected
    /// to the subscription. The topics to ask about again now.
    QList<QString> pass(qint64 nowNs, const QList<QString>& candidates,
                        const std::function<int(const QString&)>& connected);
    /// How many times `topic` was given to ask about again in its current silence (0: none).
    int tries(const QString& topic) const { return m_silent.value(topic).tries; }
    /// Topics to ask about again given since the start.
    quint64 made() const { return m_made; }
    /// Candidates silent for kSilentNs or longer at the last pass (not found connected).
    int silent() const { return m_silentLong; }

private:
    struct Silence
    {
        qint64 sinceNs = 0;
        qint64 nextNs = 0; ///< the next try, not before
        int tries = 0;
    };
    QSet<QString> m_listed;
    QHash<QString, Silence> m_silent;
    quint64 m_made = 0;
    quint64 m_cursor = 0; ///< where the next pass starts checking, in turn
    int m_silentLong = 0;
};
