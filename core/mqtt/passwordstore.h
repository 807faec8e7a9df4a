// SPDX-License-Identifier: MIT
#pragma once

#include <QObject>
#include <QString>

/// Passwords in the system keyring (QtKeychain: Secret Service, KWallet), never in a file.
///
/// Without a keyring the password is simply not kept, and the user is told so; there is no
/// plaintext fallback.
class PasswordStore : public QObject
{
    Q_OBJECT
public:
    explicit PasswordStore(QObject* parent = nullptr);

    void store(const QString& key, const QString& password);
    void fetch(const QString& key);
    void remove(const QString& key);

signals:
    void stored(const QString& key, bool ok, const QString& error);
    void fetched(const QString& key, const QString& password, bool ok, const QString& error);
};
