// SPDX-License-Identifier: MIT
// The formats stamps come in: TimeStamped (checked against genmsg), JSON stamps, Float64
// latencies, and the suite's timestamp CSV (checked against Python's csv writer).
#include "fixtures.h"
#include "pythonref.h"
#include "record/suitecsv.h"
#include "resulttext.h"
#include "syntheticrun.h"
#include "wire/sourcemessage.h"
#include "wire/stampcodec.h"

#include <cstring>
#include <QJsonArray>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

using namespace Qt::StringLiterals;

class TestStampFormats : public QObject
{
    Q_OBJECT
private slots:
    void timeStampedMatchesTheSuitesMessageFile()
    {
        const QJsonObject ref
            = PythonRef::run(u"msg_md5.py"_s,
                             {u"benchmarking_suite/TimeStamped"_s, Fixtures::path(u"benchmarking_suite"_s)})
                  .object();
        QVERIFY2(!ref.isEmpty(), "genmsg did not run");
        QCOMPARE(ref.value(u"md5"_s).toString(), QLatin1StringView(StampCodec::md5()));
        QCOMPARE(ref.value(u"definition"_s).toString(), StampCodec::definition());
    }

    void timeStampedRoundTripsAndRejectsBadBytes()
    {
        // Bytes as roscpp serializes them: seq, stamp (sec, nsec), frame_id (length + bytes), time.
        const QByteArray wire = QByteArray::fromHex("07000000"
                                                    "00f15365"
                                                    "15cd5b07"
                                                    "04000000"
                                                    "6c696461"
                                                    "01f15365"
                                                    "00e1f505");
        const Result<StampCodec::Decoded> d = StampCodec::decodeTimeStamped(wire);
        QVERIFY(d);
        QCOMPARE(d->seq, 7u);
        QCOMPARE(d->sampleNs, 0x6553f100LL * 1'000'000'000LL + 123456789);
        QCOMPARE(d->frameId, u"lida"_s);
        QCOMPARE(d->timeNs, 0x6553f101LL * 1'000'000'000LL + 100'000'000);
        QCOMPARE(StampCodec::encodeTimeStamped(*d), wire);
        QString error;
        QVERIFY(!noted(StampCodec::decodeTimeStamped(wire.left(20)), &error));
        QVERIFY(error.contains(u"short"_s) || error.contains(u"ends"_s));
        QVERIFY(!noted(StampCodec::decodeTimeStamped(wire + "x"), &error));
        QByteArray lying = wire;
        lying[12] = char(0xff); // frame_id length far beyond the message
        QVERIFY(!noted(StampCodec::decodeTimeStamped(lying), &error));
        QVERIFY(error.contains(u"frame_id"_s));

        // nsec >= 1e9 is no ROS time: it would not survive encoding (found by fuzz_stamps).
        QByteArray overflow = wire;
        overflow.replace(24, 4, QByteArray::fromHex("ffffffff"));
        error.clear();
        QVERIFY(!noted(StampCodec::decodeTimeStamped(overflow), &error));
        QVERIFY2(error.contains(u"4294967295 nanoseconds"_s), qPrintable(error));
        overflow = wire;
        overflow.replace(8, 4, QByteArray::fromHex("00ca9a3b")); // exactly 1e9 in the header stamp
        error.clear();
        QVERIFY(!noted(StampCodec::decodeTimeStamped(overflow), &error));
        QVERIFY2(error.contains(u"header stamp"_s), qPrintable(error));
        QVERIFY(!StampCodec::decodeHeader(overflow));
    }

    // Issue 34: the ROS 2 form, as rmw writes it: encapsulation header, stamp (int32 sec, uint32
    // nanosec), frame_id (length counting its NUL, the bytes, the NUL), padding to 4 from the end of
    // the header, time. Hand-made bytes, both byte orders, and what a hostile node could send.
    void ros2TimeStampedDecodesCdrAndRejectsBadBytes()
    {
        const QByteArray le = QByteArray::fromHex("00010000"
                                                  "00f15365"
                                                  "15cd5b07"
                                                  "03000000"
                                                  "61620000"
                                                  "01f15365"
                                                  "00e1f505");
        const Result<StampCodec::Decoded> d = StampCodec::decodeTimeStampedCdr(le);
        QVERIFY(d);
        QCOMPARE(d->sampleNs, 0x6553f100LL * 1'000'000'000LL + 123456789);
        QCOMPARE(d->frameId, u"ab"_s);
        QCOMPARE(d->timeNs, 0x6553f101LL * 1'000'000'000LL + 100'000'000);
        QCOMPARE(d->seq, 0u);
        QCOMPARE(StampCodec::encodeTimeStampedCdr(*d), le);
        const QByteArray be = QByteArray::fromHex("00000000"
                                                  "6553f100"
                                                  "075bcd15"
                                                  "00000003"
                                                  "61620000"
                                                  "6553f101"
                                                  "05f5e100");
        const Result<StampCodec::Decoded> b = StampCodec::decodeTimeStampedCdr(be);
        QVERIFY(b);
        QCOMPARE(b->sampleNs, d->sampleNs);
        QCOMPARE(b->timeNs, d->timeNs);
        // An empty frame_id is one NUL, three bytes of padding; RTPS may pad the end to 4 bytes.
        const QByteArray empty = QByteArray::fromHex("00010000" "00f15365" "15cd5b07" "01000000" "00000000"
                                                     "01f15365" "00e1f505");
        QVERIFY(StampCodec::decodeTimeStampedCdr(empty));
        QCOMPARE(StampCodec::decodeTimeStampedCdr(empty)->frameId, QString());
        QVERIFY(StampCodec::decodeTimeStampedCdr(le + QByteArray(3, '\0')));

        const auto rejected = [](const QByteArray& bytes, const QString& why) {
            QString error;
            const bool bad = !noted(StampCodec::decodeTimeStampedCdr(bytes), &error);
            if (!bad || !error.contains(why))
                qWarning("%s: %s", bytes.toHex().constData(), qPrintable(error));
            return bad && error.contains(why);
        };
        QVERIFY(rejected(le.left(3), u"short"_s));
        QVERIFY(rejected(le.left(14), u"short"_s));
        QVERIFY(rejected(le.left(24), u"ends before its time"_s));
        QVERIFY(rejected(le + QByteArray(4, '\0'), u"4 bytes too many"_s));
        QByteArray other = le;
        other[1] = 3; // PL_CDR_LE: no final type's encapsulation
        QVERIFY(rejected(other, u"encapsulation header is 00 03 00 00"_s));
        // A frame_id of 4 GiB in 28 bytes: refused before anything is read or allocated.
        QByteArray huge = le;
        huge.replace(12, 4, QByteArray::fromHex("f0ffffff"));
        QVERIFY(rejected(huge, u"frame_id claims 4294967280 bytes, only 12 left"_s));
        QByteArray nsec = le;
        nsec.replace(8, 4, QByteArray::fromHex("00ca9a3b"));
        QVERIFY(rejected(nsec, u"header stamp has 1000000000 nanoseconds"_s));
        nsec = le;
        nsec.replace(24, 4, QByteArray::fromHex("ffffffff"));
        QVERIFY(rejected(nsec, u"time has 4294967295 nanoseconds"_s));
        QByteArray negative = le;
        negative.replace(4, 4, QByteArray::fromHex("ffffffff")); // int32 sec -1
        QVERIFY(rejected(negative, u"before 1970"_s));
        // ROS 1 bytes are no ROS 2 sample, and the other way round.
        QVERIFY(!StampCodec::decodeTimeStampedCdr(StampCodec::encodeTimeStamped(*d)));
        QVERIFY(!StampCodec::decodeTimeStamped(le));
    }

    void ros2Float64LatencyDecodesCdr()
    {
        QCOMPARE(StampCodec::decodeFloat64SecondsCdr(QByteArray::fromHex("00010000" "2b8716d9cef7933f")),
                 std::make_optional(19'500'000LL));
        QCOMPARE(StampCodec::decodeFloat64SecondsCdr(QByteArray::fromHex("00000000" "3f93f7ced916872b")),
                 std::make_optional(19'500'000LL));
        QVERIFY(!StampCodec::decodeFloat64SecondsCdr(QByteArray::fromHex("2b8716d9cef7933f")));
        QVERIFY(!StampCodec::decodeFloat64SecondsCdr(QByteArray::fromHex("00010000" "2b8716d9")));
        QVERIFY(!StampCodec::decodeFloat64SecondsCdr(QByteArray::fromHex("00010000" "000000000000f07f"))); // inf
    }

    // One arrival type for every graph: its bytes read as the graph serializes them.
    void arrivalsReadAsTheirGraphSerializes()
    {
        StampCodec::Decoded d;
        d.sampleNs = 1'700'000'000'000'000'001LL;
        d.timeNs = 1'700'000'000'020'000'001LL;
        d.frameId = u"lidar"_s;
        const StampReading ros1 = SourceMessage::readStamp(
            {SourceGraph::Ros1, u"/a"_s, u"benchmarking_suite/TimeStamped"_s, 5, StampCodec::encodeTimeStamped(d)},
            false);
        QVERIFY(ros1.stamp && !ros1.latency);
        QCOMPARE(ros1.stamp->topic, u"/a"_s);
        QCOMPARE(ros1.stamp->sampleNs, d.sampleNs);
        QCOMPARE(ros1.stamp->timeNs, d.timeNs);
        QCOMPARE(ros1.stamp->receivedNs, 5);
        const StampReading ros2 = SourceMessage::readStamp(
            {SourceGraph::Ros2, u"ros2:/a"_s, {}, 6, StampCodec::encodeTimeStampedCdr(d)}, false);
        QVERIFY(ros2.stamp);
        QCOMPARE(ros2.stamp->topic, u"ros2:/a"_s);
        QCOMPARE(ros2.stamp->timeNs, d.timeNs);
        // A ROS 1 message on a ROS 2 topic does not read, and says why.
        const StampReading wrong = SourceMessage::readStamp(
            {SourceGraph::Ros2, u"/a"_s, {}, 6, StampCodec::encodeTimeStamped(d)}, false);
        QVERIFY(!wrong.stamp && !wrong.latency && !wrong.error.isEmpty());
        const StampReading latency = SourceMessage::readStamp(
            {SourceGraph::Ros2, u"/l"_s, {}, 7, QByteArray::fromHex("00010000" "2b8716d9cef7933f")}, true);
        QVERIFY(latency.latency && !latency.stamp);
        QCOMPARE(latency.latency->series, u"/l"_s);
        QCOMPARE(latency.latency->valueNs, 19'500'000);
        const StampReading bad = SourceMessage::readStamp({SourceGraph::Ros1, u"/l"_s, {}, 7, "1234"}, true);
        QVERIFY2(bad.error.contains(u"no finite number"_s), qPrintable(bad.error));
    }

    void jsonStamps_data()
    {
        QTest::addColumn<QByteArray>("json");
        QTest::addColumn<qint64>("sample");
        QTest::addColumn<qint64>("time");
        const qint64 s = 1'700'000'000LL * 1'000'000'000LL;
        QTest::newRow("sec.nsec strings")
            << QByteArray(R"({"sample": "1700000000.000000042", "time": "1700000000.5"})") << s + 42
            << s + 500'000'000;
        QTest::newRow("float time") << QByteArray(
            R"({"sample": "1700000000.000000042", "time": 1700000000.25})")
                                    << s + 42 << s + 250'000'000;
        QTest::newRow("numeric sample")
            << QByteArray(R"({"sample": 12, "time": "3.000000001"})") << 12'000'000'000LL << 3'000'000'001LL;
    }

    void jsonStamps()
    {
        QFETCH(QByteArray, json);
        QFETCH(qint64, sample);
        QFETCH(qint64, time);
        const Result<StampCodec::Decoded> d = StampCodec::decodeJson(json);
        QVERIFY(d);
        QCOMPARE(d->sampleNs, sample);
        QCOMPARE(d->timeNs, time);
        const Result<StampCodec::Decoded> back = StampCodec::decodeJson(StampCodec::encodeJson(sample, time));
        QVERIFY(back);
        QCOMPARE(back->sampleNs, sample);
        QCOMPARE(back->timeNs, time);
    }

    void jsonSampleIdsThatAreNotTimesAreHashedConsistently()
    {
        const auto a = StampCodec::decodeJson(R"({"sample": "frame-0042", "time": 1.0})");
        const auto b = StampCodec::decodeJson(R"({"sample": "frame-0042", "time": 2.0})");
        const auto c = StampCodec::decodeJson(R"({"sample": "frame-0043", "time": 2.0})");
        QVERIFY(a && b && c);
        QCOMPARE(a->sampleNs, b->sampleNs);
        QVERIFY(a->sampleNs != c->sampleNs);
        QVERIFY(a->sampleNs >= 0);
    }

    void badJsonStampsSayWhy_data()
    {
        QTest::addColumn<QByteArray>("json");
        QTest::addColumn<QString>("message");
        QTest::newRow("not json") << QByteArray("{sample") << u"not JSON"_s;
        QTest::newRow("array") << QByteArray("[1, 2]") << u"object"_s;
        QTest::newRow("no time") << QByteArray(R"({"sample": "1"})") << u"\"sample\" and \"time\""_s;
        // Found by fuzz_stamps: every empty id was one sample.
        QTest::newRow("empty sample") << QByteArray(R"({"sample": "", "time": 1.5})") << u"empty"_s;
        QTest::newRow("time text") << QByteArray(R"({"sample": "1", "time": "soon"})") << u"\"time\""_s;
        QTest::newRow("sample object") << QByteArray(R"({"sample": {}, "time": 1})") << u"\"sample\""_s;
    }

    void badJsonStampsSayWhy()
    {
        QFETCH(QByteArray, json);
        QFETCH(QString, message);
        QString error;
        QVERIFY(!noted(StampCodec::decodeJson(json), &error));
        QVERIFY2(error.contains(message), qPrintable(error));
    }

    void timesParseExactly()
    {
        QCOMPARE(StampCodec::parseTime(u"1700000000.123456789"),
                 std::make_optional(1'700'000'000'123'456'789LL));
        QCOMPARE(StampCodec::parseTime(u"5.5"), std::make_optional(5'500'000'000LL));
        QCOMPARE(StampCodec::parseTime(u"5"), std::make_optional(5'000'000'000LL));
        QCOMPARE(StampCodec::parseTime(u"1e-3"), std::make_optional(1'000'000LL));
        QVERIFY(!StampCodec::parseTime(u"1.2.3"));
        QVERIFY(!StampCodec::parseTime(u""));
        QVERIFY(!StampCodec::parseTime(u"abc"));
        QCOMPARE(StampCodec::timeText(1'700'000'000'000'000'042LL), u"1700000000.000000042"_s);
        double seconds = 0.0195;
        QByteArray f64(8, Qt::Uninitialized);
        std::memcpy(f64.data(), &seconds, 8);
        QCOMPARE(StampCodec::decodeFloat64Seconds(f64), std::make_optional(19'500'000LL));
        QVERIFY(!StampCodec::decodeFloat64Seconds("1234"));
    }

    void suiteCsvIsWrittenByteForByteLikeTheSuite()
    {
        const SyntheticRun run = SyntheticRun::paper(25, 1'234'567, 2);
        QTemporaryDir dir;
        QJsonArray samples;
        for (const auto& s : run.samples) {
            QJsonArray row;
            for (qint64 t : s)
                row.append(t);
            samples.append(row);
        }
        QFile in(dir.filePath(u"in.json"_s));
        QVERIFY(in.open(QIODevice::WriteOnly));
        in.write(QJsonDocument(QJsonObject {{u"topics"_s, QJsonArray::fromStringList(run.topics)},
                                            {u"samples"_s, samples}})
                     .toJson());
        in.close();
        const QString theirs = dir.filePath(u"suite.csv"_s);
        QVERIFY(!PythonRef::run(u"suite_csv_writer.py"_s, {in.fileName(), theirs}).isNull());
        QFile f(theirs);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QByteArray suiteBytes = f.readAll();
        QCOMPARE(SuiteCsv::write(run.topics, run.samples), suiteBytes);
        QString error;
        const std::optional<SuiteCsv::Data> back = noted(SuiteCsv::parse(suiteBytes, u"suite.csv"_s), &error);
        QVERIFY2(back, qPrintable(error));
        QCOMPARE(back->topics, run.topics);
        QCOMPARE(back->samples, run.samples);
        QCOMPARE(back->malformed, 0);
    }

    void badCsvRowsAreSkippedWithTheirLineAndCounted()
    {
        const QByteArray csv = "\xef\xbb\xbf/a,/b,\"/c,with comma\"\n"
                               "1.000000000,1.5,2\n"
                               "1.1,,2.2\n" // incomplete sample
                               "\n"
                               "3,x,4\n" // not a time
                               "4,5\n" // too few cells
                               "5,6,7\n";
        QString error;
        const std::optional<SuiteCsv::Data> d = noted(SuiteCsv::parse(csv, u"run.csv"_s), &error);
        QVERIFY2(d, qPrintable(error));
        QCOMPARE(d->topics, (QStringList {u"/a"_s, u"/b"_s, u"/c,with comma"_s}));
        QCOMPARE(d->samples.size(), 2u);
        QCOMPARE(d->samples[1], (std::vector<qint64> {5'000'000'000LL, 6'000'000'000LL, 7'000'000'000LL}));
        QCOMPARE(d->incomplete, 1);
        QCOMPARE(d->malformed, 2);
        QCOMPARE(d->problems.size(), 2);
        QVERIFY2(d->problems[0].startsWith(u"run.csv:5: column 2 (/b)"_s), qPrintable(d->problems[0]));
        QVERIFY2(d->problems[1].startsWith(u"run.csv:6: 2 cells"_s), qPrintable(d->problems[1]));
    }

    void unusableCsvFilesAreRefused_data()
    {
        QTest::addColumn<QByteArray>("csv");
        QTest::addColumn<QString>("message");
        QTest::newRow("empty") << QByteArray("\n\n") << u"run.csv:3: empty file"_s;
        QTest::newRow("no header") << QByteArray("1.0,2.0\n") << u"header row missing"_s;
        QTest::newRow("twice") << QByteArray("/a,/a\n") << u"appears twice"_s;
        QTest::newRow("blank name") << QByteArray("/a,\n") << u"column 2"_s;
    }

    void unusableCsvFilesAreRefused()
    {
        QFETCH(QByteArray, csv);
        QFETCH(QString, message);
        QString error;
        QVERIFY(!noted(SuiteCsv::parse(csv, u"run.csv"_s), &error));
        QVERIFY2(error.contains(message), qPrintable(error));
    }
    // Regression (issue 11): a NUL byte in a time cell cut the number ("12\0 99" read as 12), and
    // times beyond what a ROS stamp holds overflowed later; both are located row errors now.
    void csvCellsWithNulOrOutOfRangeTimesAreRowErrors()
    {
        QVERIFY(!StampCodec::parseTime(QStringView(u"12\0 99", 6)));
        QVERIFY(!StampCodec::parseTime(QStringView(u"12.5\0", 5)));
        QVERIFY(!StampCodec::parseTime(u"١٢")); // digits, but not ASCII ones
        QByteArray csv = "/a,/b\n1,2\n3,4";
        csv += '\0';
        csv += "99\n5,-6\n7,5000000000\n9223372036854775807,1\n4294967295.999999999,4294967296\n8,9\n";
        QString error;
        const std::optional<SuiteCsv::Data> d = noted(SuiteCsv::parse(csv, u"run.csv"_s), &error);
        QVERIFY2(d, qPrintable(error));
        QCOMPARE(d->samples.size(), 2u);
        QCOMPARE(d->malformed, 5);
        QVERIFY2(d->problems[0].startsWith(u"run.csv:3: column 2 (/b): a NUL byte"_s),
                 qPrintable(d->problems[0]));
        QVERIFY2(d->problems[1].startsWith(u"run.csv:4: column 2 (/b): \"-6\" is not a time"_s)
                     || d->problems[1].startsWith(u"run.csv:4: column 2 (/b): -6 is outside"_s),
                 qPrintable(d->problems[1]));
        QVERIFY2(d->problems[2].startsWith(u"run.csv:5: column 2 (/b): 5000000000 is outside"_s),
                 qPrintable(d->problems[2]));
        QVERIFY2(d->problems[3].startsWith(u"run.csv:6: column 1 (/a)"_s), qPrintable(d->problems[3]));
        QVERIFY2(d->problems[4].startsWith(u"run.csv:7: column 2 (/b): 4294967296 is outside"_s),
                 qPrintable(d->problems[4]));
        QVERIFY(!noted(SuiteCsv::parse(QByteArray("/a,/", 4) + '\0' + "b\n1,2\n", u"run.csv"_s), &error));
        QVERIFY2(error.startsWith(u"run.csv:1: column 2 of the header row holds a NUL byte"_s),
                 qPrintable(error));
    }
};

QTEST_GUILESS_MAIN(TestStampFormats)
#include "tst_stampformats.moc"
