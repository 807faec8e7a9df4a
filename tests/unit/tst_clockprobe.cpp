// SPDX-License-Identifier: MIT
// ClockProbe, the bytes of a clock probe and its answer (UDP and MQTT): what is encoded decodes to
// the same, and anything but exactly the format is refused with a reason.
#include "clock/clockprobe.h"

#include <QTest>

Q_DECLARE_METATYPE(ClockProbe)

namespace {
ClockProbe probe()
{
    ClockProbe p;
    p.nonce = 0x0123456789abcdefULL;
    p.t1 = 1'800'000'000'123'456'789LL;
    p.name = QStringLiteral("cloud");
    p.replyTopic = QStringLiteral("bridgescope/clock/cloud/reply/vehicle-1");
    return p;
}

ClockProbe answer()
{
    ClockSyncState s;
    s.source = ClockSyncState::Source::Chrony;
    s.status = 0;
    s.offsetNs = -1234;
    s.rootDelayNs = 543'210;
    s.rootDispersionNs = 123'456;
    s.frequencyPpb = -12'345;
    s.skewPpb = 50;
    s.reference = QStringLiteral("169.254.169.123");
    ClockProbe p = probe();
    p.replyTopic.clear();
    return p.answer(QStringLiteral("wolke-ü"), p.t1 + 35'000'000, p.t1 + 35'020'000, s);
}

/// `bytes` with the byte at `at` set to `value`.
QByteArray with(QByteArray bytes, int at, char value)
{
    bytes[at] = value;
    return bytes;
}
} // namespace

class TestClockProbe : public QObject
{
    Q_OBJECT

private slots:
    void roundTrips_data()
    {
        QTest::addColumn<ClockProbe>("message");
        QTest::newRow("MQTT probe") << probe();
        ClockProbe udp = probe();
        udp.name.clear();
        udp.replyTopic.clear();
        QTest::newRow("UDP probe, no names") << udp;
        QTest::newRow("answer with chrony's state") << answer();
        ClockProbe ptp = answer();
        ptp.sync = {};
        ptp.sync.source = ClockSyncState::Source::Ptp;
        ptp.sync.status = 1;
        ptp.sync.offsetNs = -12;
        ptp.sync.reference = QStringLiteral("90e2ba.fffe.2a8b3c");
        QTest::newRow("answer with linuxptp's state") << ptp;
        ClockProbe bare = answer();
        bare.sync = {};
        QTest::newRow("answer, not reported") << bare;
        ClockProbe longest = probe();
        longest.name = QString(ClockProbe::kMaxNameBytes, u'n');
        longest.replyTopic = QString(ClockProbe::kMaxReplyTopicBytes, u'r');
        QTest::newRow("longest name and topic") << longest;
    }
    void roundTrips()
    {
        QFETCH(ClockProbe, message);
        const QByteArray bytes = message.encode();
        QCOMPARE(bytes.size(), ClockProbe::kSize);
        const Result<ClockProbe> back = ClockProbe::decode(bytes);
        QVERIFY2(back.ok(), qPrintable(back.ok() ? QString() : back.error().toString()));
        QVERIFY(*back == message);
    }

    void layoutIsStable()
    {
        // docs/formats.md promises these offsets; a prober of another version reads them.
        const QByteArray b = answer().encode();
        QCOMPARE(b.left(6), QByteArray("BSCK\x01\x02"));
        QCOMPARE(quint8(b[6]), quint8(QByteArrayLiteral("wolke-ü").size()));
        QCOMPARE(b.mid(8, 8), QByteArray::fromHex("efcdab8967452301"));
        QCOMPARE(b.mid(40, 8), QByteArray("wolke-\xc3\xbc"));
        QCOMPARE(quint8(b[224]), quint8(1)); // chrony
        QCOMPARE(b.mid(268, 15), QByteArray("169.254.169.123"));
    }

    void refusesWhatIsNotOne_data()
    {
        QTest::addColumn<QByteArray>("bytes");
        QTest::addColumn<QString>("why");
        const QByteArray p = probe().encode();
        const QByteArray a = answer().encode();
        QTest::newRow("empty") << QByteArray() << QStringLiteral("bytes");
        QTest::newRow("one byte short") << p.chopped(1) << QStringLiteral("bytes");
        QTest::newRow("one byte long") << (p + '\0') << QStringLiteral("bytes");
        QTest::newRow("wrong magic") << with(p, 0, 'X') << QStringLiteral("magic");
        QTest::newRow("version 2") << with(p, 4, 2) << QStringLiteral("version");
        QTest::newRow("kind 3") << with(p, 5, 3) << QStringLiteral("kind");
        QTest::newRow("name longer than its field") << with(p, 6, 65) << QStringLiteral("host name");
        QTest::newRow("name with bytes after its length") << with(p, 6, 2) << QStringLiteral("host name");
        QTest::newRow("name with a slash") << with(p, 41, '/') << QStringLiteral("host name");
        QTest::newRow("name with a NUL") << with(with(p, 6, 6), 45, '\0') << QStringLiteral("host name");
        QTest::newRow("name not UTF-8") << with(p, 41, char(0xff)) << QStringLiteral("host name");
        QTest::newRow("reply topic longer than its field")
            << with(p, 7, char(121)) << QStringLiteral("reply topic");
        QTest::newRow("reply topic with a wildcard") << with(p, 104, '#') << QStringLiteral("reply topic");
        QTest::newRow("probe with a t2") << with(p, 24, 1) << QStringLiteral("server fields");
        QTest::newRow("probe with a sync state") << with(p, 224, 1) << QStringLiteral("server fields");
        QTest::newRow("answer without a name") << with(a, 6, 0) << QStringLiteral("host");
        QTest::newRow("answer with t3 before t2")
            << with(a, 39, char(0x80)) << QStringLiteral("t3 before t2");
        QTest::newRow("unknown sync source") << with(a, 224, 3) << QStringLiteral("sync state");
        QTest::newRow("leap status 4") << with(a, 225, 4) << QStringLiteral("sync state");
        QTest::newRow("reserved byte set") << with(a, 227, 1) << QStringLiteral("sync state");
        QTest::newRow("reference too long") << with(a, 226, 21) << QStringLiteral("sync state");
        QTest::newRow("reference with a space") << with(a, 270, ' ') << QStringLiteral("sync state");
        const QByteArray bare = [] {
            ClockProbe b = answer();
            b.sync = {};
            return b.encode();
        }();
        QTest::newRow("no source but sync fields") << with(bare, 240, 1) << QStringLiteral("sync state");
    }
    void refusesWhatIsNotOne()
    {
        QFETCH(QByteArray, bytes);
        QFETCH(QString, why);
        const Result<ClockProbe> decoded = ClockProbe::decode(bytes);
        QVERIFY(!decoded.ok());
        QVERIFY2(decoded.error().toString().contains(why), qPrintable(decoded.error().toString()));
    }

    void namesAreTopicLevels_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<bool>("valid");
        QTest::newRow("plain") << QStringLiteral("cloud") << true;
        QTest::newRow("dots and dashes") << QStringLiteral("edge-1.lab") << true;
        QTest::newRow("umlaut") << QStringLiteral("wolke-ü") << true;
        QTest::newRow("64 bytes") << QString(64, u'a') << true;
        QTest::newRow("65 bytes") << QString(65, u'a') << false;
        QTest::newRow("33 two-byte letters") << QString(33, QChar(0xfc)) << false;
        QTest::newRow("empty") << QString() << false;
        QTest::newRow("slash") << QStringLiteral("a/b") << false;
        QTest::newRow("plus") << QStringLiteral("a+") << false;
        QTest::newRow("hash") << QStringLiteral("#") << false;
        QTest::newRow("space") << QStringLiteral("a b") << false;
        QTest::newRow("newline") << QStringLiteral("a\nb") << false;
    }
    void namesAreTopicLevels()
    {
        QFETCH(QString, name);
        QFETCH(bool, valid);
        QCOMPARE(ClockProbe::isValidName(name), valid);
    }
};

QTEST_APPLESS_MAIN(TestClockProbe)
#include "tst_clockprobe.moc"
