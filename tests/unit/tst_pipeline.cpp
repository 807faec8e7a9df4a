// SPDX-License-Identifier: MIT
// Pipelines: the suite's metrics-logger files, the hosts extension, host guessing, stage labels,
// and finding a pipeline in stamps alone.
#include "fixtures.h"
#include "latency/hostguess.h"
#include "latency/pipeline.h"
#include "latency/pipelinediscovery.h"
#include "resulttext.h"
#include "syntheticrun.h"

#include <QTemporaryDir>
#include <QTest>
#include <random>

using namespace Qt::StringLiterals;

namespace {
/// Stage labelling as it was before it became linear (one call per label, prefix recomputed each
/// time): the reference the fast labels must equal. One fix: topics that share no character have
/// no common prefix (lastIndexOf(u'/', -1) searched from the end and cut every topic to its leaf).
struct OldLabels
{
    QStringList topics;
    QString shortTopic(int i) const
    {
        const QString& t = topics[i];
        if (topics.size() < 2)
            return t;
        qsizetype common = topics.first().size();
        for (const QString& other : topics) {
            qsizetype k = 0;
            while (k < common && k < other.size() && other[k] == topics.first()[k])
                ++k;
            common = k;
        }
        common = common == 0 ? 0 : topics.first().lastIndexOf(u'/', common - 1) + 1;
        const QString rest = t.mid(common);
        return rest.isEmpty() ? t : rest;
    }
    QString component(int i) const
    {
        const QString t = shortTopic(i);
        const qsizetype slash = t.indexOf(u'/');
        return slash > 0 ? t.left(slash) : t;
    }
    QString longStageLabel(int s) const
    {
        const QString a = shortTopic(s);
        const QString b = shortTopic(s + 1);
        const qsizetype slashA = a.lastIndexOf(u'/');
        const qsizetype slashB = b.lastIndexOf(u'/');
        if (slashA > 0 && slashA == slashB && a.left(slashA) == b.left(slashB))
            return u"%1 (%2 → %3)"_s.arg(a.left(slashA), a.mid(slashA + 1), b.mid(slashB + 1));
        return u"%1 → %2"_s.arg(a, b);
    }
    QString brief(int s) const
    {
        const QString a = component(s);
        const QString b = component(s + 1);
        return a == b ? longStageLabel(s) : u"%1 → %2"_s.arg(a, b);
    }
    QString stageLabel(int stage) const
    {
        const QString label = brief(stage);
        for (int s = 0; s + 1 < topics.size(); ++s)
            if (s != stage && brief(s) == label)
                return longStageLabel(stage);
        return label;
    }
};

/// Random pipelines over a few name parts, so that labels collide and prefixes vary.
QStringList randomTopics(std::mt19937& rng, int count)
{
    static const QStringList parts {u"a"_s, u"b"_s, u"veh"_s, u"cloud"_s, u"in"_s, u"out"_s, u"x"_s};
    std::uniform_int_distribution<int> part(0, int(parts.size()) - 1);
    std::uniform_int_distribution<int> depth(1, 4);
    const QString root = std::uniform_int_distribution<int>(0, 2)(rng) == 0 ? QString() : u"/t/"_s;
    QStringList out;
    while (out.size() < count) {
        QString t = root;
        for (int d = depth(rng); d > 0; --d)
            t += parts[part(rng)] + (d > 1 ? u"/"_s : QString());
        if (!out.contains(t))
            out << t;
    }
    return out;
}
} // namespace

class TestPipeline : public QObject
{
    Q_OBJECT
private slots:
    void readsTheSuitesMetricsLoggerFiles_data()
    {
        QTest::addColumn<QString>("file");
        QTest::addColumn<int>("topics");
        QTest::newRow("mqtt interface") << u"metrics_logger_mqtt_interface.yaml"_s << 12;
        QTest::newRow("transmission only") << u"metrics_logger_mqtt_interface_transmission-only.yaml"_s << 2;
        QTest::newRow("in vehicle") << u"metrics_logger_in_vehicle.yaml"_s << 4;
        QTest::newRow("overlay") << u"metrics_logger_overlay.yaml"_s << 4;
    }

    void readsTheSuitesMetricsLoggerFiles()
    {
        QFETCH(QString, file);
        QFETCH(int, topics);
        QString error;
        const std::optional<Pipeline> p
            = noted(Pipeline::readFile(Fixtures::path(u"benchmarking_suite/"_s + file)), &error);
        QVERIFY2(p, qPrintable(error));
        QCOMPARE(p->topicCount(), topics);
        QCOMPARE(p->window(), 600);
        QVERIFY(p->topics().first().startsWith(u"/benchmarking_suite/timestamps/"_s));
        QVERIFY(!p->hasHosts());
    }

    void hostsExtensionRoundTrips()
    {
        Result<Pipeline> p
            = Pipeline::readFile(Fixtures::path(u"benchmarking_suite/metrics_logger_mqtt_interface.yaml"_s));
        QVERIFY(p);
        const QHash<QString, QString> guessed = HostGuess::ofTopics(p->topics());
        for (auto it = guessed.cbegin(); it != guessed.cend(); ++it)
            p->setHost(it.key(), it.value());
        QTemporaryDir dir;
        QString error;
        QVERIFY2(noted(p->save(dir.filePath(u"p.yaml"_s)), &error), qPrintable(error));
        const std::optional<Pipeline> back = noted(Pipeline::readFile(dir.filePath(u"p.yaml"_s)), &error);
        QVERIFY2(back, qPrintable(error));
        QCOMPARE(*back, *p);
    }

    // Topics from discovery can hold anything: what is written is read back as the same names.
    void oddTopicsAreWrittenSoThatTheyReadBack()
    {
        // U+2028 and a byte-order mark inside a name too.
        const Pipeline p({u"/a\"b"_s, u"c\\d"_s, u"e: #f"_s, u"ü/\u00a0/x"_s, u"a\ufeff"_s, u"l\u2028m"_s});
        QString error;
        const std::optional<Pipeline> back = noted(Pipeline::read(p.toYaml()), &error);
        QVERIFY2(back, qPrintable(error));
        QCOMPARE(back->topics(), p.topics());
        const Pipeline control({u"/a\nb"_s, u"/c"_s});
        QVERIFY(control.toYaml().contains("\\u000a"));
        QVERIFY(!noted(Pipeline::read(control.toYaml()), &error)); // refused, with a reason, not renamed
        QVERIFY(error.contains(u"control character"_s));
    }

    // The paper's pipeline: the vehicle's benchmark IO and bridge, the cloud's bridge and the
    // detection, and back. "pointcloud" is not "cloud": names are split into words.
    void guessesThePapersHosts()
    {
        const Result<Pipeline> p
            = Pipeline::readFile(Fixtures::path(u"benchmarking_suite/metrics_logger_mqtt_interface.yaml"_s));
        QVERIFY(p);
        const QHash<QString, QString> hosts = HostGuess::ofTopics(p->topics());
        QStringList got;
        for (const QString& t : p->topics())
            got << hosts.value(t);
        QCOMPARE(got, SyntheticRun::paper(1, 0, 1).hosts());
        Pipeline withHosts = *p;
        for (auto it = hosts.cbegin(); it != hosts.cend(); ++it)
            withHosts.setHost(it.key(), it.value());
        QCOMPARE(withHosts.crossings(), (QList<int> {2, 8}));
        QCOMPARE(withHosts.outAndReturnCrossings(), std::make_optional(std::make_pair(2, 8)));
        QCOMPARE(withHosts.stageLabel(1), u"mqtt_interface_vehicle/pointcloud (in → out)"_s);
        QCOMPARE(withHosts.stageLabel(2), u"mqtt_interface_vehicle → mqtt_interface_cloud"_s);
        QCOMPARE(withHosts.stageLabel(0), u"pointcloud → mqtt_interface_vehicle"_s);
        QCOMPARE(withHosts.stageLabel(5), u"object_detection (pointcloud → object_list)"_s);
        QCOMPARE(withHosts.labels().longStageLabel(2),
                 u"mqtt_interface_vehicle/pointcloud/out → mqtt_interface_cloud/pointcloud/in"_s);
        // Labels that would read the same fall back to the long form.
        const Pipeline twice({u"/t/a/x"_s, u"/t/b/x"_s, u"/t/a/y"_s, u"/t/b/y"_s});
        QCOMPARE(twice.stageLabel(0), u"a/x → b/x"_s);
        QCOMPARE(twice.stageLabel(1), u"b → a"_s);
        QCOMPARE(withHosts.labels().shortTopic(0), u"pointcloud"_s);
    }

    void badPipelinesSayWhereAndWhy_data()
    {
        QTest::addColumn<QByteArray>("yaml");
        QTest::addColumn<QString>("message");
        QTest::newRow("not yaml") << QByteArray("topics_in_order: [a,\n  b") << u"line"_s;
        QTest::newRow("no topics") << QByteArray("metrics_window: 5\n") << u"topics_in_order is missing"_s;
        QTest::newRow("window") << QByteArray("topics_in_order: [/a, /b]\nmetrics_window: lots\n")
                                << u"line 2"_s;
        QTest::newRow("host of a stranger")
            << QByteArray("topics_in_order: [/a, /b]\nhosts:\n  /c: x\n") << u"line 3: hosts names /c"_s;
        QTest::newRow("nested topic") << QByteArray("topics_in_order:\n  - [/a]\n") << u"line 2"_s;
        // Found by fuzz_pipeline: a line break in a topic used to be accepted and written raw.
        QTest::newRow("escaped newline") << QByteArray("topics_in_order: [\"/a\\nb\", /c]\n")
                                         << u"line 1: the topic \"/a\\u000ab\" holds the control character U+000a at 3"_s;
        // Found by fuzz_pipeline: Qt drops a leading byte-order mark, so the topic changed.
        QTest::newRow("BOM") << QByteArray("topics_in_order: [\"\\ufeff/a\", /c]\n") << u"line 1: a topic starts with a byte-order mark"_s;
        QTest::newRow("NUL") << QByteArray("topics_in_order: [\"/a\\0\", /c]\n") << u"U+0000"_s;
        QTest::newRow("host with a tab")
            << QByteArray("topics_in_order: [/a, /b]\nhosts:\n  /a: \"x\\ty\"\n") << u"line 3: the host of /a"_s;
    }

    void badPipelinesSayWhereAndWhy()
    {
        QFETCH(QByteArray, yaml);
        QFETCH(QString, message);
        QString error;
        QVERIFY(!noted(Pipeline::read(yaml), &error));
        QVERIFY2(error.contains(message), qPrintable(error));
    }

    // A topic holding "%1" and a control character: the message used to substitute into the topic
    // ("/a000a…" and "U+5 at %4").
    void aPercentInATopicStaysInTheMessage()
    {
        QString error;
        QVERIFY(!noted(Pipeline::read("topics_in_order: [\"/a%1\\nb\", /c]\n"), &error));
        QCOMPARE(error, u"line 1: the topic \"/a%1\\u000ab\" holds the control character U+000a at 5"_s);
    }

    void duplicateTopicsCountOnceAndSlashesDoNotMatter()
    {
        const Pipeline p({u"/a/x"_s, u"/a/y"_s, u"/a/x"_s, u"a/y"_s, u"/a/z"_s});
        QCOMPARE(p.topics(), (QStringList {u"/a/x"_s, u"/a/y"_s, u"/a/z"_s}));
        QCOMPARE(p.indexOf(u"a/z"), 2);
        QCOMPARE(p.indexOf(u"/a/y"), 1);
        QCOMPARE(p.indexOf(u"/a"), -1);
    }

    // Stamps of the paper's twelve topics, arriving in random order over ROS and MQTT spellings,
    // give back the pipeline in order, with hosts.
    void discoveryOrdersTopicsByTheirTimeInTheSample()
    {
        const SyntheticRun run = SyntheticRun::paper(50, 3'000'000, 5);
        std::vector<StampEvent> events;
        for (const auto& s : run.samples)
            for (int t = 0; t < run.topics.size(); ++t) {
                const QString topic = t % 2 ? run.topics[t].mid(1) : run.topics[t]; // MQTT drops the '/'
                events.push_back({topic, s.front(), s[std::size_t(t)], 0});
            }
        std::mt19937 rng(9);
        std::shuffle(events.begin(), events.end(), rng);
        PipelineDiscovery d;
        for (const StampEvent& e : events)
            d.add(e);
        d.add(events.front()); // a duplicate changes nothing
        // Topic 1 also seen on ROS: its ROS name wins; the others keep the spelling they came with.
        d.add({run.topics[1], run.samples[0].front(), run.samples[0][1], 0});
        QCOMPARE(d.completeSamples(), 50);
        const Pipeline p = d.propose();
        QStringList expected = run.topics;
        for (int t = 3; t < expected.size(); t += 2)
            expected[t] = expected[t].mid(1);
        QCOMPARE(p.topics(), expected);
        QCOMPARE(p.host(3), u"cloud"_s);
        QCOMPARE(p.host(11), u"vehicle"_s);
        QCOMPARE(d.stampCount(run.topics[3]), 50u);
    }
    void discoveryOrdersAcrossClockOffsets_data()
    {
        QTest::addColumn<qint64>("offsetNs");
        QTest::newRow("one clock") << qint64(0);
        QTest::newRow("cloud 35 ms ahead") << qint64(35'000'000);
        QTest::newRow("cloud 250 ms behind") << qint64(-250'000'000);
        QTest::newRow("cloud 2 s ahead") << qint64(2'000'000'000);
    }

    // Regression (issue 40, item 4): with the cloud's clock 35 ms ahead the vehicle's return stamps
    // came before the cloud's, and the pinned round trip read -9.86 ms. Each host's clock orders
    // its own stamps; the cloud's visit goes where it fits, whatever the offset.
    void discoveryOrdersAcrossClockOffsets()
    {
        QFETCH(qint64, offsetNs);
        const SyntheticRun run = SyntheticRun::paper(60, offsetNs, 17);
        PipelineDiscovery d;
        for (const auto& s : run.samples)
            for (int t = run.topics.size() - 1; t >= 0; --t) // the order they arrive in tells nothing
                d.add({run.topics[t], s.front(), s[std::size_t(t)], 0});
        const Pipeline p = d.propose();
        QCOMPARE(p.topics(), run.topics);
        QStringList hosts;
        for (int t = 0; t < p.topicCount(); ++t)
            hosts << p.host(t);
        QCOMPARE(hosts, run.hosts());
        QCOMPARE(p.crossings(), (QList<int> {2, 8}));
    }

    // Stamps of a broker with many stamp topics: memory stays bounded by stamps, not only by
    // samples (2,000 samples of 100,000 topics were 200 million kept stamps).
    void discoveryKeepsABoundedNumberOfStamps()
    {
        QStringList topics;
        for (int t = 0; t < 1000; ++t)
            topics << u"/many/t%1"_s.arg(t);
        PipelineDiscovery d;
        const int samples = int(PipelineDiscovery::kKeptStamps / 1000) + 100;
        for (int s = 0; s < samples; ++s)
            for (int t = 0; t < 1000; ++t)
                d.add({topics[t], qint64(s) * 1'000'000'000LL, qint64(s) * 1'000'000'000LL + t, 0});
        QCOMPARE(d.completeSamples(), int(PipelineDiscovery::kKeptStamps / 1000));
        QCOMPARE(d.topics().size(), 1000);
        QCOMPARE(d.propose().topics(), topics);
    }

    // Regression (issue 11, item 6): labelling was cubic in the topics. The labels must not change.
    void stageLabelsAreTheOldLabels()
    {
        std::mt19937 rng(11);
        for (int round = 0; round < 300; ++round) {
            const QStringList topics = randomTopics(rng, 2 + round % 12);
            const Pipeline p(topics);
            const OldLabels old {p.topics()};
            for (int s = 0; s < p.stageCount(); ++s)
                QCOMPARE(p.stageLabel(s), old.stageLabel(s));
            for (int t = 0; t < p.topicCount(); ++t)
                QCOMPARE(p.labels().shortTopic(t), old.shortTopic(t));
        }
        // A large pipeline: components repeat, so many labels fall back to the long form.
        QStringList topics;
        for (int i = 0; i < 100; ++i)
            topics << u"/lab/timestamps/node%1/data/in"_s.arg(i % 40) + QString::number(i / 40)
                   << u"/lab/timestamps/node%1/data/out"_s.arg(i % 40) + QString::number(i / 40);
        const Pipeline big(topics);
        const OldLabels old {big.topics()};
        for (int s = 0; s < big.stageCount(); s += 7)
            QCOMPARE(big.stageLabel(s), old.stageLabel(s));
        // Every label of a pipeline of 20,000 topics, at once.
        QStringList many;
        for (int i = 0; i < 20000; ++i)
            many << u"/suite/timestamps/c%1/d/out"_s.arg(i);
        const Pipeline huge(many);
        QCOMPARE(huge.stageLabel(0), u"c0 → c1"_s);
        QCOMPARE(huge.stageLabel(19998), u"c19998 → c19999"_s);
        QCOMPARE(huge.stageLabel(19999), QString());
        QCOMPARE(huge.labels().shortTopic(7), u"c7/d/out"_s);
        // Topics sharing no character keep their components.
        const Pipeline disjoint({u"veh/a/in"_s, u"cloud/a/out"_s});
        QCOMPARE(disjoint.stageLabel(0), u"veh → cloud"_s);
    }
};

QTEST_GUILESS_MAIN(TestPipeline)
#include "tst_pipeline.moc"
