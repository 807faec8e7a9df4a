// SPDX-License-Identifier: MIT
// AnnouncedTypes: what mqtt_client announced per topic, each change decoded once, bounded (how a
// link uses an announcement is pinned in tst_linkmonitor).
#include "watch/announcedtypes.h"
#include "wire/mqttclientwire.h"

#include <QTest>

using namespace Qt::StringLiterals;

namespace {
const QString kHeaderDefinition
    = u"Header header\nfloat64 value\n"
      u"================================================================================\n"
      u"MSG: std_msgs/Header\nuint32 seq\ntime stamp\nstring frame_id\n"_s;

QByteArray announcement(const QString& type, const QString& definition, bool stamped,
                        RosTypeRegistry::Dialect dialect = RosTypeRegistry::Dialect::Ros1)
{
    return MqttClientWire::encodeType({QString(32, u'a'), type, definition, stamped, dialect});
}
} // namespace

class TestAnnouncedTypes : public QObject
{
    Q_OBJECT
private slots:
    void anAnnouncementSaysTypeStampHeaderAndDialect()
    {
        AnnouncedTypes types;
        const auto a
            = types.add(u"vehicle/pose"_s, announcement(u"test_msgs/Stamped"_s, kHeaderDefinition, true));
        QVERIFY(a);
        QCOMPARE(a->type, u"test_msgs/Stamped"_s);
        QVERIFY(a->stamped);
        QVERIFY(a->header);
        QVERIFY(!a->ros2);
        const auto b = types.add(
            u"cloud/value"_s,
            announcement(u"std_msgs/msg/Float64"_s, QString(), false, RosTypeRegistry::Dialect::Ros2));
        QVERIFY(b);
        QVERIFY(!b->stamped);
        QVERIFY(!b->header);
        QVERIFY(b->ros2);
        QCOMPARE(types.all().size(), 2);
        QCOMPARE(types.all().value(u"vehicle/pose"_s).type, u"test_msgs/Stamped"_s);
    }

    void theSamePayloadAgainIsNotDecodedAgainAChangeIs()
    {
        AnnouncedTypes types;
        const QByteArray stamped = announcement(u"test_msgs/Stamped"_s, kHeaderDefinition, true);
        QVERIFY(types.add(u"vehicle/pose"_s, stamped));
        QVERIFY(!types.add(u"vehicle/pose"_s, stamped));
        const auto changed
            = types.add(u"vehicle/pose"_s, announcement(u"test_msgs/Stamped"_s, kHeaderDefinition, false));
        QVERIFY(changed);
        QVERIFY(!changed->stamped);
        QVERIFY(!types.all().value(u"vehicle/pose"_s).stamped);
    }

    void bytesThatAreNoAnnouncementSayNothing()
    {
        AnnouncedTypes types;
        QVERIFY(!types.add(u"vehicle/pose"_s, "\xff\x00 not json"_ba));
        QVERIFY(types.all().isEmpty());
        QCOMPARE(types.dropped(), quint64(0));
    }

    void topicsPastTheBoundAreCountedNotKept()
    {
        AnnouncedTypes types;
        const QByteArray payload = announcement(u"std_msgs/Float64"_s, u"float64 data\n"_s, false);
        for (int i = 0; i < AnnouncedTypes::kMax + 7; ++i)
            types.add(u"x/%1"_s.arg(i), payload);
        QCOMPARE(types.all().size(), AnnouncedTypes::kMax);
        QCOMPARE(types.dropped(), quint64(7));
        QVERIFY(!types.add(u"x/%1"_s.arg(AnnouncedTypes::kMax + 100), payload));
        QCOMPARE(types.dropped(), quint64(8));
        // A topic already kept still takes changes.
        QVERIFY(types.add(u"x/0"_s, announcement(u"std_msgs/Float64"_s, u"float64 data\n"_s, true)));
    }

    void headerFirstNeedsAHeaderAsTheFirstField()
    {
        QVERIFY(AnnouncedTypes::headerFirst(u"test_msgs/Stamped"_s, kHeaderDefinition));
        QVERIFY(!AnnouncedTypes::headerFirst(u"std_msgs/Float64"_s, u"float64 data\n"_s));
        QVERIFY(!AnnouncedTypes::headerFirst(QString(), kHeaderDefinition));
        QVERIFY(!AnnouncedTypes::headerFirst(u"test_msgs/Late"_s, u"float64 value\n"_s + kHeaderDefinition));
    }
};

QTEST_GUILESS_MAIN(TestAnnouncedTypes)
#include "tst_announcedtypes.moc"
