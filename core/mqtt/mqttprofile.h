// SPDX-License-Identifier: MIT
#pragma once

#include "base/result.h"

#include <QCoreApplication>
#include <QList>
#include <QString>
#include <QStringList>

/// How to reach a broker: a connection profile as the user saves it.
///
/// Passwords live only in memory here; ProfileStore never writes them to QSettings and
/// PasswordStore keeps them in the system keyring (or not at all).
struct MqttProfile
{
    QString name = QStringLiteral("local broker");
    QString url
        = QStringLiteral("tcp://localhost:1883"); ///< tcp://, ssl://, mqtt://, mqtts://, ws://, wss://
    int mqttVersion = 4; ///< 4 = MQTT 3.1.1, 5 = MQTT 5
    QString clientId; ///< empty: a random "bridgescope-..." id
    int keepAliveSeconds = 60;
    bool cleanSession = true;
    QString username;
    QString password; ///< never stored in settings
    QString caFile;
    QString certFile;
    QString keyFile;
    QString keyPassword; ///< never stored in settings
    bool verifyServer = true;
    QStringList filters = {QStringLiteral("#")};
    bool brokerStatistics = false; ///< also subscribe $SYS/#
    int historyDepth = 20; ///< payloads kept per topic

    bool isTls() const;
    /// Checks the URL (scheme, host, port) and the filters; the message says what is wrong.
    Status validate() const;
    /// The URL with the scheme Paho understands (mqtt:// -> tcp://, mqtts:// -> ssl://).
    QString pahoUri() const;
    /// A profile for `url`; credentials in it (`tcp://user:pass@host`) move to username and
    /// password, so that the URL, which is shown, logged and stored, never holds them.
    static MqttProfile fromUrl(const QString& url);
    /// `url` without user and password.
    static QString withoutCredentials(const QString& url);
};

/// Saved connection profiles (QSettings), without any password.
class ProfileStore
{
    Q_DECLARE_TR_FUNCTIONS(ProfileStore)
public:
    static QList<MqttProfile> load();
    static void save(const QList<MqttProfile>& profiles);
};
