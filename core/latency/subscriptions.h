// SPDX-License-Identifier: MIT
#pragma once

#include <QObject>
#include <QPointer>
#include <QSet>
#include <QString>

class MessageSource;

/// One user's counted subscriptions on one MessageSource (the Links page's, Map health's, the
/// watch's): holdExactly() monitors the topics it is given that it does not hold yet and
/// unmonitors those it holds and is not given any more, so that two users never end each other's.
/// Destroying it releases everything it holds, unless the source went first (its owner gone:
/// siblings in a window die in the order they were made).
class Subscriptions
{
public:
    Subscriptions() = default;
    /// `owner` owns the source (LiveSources::owner): null once the source is gone.
    Subscriptions(MessageSource* source, QPointer<QObject> owner);
    ~Subscriptions();
    Subscriptions(Subscriptions&& other) noexcept;
    Subscriptions& operator=(Subscriptions&& other) noexcept;
    Subscriptions(const Subscriptions&) = delete;
    Subscriptions& operator=(const Subscriptions&) = delete;

    void holdExactly(const QSet<QString>& wanted);
    const QSet<QString>& held() const { return m_held; }

private:
    void release();

    MessageSource* m_source = nullptr;
    QPointer<QObject> m_owner;
    QSet<QString> m_held;
};
