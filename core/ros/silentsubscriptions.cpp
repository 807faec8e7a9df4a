// SPDX-License-Identifier: MIT
#include "silentsubscriptions.h"

#include <algorithm>

QList<QString> SilentSubscriptions::pass(qint64 nowNs, const QList<QString>& candidates,
                                         const std::function<int(const QString&)>& connected)
{
    QList<QString> again;
    QHash<QString, Silence> still;
    m_silentLong = 0;
    int checks = 0;
    const qsizetype n = candidates.size();
    const qsizetype start = n > 0 ? qsizetype(m_cursor % quint64(n)) : 0;
    for (qsizetype k = 0; k < n; ++k) {
        const QString& topic = candidates.at((start + k) % n);
        if (!m_listed.contains(topic))
            continue; // no publisher to hear
        Silence s = m_silent.value(topic, Silence {nowNs, nowNs + kSilentNs, 0});
        if (nowNs >= s.nextNs && again.size() < kMaxPerPass && checks < kMaxChecksPerPass) {
            ++checks; // roscpp's count walks every subscription of the process: checked when due only
            if (connected(topic) > 0)
                continue; // a publisher connected: silent no more
            again.append(topic);
            ++s.tries;
            s.nextNs = nowNs + std::min(kSilentNs << std::min(s.tries, 8), kMaxBackoffNs);
            ++m_made;
        }
        if (nowNs - s.sinceNs >= kSilentNs)
            ++m_silentLong;
        still.insert(topic, s);
    }
    m_cursor += quint64(checks);
    m_silent = std::move(still); // topics no longer candidates or listed start again from 0
    return again;
}
