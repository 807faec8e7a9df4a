// SPDX-License-Identifier: MIT
#include "clock/clockbudget.h"

#include <algorithm>

ClockBudget::ClockBudget(double perPeerHz, double totalHz, int maxPeers)
    : m_perPeerHz(perPeerHz)
    , m_totalHz(totalHz)
    , m_maxPeers(maxPeers)
{
    m_total.tokens = totalHz;
    m_total.lastNs = -1;
}

void ClockBudget::refill(Bucket& b, double rateHz, qint64 nowNs)
{
    if (b.lastNs >= 0 && nowNs > b.lastNs)
        b.tokens = std::min(rateHz, b.tokens + rateHz * double(nowNs - b.lastNs) / 1e9);
    b.lastNs = std::max(b.lastNs, nowNs);
}

void ClockBudget::forgetIdle(qint64 nowNs)
{
    for (auto it = m_peers.begin(); it != m_peers.end();) {
        refill(*it, m_perPeerHz, nowNs);
        if (it->tokens >= m_perPeerHz)
            it = m_peers.erase(it);
        else
            ++it;
    }
}

bool ClockBudget::allow(const QString& peer, qint64 nowNs)
{
    refill(m_total, m_totalHz, nowNs);
    auto it = m_peers.find(peer);
    if (it == m_peers.end()) {
        if (m_peers.size() >= m_maxPeers)
            forgetIdle(nowNs);
        if (m_peers.size() >= m_maxPeers)
            return false;
        it = m_peers.insert(peer, Bucket {m_perPeerHz, nowNs});
    }
    refill(*it, m_perPeerHz, nowNs);
    if (it->tokens < 1 || m_total.tokens < 1)
        return false;
    it->tokens -= 1;
    m_total.tokens -= 1;
    return true;
}
