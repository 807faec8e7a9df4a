// SPDX-License-Identifier: MIT
#include "subscriptions.h"

#include "latency/messagesource.h"

#include <utility>

Subscriptions::Subscriptions(MessageSource* source, QPointer<QObject> owner)
    : m_source(source)
    , m_owner(std::move(owner))
{ }

Subscriptions::~Subscriptions()
{
    release();
}

Subscriptions::Subscriptions(Subscriptions&& other) noexcept
    : m_source(std::exchange(other.m_source, nullptr))
    , m_owner(std::move(other.m_owner))
    , m_held(std::exchange(other.m_held, {}))
{ }

Subscriptions& Subscriptions::operator=(Subscriptions&& other) noexcept
{
    if (this != &other) {
        release();
        m_source = std::exchange(other.m_source, nullptr);
        m_owner = std::move(other.m_owner);
        m_held = std::exchange(other.m_held, {});
    }
    return *this;
}

void Subscriptions::holdExactly(const QSet<QString>& wanted)
{
    if (!m_source || !m_owner)
        return;
    for (const QString& topic : std::as_const(m_held))
        if (!wanted.contains(topic))
            m_source->unmonitor(topic);
    for (const QString& topic : wanted)
        if (!m_held.contains(topic))
            m_source->monitor(topic);
    m_held = wanted;
}

void Subscriptions::release()
{
    if (m_source && m_owner)
        for (const QString& topic : std::as_const(m_held))
            m_source->unmonitor(topic);
    m_held.clear();
}
