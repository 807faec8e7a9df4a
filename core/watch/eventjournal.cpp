// SPDX-License-Identifier: MIT
#include "eventjournal.h"

#include <algorithm>

std::optional<WatchEvent> EventJournal::end(const QString& subject, qint64 nowNs, const LinkFigures& figures)
{
    const auto it = m_open.find(subject);
    if (it == m_open.end())
        return std::nullopt;
    WatchEvent ended = *it;
    m_open.erase(it);
    ended.endNs = std::max(nowNs, ended.startNs); // an end dated back never precedes the start
    ended.atEnd = figures;
    m_ended.push_back(ended);
    if (m_ended.size() > kEndedEvents)
        m_ended.pop_front();
    return ended;
}

void EventJournal::open(const WatchEvent& event)
{
    m_open.insert(event.subject, event);
}

void EventJournal::gather(const QString& subject, const QStringList& reasons)
{
    const auto it = m_open.find(subject);
    if (it == m_open.end())
        return;
    for (const QString& r : reasons)
        if (!it->reasons.contains(r))
            it->reasons << r;
}

QList<WatchEvent> EventJournal::openEvents() const
{
    QList<WatchEvent> out = m_open.values();
    std::sort(out.begin(), out.end(),
              [](const WatchEvent& a, const WatchEvent& b) { return a.startNs < b.startNs; });
    return out;
}
