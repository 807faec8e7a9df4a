// SPDX-License-Identifier: MIT
// Bytes from a shared broker, as an attacker or an unlucky device sends them: every decoder of
// MQTT payloads does bounded work, and every failure is counted for its topic (issue 11).
#include "latency/latencyengine.h"
#include "latency/latencyseries.h"
#include "latency/samplejoiner.h"
#include "mqtt/mqttstampdecoder.h"
#include "resulttext.h"
#include "wire/mqttclientwire.h"
#include "wire/payloadtext.h"
#include "wire/stampcodec.h"

#include <cmath>
#include <limits>
#include <QTest>

using namespace Qt::StringLiterals;

namespace {
MqttMessage msg(const QString& topic, const QByteArray& payload)
{
    MqttMessage m;
    m.topic = topic;
    m.payload = payload;
    m.receivedNs = 1'700'000'000'000'000'000LL;
    return m;
}
} // namespace

class TestHostileInput : public QObject
{
    Q_OBJECT
private slots:
    // A 50 MB JSON document asked for as JSON: parsed and indented in full before, for a view
    // that shows 64 kB.
    void payloadViewsAreBounded()
    {
        QByteArray huge = "[";
        while (huge.size() < 50 * 1024 * 1024)
            huge += "{\"sample\": 1, \"time\": 2.5, \"text\": \"aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa\"},";
        huge += "0]";
        const PayloadText::Rendered json = PayloadText::render(huge, PayloadText::Mode::Json);
        QVERIFY(json.text.size() <= 64 * 1024);
        QVERIFY2(json.note.contains(u"too large to show as JSON"_s), qPrintable(json.note));
        const PayloadText::Rendered hex = PayloadText::render(huge, PayloadText::Mode::Hex);
        QVERIFY(hex.text.size() < 64 * 1024 * 5);
        // Deep nesting within the size limit indents quadratically: the view is cut.
        const QByteArray deep = QByteArray(1000, '[') + QByteArray(1000, ']');
        const PayloadText::Rendered nested = PayloadText::render(deep, PayloadText::Mode::Json, 2000);
        QVERIFY(nested.text.size() <= 4 * 2000);
        QVERIFY2(nested.note.contains(u"cut"_s), qPrintable(nested.note));
    }

    void oversizedAnnouncementsAreRefusedUnread()
    {
        RosMsgTypeInfo info;
        info.md5 = u"*"_s;
        info.name = u"pkg/Big"_s;
        info.definition = QString(MqttClientWire::kMaxTypeBytes, u'#');
        QString error;
        QVERIFY(!noted(MqttClientWire::decodeType(MqttClientWire::encodeType(info)), &error));
        QVERIFY2(error.contains(u"more than"_s), qPrintable(error));
        info.definition = u"uint8 x\n"_s;
        QVERIFY(noted(MqttClientWire::decodeType(MqttClientWire::encodeType(info)), &error));
    }

    // Every stamp that does not decode is counted for its topic, also one over the size budget
    // (a large JSON object was ignored without a count) and one out of the range of ROS time.
    void everyStampFailureIsCountedPerTopic()
    {
        MqttStampDecoder decoder;
        std::vector<StampEvent> stamps;
        std::vector<LatencyValue> latencies;
        QByteArray big = "{\"sample\": \"1\", \"time\": 1, \"pad\": \"";
        big += QByteArray(StampCodec::kMaxJsonBytes, 'x') + "\"}";
        RosMsgTypeInfo bad;
        bad.md5 = QString::fromLatin1(StampCodec::md5());
        bad.name = QString::fromLatin1(StampCodec::typeName());
        QByteArray announcement = MqttClientWire::encodeType(bad);
        announcement.chop(1); // no stamped flag
        decoder.decode({msg(u"dev/a"_s, R"({"sample": "1", "time": 1.5})"), msg(u"dev/a"_s, big),
                        msg(u"dev/b"_s, R"({"sample": "1", "time": 1e10})"),
                        msg(u"dev/b"_s, R"({"sample": "1", "time": "-3.5"})"),
                        msg(u"mqtt_client/ros_msg_type/dev/c"_s, announcement)},
                       stamps, latencies);
        QCOMPARE(stamps.size(), 1u);
        QCOMPARE(decoder.malformed(), 4u);
        QCOMPARE(decoder.malformedByTopic().value(u"dev/a"_s), 1u);
        QCOMPARE(decoder.malformedByTopic().value(u"dev/b"_s), 2u);
        QCOMPARE(decoder.malformedByTopic().value(u"dev/c"_s), 1u);
        QVERIFY2(decoder.lastError().startsWith(u"dev/c: type announcement"_s),
                 qPrintable(decoder.lastError()));
    }
    // Extreme but accepted values: stage spans near 2^32 s, summed over many stages, and series
    // of values whose squares overflow 128 bits. Figures are what the values say, never wrapped.
    void extremeAcceptedStampsDoNotOverflow()
    {
        const qint64 top = StampCodec::kMaxTimeNs - 1;
        QStringList topics;
        for (int i = 0; i < 7; ++i)
            topics << u"/veh/t%1"_s.arg(i);
        Pipeline p(topics, 0);
        // Every other stamp on the other host: all six stages are crossings.
        for (int i = 0; i < 7; ++i)
            p.setHost(topics[i], i % 2 ? u"cloud"_s : u"vehicle"_s);
        LatencyEngine engine(p);
        for (int k = 0; k < 3; ++k)
            engine.addSample({0, top, 0, top, 0, top, 0});
        const LatencyStats rt = engine.series(engine.pipelineSeries().roundTripSeries()).stats();
        QCOMPARE(rt.count, 3);
        QCOMPARE(rt.min, 0.0); // six spans of ±top that cancel: exactly 0, not a wrapped sum
        QCOMPARE(engine.series(engine.pipelineSeries().stageSeries(0)).stats().mean, double(top) / 1e6);
        QCOMPARE(engine.series(engine.pipelineSeries().stageSeries(1)).stats().mean, -double(top) / 1e6);

        LatencySeries series;
        series.setWindow(0);
        const qint64 big = std::numeric_limits<qint64>::max();
        for (int i = 0; i < 4; ++i) {
            series.append(big);
            series.append(-big);
        }
        QCOMPARE(series.meanMs(), 0.0);
        const double expected = double(big) * 1e-6 * std::sqrt(8.0 / 7.0);
        QVERIFY2(std::abs(series.stdMs() - expected) < expected * 1e-9,
                 qPrintable(QString::number(series.stdMs())));
        // Once the big values leave the window, the exact sums take over again.
        series.setWindow(2);
        series.append(5'000'000);
        series.append(7'000'000);
        QCOMPARE(series.meanMs(), 6.0);
        QCOMPARE(series.stdMs(), std::sqrt(2.0));
    }

    // Clocks decades apart: the joiner's timeout is measured without overflowing.
    void joinerTimeoutsSurviveExtremeClocks()
    {
        SampleJoiner joiner(2);
        std::vector<qint64> times;
        joiner.add(0, 0, 1, 0, times);
        QVERIFY(joiner.add(1, 0, 1, 0, times)); // both topics heard: a missing stamp is a drop
        QVERIFY(!joiner.add(0, 1, 1, std::numeric_limits<qint64>::min() + 1, times));
        joiner.expire(std::numeric_limits<qint64>::max());
        QCOMPARE(joiner.counters().timedOut, 1u);
        QVERIFY(!joiner.add(0, 2, 1, std::numeric_limits<qint64>::max(), times));
        joiner.expire(std::numeric_limits<qint64>::min());
        QCOMPARE(joiner.pending(), 1);
    }
};

QTEST_GUILESS_MAIN(TestHostileInput)
#include "tst_hostileinput.moc"
