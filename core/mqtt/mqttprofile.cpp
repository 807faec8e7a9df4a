// SPDX-License-Identifier: MIT
#include "mqttprofile.h"

#include "yaml/secrets.h"
#include "text/topicnames.h"

#include <QSettings>
#include <QUrl>

using namespace Qt::StringLiterals;

namespace {
class ProfileText
{
    Q_DECLARE_TR_FUNCTIONS(MqttProfile)
};
} // namespace

bool MqttProfile::isTls() const
{
    const QString scheme = QUrl(url).scheme();
    return scheme == u"ssl"_s || scheme == u"mqtts"_s || scheme == u"wss"_s;
}

Status MqttProfile::validate() const
{
    const QUrl u(url, QUrl::StrictMode);
    // Never echo the URL as given: what did not parse may be a password.
    const QString shown = Secrets::redactedUrl(url);
    static const QStringList schemes = {u"tcp"_s, u"ssl"_s, u"mqtt"_s, u"mqtts"_s, u"ws"_s, u"wss"_s};
    if (!u.isValid() || u.scheme().isEmpty())
        return LocatedError {
            ProfileText::tr("'%1' is not a broker URL; write it as tcp://host:1883 or ssl://host:8883.")
                .arg(shown)};
    if (!schemes.contains(u.scheme()))
        return LocatedError {
            ProfileText::tr("'%1' is not a broker scheme; use tcp, ssl, mqtt, mqtts, ws or wss.")
                .arg(u.scheme())};
    if (u.host().isEmpty())
        return LocatedError {ProfileText::tr("'%1' names no host.").arg(shown)};
    if (u.port() == 0)
        return LocatedError {ProfileText::tr("'%1': port 0 is not a port.").arg(shown)};
    if (mqttVersion != 4 && mqttVersion != 5)
        return LocatedError {ProfileText::tr("MQTT version must be 3.1.1 (4) or 5.")};
    if (filters.isEmpty())
        return LocatedError {ProfileText::tr("Subscribe at least one topic filter, e.g. #.")};
    for (const QString& f : filters) {
        QString why;
        if (!TopicNames::isValidMqttTopic(f, false, &why))
            return LocatedError {ProfileText::tr("Filter '%1': %2.").arg(f, why)};
    }
    if (!certFile.isEmpty() && keyFile.isEmpty())
        return LocatedError {ProfileText::tr("A client certificate needs its key file.")};
    return {};
}

QString MqttProfile::pahoUri() const
{
    QUrl u(url);
    if (u.scheme() == u"mqtt"_s)
        u.setScheme(u"tcp"_s);
    else if (u.scheme() == u"mqtts"_s)
        u.setScheme(u"ssl"_s);
    if (u.port() < 0)
        u.setPort(u.scheme() == u"ssl"_s
                      ? 8883
                      : (u.scheme() == u"ws"_s ? 80 : (u.scheme() == u"wss"_s ? 443 : 1883)));
    return u.toString();
}

MqttProfile MqttProfile::fromUrl(const QString& url)
{
    MqttProfile p;
    p.url = withoutCredentials(url);
    p.name = p.url;
    if (p.url.size() != url.size()) {
        // What was taken out is "user[:password]@", percent-encoded as URLs are.
        const qsizetype start = url.indexOf(u"://"_s) + 3;
        const QString userInfo = url.mid(start, url.size() - p.url.size() - 1);
        const qsizetype colon = userInfo.indexOf(u':');
        p.username = QUrl::fromPercentEncoding(userInfo.left(colon < 0 ? userInfo.size() : colon).toUtf8());
        if (colon >= 0)
            p.password = QUrl::fromPercentEncoding(userInfo.mid(colon + 1).toUtf8());
    }
    return p;
}

QString MqttProfile::withoutCredentials(const QString& url)
{
    return Secrets::urlWithoutCredentials(url);
}

QList<MqttProfile> ProfileStore::load()
{
    QList<MqttProfile> out;
    QSettings s;
    const int n = s.beginReadArray(u"mqttProfiles"_s);
    for (int i = 0; i < n; ++i) {
        s.setArrayIndex(i);
        MqttProfile p;
        p.name = s.value(u"name"_s, p.name).toString();
        p.url = s.value(u"url"_s, p.url).toString();
        p.mqttVersion = s.value(u"mqttVersion"_s, p.mqttVersion).toInt();
        p.clientId = s.value(u"clientId"_s).toString();
        p.keepAliveSeconds = s.value(u"keepAlive"_s, p.keepAliveSeconds).toInt();
        p.cleanSession = s.value(u"cleanSession"_s, p.cleanSession).toBool();
        p.username = s.value(u"username"_s).toString();
        p.caFile = s.value(u"caFile"_s).toString();
        p.certFile = s.value(u"certFile"_s).toString();
        p.keyFile = s.value(u"keyFile"_s).toString();
        p.verifyServer = s.value(u"verifyServer"_s, true).toBool();
        p.filters = s.value(u"filters"_s, p.filters).toStringList();
        p.brokerStatistics = s.value(u"brokerStatistics"_s, false).toBool();
        p.historyDepth = s.value(u"historyDepth"_s, p.historyDepth).toInt();
        out << p;
    }
    s.endArray();
    return out;
}

void ProfileStore::save(const QList<MqttProfile>& profiles)
{
    QSettings s;
    s.beginWriteArray(u"mqttProfiles"_s, int(profiles.size()));
    for (int i = 0; i < profiles.size(); ++i) {
        s.setArrayIndex(i);
        const MqttProfile& p = profiles[i];
        // A URL typed with user:password@ keeps them out of the settings file.
        s.setValue(u"name"_s, MqttProfile::withoutCredentials(p.name));
        s.setValue(u"url"_s, MqttProfile::withoutCredentials(p.url));
        s.setValue(u"mqttVersion"_s, p.mqttVersion);
        s.setValue(u"clientId"_s, p.clientId);
        s.setValue(u"keepAlive"_s, p.keepAliveSeconds);
        s.setValue(u"cleanSession"_s, p.cleanSession);
        s.setValue(u"username"_s, p.username);
        s.setValue(u"caFile"_s, p.caFile);
        s.setValue(u"certFile"_s, p.certFile);
        s.setValue(u"keyFile"_s, p.keyFile);
        s.setValue(u"verifyServer"_s, p.verifyServer);
        s.setValue(u"filters"_s, p.filters);
        s.setValue(u"brokerStatistics"_s, p.brokerStatistics);
        s.setValue(u"historyDepth"_s, p.historyDepth);
        // Passwords are deliberately absent: they go to the keyring (PasswordStore) or nowhere.
    }
    s.endArray();
}
