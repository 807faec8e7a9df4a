// SPDX-License-Identifier: MIT
#include "eventthrottle.h"

#include <algorithm>

using namespace Qt::StringLiterals;

namespace {
constexpr qint64 kSecond = 1'000'000'000LL;
}

EventThrottle::EventThrottle(int burst, int perSecond)
    : m_burst(std::max(burst, 1))
    , m_perSecond(std::max(perSecond, 1))
    , m_tokens(m_burst)
{ }

void EventThrottle::refill(qint64 nowNs)
{
    if (m_refilledNs > 0 && nowNs > m_refilledNs)
        m_tokens = std::min<double>(m_burst, m_tokens + double(nowNs - m_refilledNs) / 1e9 * m_perSecond);
    if (nowNs > m_refilledNs)
        m_refilledNs = nowNs;
}

bool EventThrottle::admit(const WatchEvent& e, qint64 nowNs)
{
    refill(nowNs);
    if (m_tokens >= 1) {
        m_tokens -= 1;
        return true;
    }
    ++m_heldBackTotal;
    if (m_started + m_ended == 0)
        m_firstHeldNs = nowNs;
    ++(e.endNs > 0 ? m_ended : m_started);
    for (const QString& r : e.reasons)
        ++m_reasons[r];
    return false;
}

std::optional<QJsonObject> EventThrottle::heldBackLine(qint64 nowNs, Line when)
{
    if (m_started + m_ended == 0 || (when == Line::Paced && nowNs - m_saidNs < kSecond))
        return std::nullopt;
    QJsonObject reasons;
    for (const auto& [name, count] : m_reasons)
        reasons.insert(name, double(count));
    QJsonObject line {
        {u"event"_s, u"held_back"_s},
        {u"started"_s, double(m_started)},
        {u"ended"_s, double(m_ended)},
        {u"reasons"_s, reasons},
        {u"since"_s, WatchEvent::isoTime(m_firstHeldNs)},
        {u"until"_s, WatchEvent::isoTime(nowNs)},
        {u"held_back_total"_s, double(m_heldBackTotal)},
        {u"detail"_s,
         u"more events than %1 lines a second (after a burst of %2): counted, not written"_s.arg(m_perSecond)
             .arg(m_burst)}};
    m_started = m_ended = 0;
    m_reasons.clear();
    m_saidNs = nowNs;
    return line;
}
