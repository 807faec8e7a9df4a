// SPDX-License-Identifier: MIT
#include "silentsubscriptions.h"

#include <algorithm>

QList<QString> SilentSubscriptions::pass(qint64 nowNs, const QList<QString>& subscribed,
                                         const std::function<int(const QString&)>& connected)
{
    QList<QString> again;
    QHash<QString, Silence> still;
    m_silentLong = 0;
    for (const QString& topic : subscribed) {
        if (!m_listed.contains(topic) || connected(topic) > 0)
            continue; // no publisher to hear, or one heard: silent no more
        Silence s = m_silent.value(topic, Silence {nowNs, nowNs + kSilentNs, 0});
        if (nowNs - s.sinceNs >= kSilentNs)
            ++m_silentLong;
        if (nowNs >= s.nextNs && again.size() < kMaxPerPass) {
            again.append(topic);
            ++s.tries;
            s.nextNs = nowNs + std::min(kSilentNs << std::min(s.tries, 8), kMaxBackoffNs);
            ++m_made;
        }
        still.insert(topic, s);
    }
    m_silent = std::move(still); // topics no longer silent or subscribed start again from 0
    return again;
}
