// SPDX-License-Identifier: MIT
// LinkReader: each message reaches the links of its topic, latency topics and the pipeline give
// latency (what the figures then say is pinned in tst_linkmonitor).
#include "watch/linkreader.h"
#include "watch/linktrack.h"
#include "wire/sourcemessage.h"

#include <QtEndian>
#include <QTest>

using namespace Qt::StringLiterals;

namespace {
constexpr qint64 kMs = 1'000'000;

std::unique_ptr<LinkTrack> track(Direction d, const QString& ros, const QString& mqtt)
{
    auto t = std::make_unique<LinkTrack>();
    t->def.config = u"vehicle"_s;
    t->def.direction = d;
    t->def.rosTopic = ros;
    t->def.mqttTopic = mqtt;
    return t;
}

SourceHead head(SourceGraph graph, const QString& topic, const QByteArray& bytes, qint64 ns)
{
    return {graph, topic, ns, int(bytes.size()), bytes.left(SourceHead::kHeadBytes), ContentKey::of(bytes)};
}

QByteArray float64(double value)
{
    QByteArray b(8, '\0');
    qToLittleEndian(value, b.data());
    return b;
}
} // namespace

class TestLinkReader : public QObject
{
    Q_OBJECT
private slots:
    void eachMessageCountsAtItsLinksEnd()
    {
        LinkReader::Tracks tracks;
        tracks.push_back(track(Direction::Ros2Mqtt, u"/a"_s, u"a"_s));
        tracks.push_back(track(Direction::Mqtt2Ros, u"/b"_s, u"b"_s));
        LinkReader reader(tracks);
        reader.index();
        QStringList mqtt = reader.mqttTopics();
        mqtt.sort();
        QCOMPARE(mqtt, QStringList({u"a"_s, u"b"_s}));
        reader.add({head(SourceGraph::Ros1, u"/a"_s, "12345", kMs),
                    head(SourceGraph::Mqtt, u"a"_s, "123", 2 * kMs),
                    head(SourceGraph::Mqtt, u"b"_s, "1234567", 3 * kMs),
                    head(SourceGraph::Mqtt, u"elsewhere"_s, "1", 4 * kMs)});
        QCOMPARE(tracks[0]->src.f.messages, quint64(1));
        QCOMPARE(tracks[0]->src.f.bytes, quint64(5));
        QCOMPARE(tracks[0]->dst.f.messages, quint64(1));
        QCOMPARE(tracks[0]->dst.f.bytes, quint64(3));
        QCOMPARE(tracks[1]->src.f.messages, quint64(1));
        QCOMPARE(tracks[1]->src.f.bytes, quint64(7));
        QCOMPARE(tracks[1]->dst.f.messages, quint64(0));
    }

    void aBridgesLatencyTopicGivesItsLinkLatency()
    {
        LinkReader::Tracks tracks;
        tracks.push_back(track(Direction::Mqtt2Ros, u"/b"_s, u"b"_s));
        tracks[0]->keepLatencies = true; // as while the metrics take them
        LinkReader reader(tracks);
        reader.index();
        const QString latencyTopic = u"/bridge/latencies/b"_s;
        QCOMPARE(reader.rosTopicsToMonitor({latencyTopic, u"/other/latencies/c"_s}),
                 QStringList({u"/b"_s, latencyTopic}));
        reader.add({head(SourceGraph::Ros1, latencyTopic, float64(0.25), kMs)});
        QVERIFY(tracks[0]->newLatencies.empty()); // its type is not known yet
        reader.setRosDefinition(latencyTopic, u"std_msgs/Float64"_s, u"float64 data\n"_s);
        reader.add({head(SourceGraph::Ros1, latencyTopic, float64(0.25), 2 * kMs)});
        QCOMPARE(tracks[0]->newLatencies, std::vector<double>({250.0}));
    }

    void aPipelineSampleGivesTheLatencyBetweenItsStampsAndOnlyIt()
    {
        LinkReader::Tracks tracks;
        tracks.push_back(track(Direction::Mqtt2Ros, u"/b"_s, u"b"_s));
        tracks[0]->def.stampPrefix = u"/hop/"_s;
        tracks[0]->keepLatencies = true; // as while the metrics take them
        const QString latencyTopic = u"/bridge/latencies/b"_s;
        LinkReader reader(tracks);
        reader.index();
        reader.setRosDefinition(latencyTopic, u"std_msgs/Float64"_s, u"float64 data\n"_s);
        reader.setPipeline({u"/sensor"_s, u"hop/in"_s, u"/hop/out"_s});
        reader.addPipelineSample({0, 1 * kMs, 8 * kMs}, 10 * kMs);
        reader.addPipelineSample({0, 1 * kMs}, 11 * kMs); // another pipeline's sample
        reader.add({head(SourceGraph::Ros1, latencyTopic, float64(0.5), 12 * kMs)});
        QCOMPARE(tracks[0]->newLatencies, std::vector<double>({7.0}));
        QVERIFY(tracks[0]->pipelineLatency);
        reader.setPipeline({u"/sensor"_s});
        QVERIFY(!tracks[0]->pipelineLatency);
    }
};

QTEST_GUILESS_MAIN(TestLinkReader)
#include "tst_linkreader.moc"
