// SPDX-License-Identifier: MIT
// Connection profiles: what a valid broker URL is, what gets saved (never a password), and the
// ROS master's XML-RPC encoding.
#include "mqtt/mqttprofile.h"
#include "mqtt/passwordstore.h"
#include "resulttext.h"
#include "ros/rosmasterapi.h"
#include "wire/payloadtext.h"

#include <QFile>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTest>

using namespace Qt::StringLiterals;

class TestMqttProfile : public QObject
{
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName(u"BridgescopeTest"_s);
        QCoreApplication::setApplicationName(u"tst_mqttprofile"_s);
    }

    void urls_data()
    {
        QTest::addColumn<QString>("url");
        QTest::addColumn<bool>("valid");
        QTest::addColumn<QString>("paho");
        QTest::newRow("tcp") << u"tcp://127.0.0.1:1883"_s << true << u"tcp://127.0.0.1:1883"_s;
        QTest::newRow("mqtt default port") << u"mqtt://broker.lan"_s << true << u"tcp://broker.lan:1883"_s;
        QTest::newRow("mqtts") << u"mqtts://broker.lan"_s << true << u"ssl://broker.lan:8883"_s;
        QTest::newRow("ssl with port") << u"ssl://[::1]:8884"_s << true << u"ssl://[::1]:8884"_s;
        QTest::newRow("websocket") << u"ws://localhost:9001/mqtt"_s << true << u"ws://localhost:9001/mqtt"_s;
        QTest::newRow("http") << u"http://localhost"_s << false << QString();
        QTest::newRow("no scheme") << u"localhost:1883"_s << false << QString();
        QTest::newRow("empty") << QString() << false << QString();
    }
    void urls()
    {
        QFETCH(QString, url);
        QFETCH(bool, valid);
        QFETCH(QString, paho);
        const MqttProfile p = MqttProfile::fromUrl(url);
        QString error;
        QCOMPARE(noted(p.validate(), &error), valid);
        if (valid)
            QCOMPARE(p.pahoUri(), paho);
        else
            QVERIFY(!error.isEmpty());
    }

    void filtersAreChecked()
    {
        MqttProfile p;
        p.filters = {u"a/#/b"_s};
        QString error;
        QVERIFY(!noted(p.validate(), &error));
        QVERIFY(error.contains(u"a/#/b"_s));
        p.filters = {u"a/+/b"_s, u"#"_s};
        QVERIFY(noted(p.validate(), &error));
        p.certFile = u"client.pem"_s;
        QVERIFY(!noted(p.validate(), &error)); // a certificate needs its key
    }

    // Regression guard: passwords never reach the settings file.
    void profilesAreSavedWithoutPasswords()
    {
        MqttProfile p = MqttProfile::fromUrl(u"ssl://broker.lan:8883"_s);
        p.name = u"lab"_s;
        p.username = u"alice"_s;
        p.password = u"pa55-word-xyz"_s;
        p.keyPassword = u"key-secret-xyz"_s;
        p.caFile = u"/etc/ca.pem"_s;
        p.filters = {u"vehicle/#"_s, u"cloud/#"_s};
        p.mqttVersion = 5;
        ProfileStore::save({p});
        const QList<MqttProfile> back = ProfileStore::load();
        QCOMPARE(back.size(), 1);
        QCOMPARE(back[0].name, u"lab"_s);
        QCOMPARE(back[0].username, u"alice"_s);
        QCOMPARE(back[0].filters, p.filters);
        QCOMPARE(back[0].mqttVersion, 5);
        QVERIFY(back[0].password.isEmpty());
        QVERIFY(back[0].keyPassword.isEmpty());
        QSettings settings;
        settings.sync();
        QFile file(settings.fileName());
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QByteArray text = file.readAll();
        QVERIFY(text.contains("alice"));
        QVERIFY(!text.contains("pa55-word-xyz"));
        QVERIFY(!text.contains("key-secret-xyz"));
    }

    // Without a keyring service the password is not kept, and that is said; nothing falls back
    // to a file.
    void keyringAnswersEitherWay()
    {
        PasswordStore store;
        QSignalSpy stored(&store, &PasswordStore::stored);
        store.store(u"mqtt/test"_s, u"secret"_s);
        QTRY_COMPARE_WITH_TIMEOUT(stored.size(), 1, 30000);
        const bool ok = stored[0][1].toBool();
        if (!ok)
            QVERIFY(!stored[0][2].toString().isEmpty());
        QSettings settings;
        QFile file(settings.fileName());
        if (file.open(QIODevice::ReadOnly))
            QVERIFY(!file.readAll().contains("secret"));
    }

    void xmlRpcRoundTrip()
    {
        const QByteArray call = RosMasterApi::encodeCall(u"getSystemState"_s, {u"/a<b>"_s, 3, true});
        QVERIFY(call.contains("<methodName>getSystemState</methodName>"));
        QVERIFY(call.contains("<string>/a&lt;b&gt;</string>"));
        QVERIFY(call.contains("<i4>3</i4>"));
        QString error;
        const auto v = noted(
            RosMasterApi::decodeResponse(
                "<?xml "
                "version='1.0'?><methodResponse><params><param><value><array><data><value><int>1</int></"
                "value>"
                "<value><string>ok</string></value><value><array><data><value>/x</value><value><i4>-2</i4></"
                "value>"
                "<value><boolean>1</boolean></value><value><struct><member><name>k</name><value><double>1.5</"
                "double>"
                "</value></member></struct></value></data></array></value></data></array></value></param></"
                "params>"
                "</methodResponse>"),
            &error);
        QVERIFY2(v, qPrintable(error));
        const QVariantList triple = v->toList();
        QCOMPARE(triple[0].toInt(), 1);
        const QVariantList inner = triple[2].toList();
        QCOMPARE(inner[0].toString(), u"/x"_s); // untyped value is a string
        QCOMPARE(inner[1].toInt(), -2);
        QCOMPARE(inner[2].toBool(), true);
        QCOMPARE(inner[3].toMap().value(u"k"_s).toDouble(), 1.5);
    }

    void xmlRpcFaultsAndGarbageAreErrors_data()
    {
        QTest::addColumn<QByteArray>("body");
        QTest::newRow("fault") << QByteArray(
            "<methodResponse><fault><value><struct><member><name>faultCode</name><value>"
            "<int>1</int></value></member><member><name>faultString</name><value>"
            "<string>boom</string></value></member></struct></value></fault></methodResponse>");
        QTest::newRow("garbage") << QByteArray("<html>not xml-rpc");
        QTest::newRow("bad int") << QByteArray(
            "<methodResponse><params><param><value><int>x</int></value></param></params></methodResponse>");
        QTest::newRow("cut") << QByteArray("<methodResponse><params><param><value><array><data><value>");
    }
    void xmlRpcFaultsAndGarbageAreErrors()
    {
        QFETCH(QByteArray, body);
        QString error;
        QVERIFY(!noted(RosMasterApi::decodeResponse(body), &error));
        QVERIFY(!error.isEmpty());
    }

    void payloadsRender()
    {
        QCOMPARE(PayloadText::render("{\"a\":1}", PayloadText::Mode::Auto).mode, PayloadText::Mode::Json);
        QCOMPARE(PayloadText::render("hello", PayloadText::Mode::Auto).mode, PayloadText::Mode::Text);
        const auto hex = PayloadText::render(QByteArray("\x00\x01\xff", 3), PayloadText::Mode::Auto);
        QCOMPARE(hex.mode, PayloadText::Mode::Hex);
        QVERIFY(hex.text.startsWith(u"00000000  00 01 ff"_s));
        const auto cut = PayloadText::render(QByteArray(200000, 'a'), PayloadText::Mode::Text, 1000);
        QCOMPARE(cut.text.size(), 1000);
        QVERIFY(cut.note.contains(u"showing the first"_s));
        QVERIFY(PayloadText::render("{bad", PayloadText::Mode::Json).note.contains(u"not JSON"_s));
    }
};

QTEST_GUILESS_MAIN(TestMqttProfile)
#include "tst_mqttprofile.moc"
