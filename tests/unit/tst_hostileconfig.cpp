// SPDX-License-Identifier: MIT
// Hostile YAML (issue 11): alias bombs, cycles, deep nesting, huge files and bytes that are not
// UTF-8 are refused with a located error before anything walks the tree; the anchors real files
// use still load, edit and save.
#include "yaml/yamllimits.h"
#include "config/configdocument.h"
#include "config/configpatcher.h"
#include "config/configreader.h"
#include "config/configvalidator.h"
#include "config/configwriter.h"
#include "fixtures.h"
#include "latency/pipeline.h"
#include "resulttext.h"

#include <QFile>
#include <QTemporaryDir>
#include <QTest>

using namespace Qt::StringLiterals;

namespace {
const QByteArray okBridge = "bridge:\n  ros2mqtt:\n    - ros_topic: /a\n      mqtt_topic: a\n";

// The bomb: `levels` maps under an unknown key, each naming the one before twice.
QByteArray aliasBomb(int levels)
{
    QByteArray text = okBridge + "junk:\n  b0: &b0 {x: 1}\n";
    for (int i = 1; i <= levels; ++i)
        text += "  b" + QByteArray::number(i) + ": &b" + QByteArray::number(i) + " {l: *b"
            + QByteArray::number(i - 1) + ", r: *b" + QByteArray::number(i - 1) + "}\n";
    return text;
}

// Zero-based line of the first line that starts with `prefix`.
int lineStartingWith(const QByteArray& text, const QByteArray& prefix)
{
    const QList<QByteArray> lines = text.split('\n');
    for (int i = 0; i < lines.size(); ++i) {
        if (lines[i].startsWith(prefix))
            return i;
    }
    return -1;
}

ConfigReadResult read(const QByteArray& text)
{
    return ConfigReader::read(text);
}

QString firstCode(const ConfigReadResult& r)
{
    return r.problems.isEmpty() ? QString() : r.problems.first().code;
}
} // namespace

class TestHostileConfig : public QObject
{
    Q_OBJECT
private slots:
    // Regression (issue 11, item 5): 20 levels are 600 bytes and expand to millions of nodes; the
    // reader walked every one of them (minutes, gigabytes). Fourteen levels keep the old code's
    // failure of this test to about a second.
    void aliasBombIsRefusedWhereItPassesTheLimit()
    {
        for (int levels : {14, 20}) {
            const QByteArray text = aliasBomb(levels);
            QVERIFY(text.size() < 1000);
            const ConfigReadResult r = read(text);
            QVERIFY2(!r.parsed, qPrintable(u"%1 levels were read"_s.arg(levels)));
            QCOMPARE(r.problems.size(), 1);
            const Problem& p = r.problems.first();
            QCOMPARE(p.code, u"yaml-alias-expansion"_s);
            QCOMPARE(p.severity, Severity::Error);
            QVERIFY2(p.message.contains(QString::number(YamlLimits::maxAliasNodes)), qPrintable(p.message));
            // Level i repeats level i-1 twice: the first level whose aliases pass the limit.
            qint64 size = 3, repeated = 0; // {x: 1}: the map, its key and its value
            int level = 0;
            while (repeated <= YamlLimits::maxAliasNodes) {
                ++level;
                repeated += size;
                if (repeated > YamlLimits::maxAliasNodes)
                    break;
                repeated += size;
                size = 3 + 2 * size;
            }
            const QByteArray key = "  b" + QByteArray::number(level) + ":";
            QCOMPARE(p.pos.line, lineStartingWith(text, key));
            QVERIFY2(p.message.contains(u"*b%1"_s.arg(level - 1)), qPrintable(p.message));
            QCOMPARE(text.mid(text.indexOf(key) + p.pos.column, 1), QByteArray("*"));
        }
    }

    void limitsNameWhatPassedThemAndWhere_data()
    {
        QTest::addColumn<QByteArray>("text");
        QTest::addColumn<QString>("code");
        QTest::addColumn<int>("line");

        QByteArray deep = okBridge + "junk: ";
        for (int i = 0; i < YamlLimits::maxDepth; ++i)
            deep += '[';
        deep += "1";
        for (int i = 0; i < YamlLimits::maxDepth; ++i)
            deep += ']';
        QTest::newRow("nested deeper than the limit") << deep + '\n' << u"yaml-too-deep"_s << 4;

        // Within the limit as written, too deep once the alias is expanded.
        const int half = YamlLimits::maxDepth / 2 + 1;
        QByteArray viaAlias = okBridge + "a: &a " + QByteArray(half, '[') + "1" + QByteArray(half, ']')
            + "\nb: " + QByteArray(half, '[') + "*a" + QByteArray(half, ']') + "\n";
        QTest::newRow("nested deeper through an alias") << viaAlias << u"yaml-too-deep"_s << 5;

        QByteArray many = okBridge + "junk: [";
        for (qint64 i = 0; i < YamlLimits::maxNodes; ++i)
            many += "1,";
        many += "1]\n";
        QTest::newRow("too many nodes") << many << u"yaml-too-many-nodes"_s << 4;

        QByteArray big = okBridge + "# " + QByteArray(YamlLimits::maxBytes, 'x') + '\n';
        QTest::newRow("too large") << big << u"yaml-too-large"_s << -1; // no place: its size

        // A long scalar repeated by aliases: few nodes, many bytes.
        QByteArray wide = okBridge + "s: &s " + QByteArray(1024 * 1024, 'x') + "\nl: [";
        for (int i = 0; i < 9; ++i)
            wide += "*s, ";
        wide += "*s]\n";
        QTest::newRow("aliases repeat too many bytes") << wide << u"yaml-alias-expansion"_s << 5;

        QTest::newRow("a list that holds itself") << okBridge + "x: &x [1, *x]\n"
                                                  << u"yaml-alias-cycle"_s << 4;
        QTest::newRow("a map that holds itself") << okBridge + "x: &x {a: {b: *x}}\n"
                                                 << u"yaml-alias-cycle"_s << 4;
        // Found by fuzz_config: yaml-cpp reads the first of two equal keys, rosparam the last.
        QTest::newRow("a key twice") << okBridge + "x: 1\n\"x\": 2\n" << u"yaml-duplicate-key"_s << 5;
        QTest::newRow("a key twice, nested") << okBridge + "y:\n  - {a: 1, b: {a: 2}, a: 3}\n"
                                             << u"yaml-duplicate-key"_s << 5;
        QTest::newRow("a map as a key") << okBridge + "x:\n  ? {a: 1}\n  : 2\n" << u"yaml-complex-key"_s << 5;
        QTest::newRow("a list as a key") << okBridge + "[a, b]: 2\n" << u"yaml-complex-key"_s << 4;
        QTest::newRow("an alias of a map as a key") << okBridge + "x: &m {a: 1}\ny: {*m : 2}\n"
                                                    << u"yaml-complex-key"_s << 5;
        QTest::newRow("null key twice") << okBridge + "NULL: 1\n: 2\n" << u"yaml-duplicate-key"_s << 5;
        // Found by fuzz_config: a NUL in the indentation was read as content.
        QTest::newRow("NUL") << okBridge + "x: 1\n  " + QByteArray(1, '\0') + " y: 2\n"
                             << u"yaml-control-character"_s << 5;
        QTest::newRow("escape character") << okBridge + "x: \"\x1b[31m\"\n"
                                          << u"yaml-control-character"_s << 4;
        QTest::newRow("CR at the end") << okBridge + "x: a\r\ny: b\r" << u"yaml-lone-carriage-return"_s << 5;
        QTest::newRow("CR line ends") << okBridge + "x: a\ry: b\n" << u"yaml-lone-carriage-return"_s << 4;
        QTest::newRow("C1 control") << okBridge + "x: a\xc2\x9b\n" << u"yaml-control-character"_s << 4;
    }
    // Regression: every one of these was read (and walked, or crashed the reader with a stack
    // overflow for the map that holds itself).
    void limitsNameWhatPassedThemAndWhere()
    {
        QFETCH(QByteArray, text);
        QFETCH(QString, code);
        QFETCH(int, line);
        const ConfigReadResult r = read(text);
        QVERIFY(!r.parsed);
        QCOMPARE(r.problems.size(), 1);
        QCOMPARE(r.problems.first().code, code);
        QCOMPARE(r.problems.first().pos.line, line);
        QVERIFY(!r.problems.first().message.isEmpty());
        // The same check guards the pipeline reader and the patcher.
        QString error;
        QVERIFY(!noted(Pipeline::read("topics_in_order: [/a, /b]\n" + text.mid(okBridge.size())), &error));
        if (line >= 0)
            QVERIFY2(error.contains(u"line %1: "_s.arg(line - 2)), qPrintable(error));
        else
            QVERIFY2(!error.contains(u"line "_s), qPrintable(error));
        QCOMPARE(YamlLimits::check(text)->code, code);
    }

    // Issue 40: opening a 17 MB file said `290792:3` and `8388608 bytes`: the place of the limit's
    // byte, which is nowhere the user can fix anything, and a count nobody reads. It says the
    // sizes in the units people think in, and no place.
    void aFileTooLargeSaysItsSizeNotAPlace()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(u"huge.yaml"_s);
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(okBridge);
        const QByteArray line = "# " + QByteArray(58, 'x') + '\n';
        while (f.size() < 17 * 1024 * 1024 + 300 * 1024)
            f.write(line);
        f.close();
        ConfigDocument doc;
        const ConfigDocument::LoadResult r = doc.load(path);
        QVERIFY(!r.ok && !r.unreadable);
        QCOMPARE(r.error, path + u": error: The file is 17 MB, the limit is 8 MB. (Split the file.)"_s);
        QCOMPARE(r.problems.size(), 1);
        QVERIFY(!r.problems.first().pos.isValid());
        // Only its start was read, to be shown.
        QCOMPARE(r.text.size(), ConfigDocument::kShownBytes);
        // Read through the reader's bounded read: larger than the limit, its size unknown.
        QCOMPARE(YamlLimits::tooLargeMessage(YamlLimits::maxBytes + 1),
                 u"The file is larger than 8 MB, the limit."_s);
        QCOMPARE(YamlLimits::tooLargeMessage(YamlLimits::maxBytes + 100),
                 u"The file is larger than 8 MB, the limit."_s);
        QCOMPARE(YamlLimits::tooLargeMessage(9 * 1024 * 1024), u"The file is 9.0 MB, the limit is 8 MB."_s);
    }

    // Within the limits nothing changes: the same text reads as before.
    void aliasesWithinTheLimitsStillExpand()
    {
        const ConfigReadResult r = read(aliasBomb(8));
        QVERIFY(r.parsed);
        QCOMPARE(r.config.rootExtras.size(), 511); // b0 .. b8 hold 2^0 + ... + 2^8 leaves
        QVERIFY(!YamlLimits::check(aliasBomb(8)));
    }

    // The anchors real files use (ros1-era-params.aws.yaml names the TLS version once) load, edit
    // in place and save with the anchor and alias kept.
    void anchorsOfRealFilesLoadEditAndSave()
    {
        const QByteArray text = Fixtures::read(u"mqtt_client/ros1-era-params.aws.yaml"_s);
        QVERIFY(!YamlLimits::check(text));
        const ConfigReadResult r = read(text);
        QVERIFY(r.parsed);
        QCOMPARE(r.config.client.values.text(u"tls.version"_s), u"3"_s);
        BridgeConfig edited = r.config;
        edited.client.values.setText(u"id"_s, u"edited"_s);
        QString why;
        const std::optional<QByteArray> saved = ConfigPatcher::patch(text, r.config, edited, &why);
        QVERIFY2(saved, qPrintable(why));
        QVERIFY(saved->contains("tls_1_2: &tls_1_2 3"));
        QVERIFY(saved->contains("version: *tls_1_2"));
        QCOMPARE(read(*saved).config.client.values.text(u"id"_s), u"edited"_s);
    }

    // The patcher loads the text itself: a bomb behind a baseline is refused there too.
    void patcherRefusesTextPastTheLimits()
    {
        const ConfigReadResult base = read(okBridge);
        BridgeConfig edited = base.config;
        edited.client.values.setText(u"id"_s, u"edited"_s);
        QString why;
        QVERIFY(!ConfigPatcher::patch(aliasBomb(20), base.config, edited, &why));
        QVERIFY2(why.contains(u"*b"_s) && why.contains(QString::number(YamlLimits::maxAliasNodes)),
                 qPrintable(why));
    }

    void invalidUtf8IsALocatedError_data()
    {
        QTest::addColumn<QByteArray>("bad");
        QTest::newRow("a lone 0xff") << QByteArray("\xff");
        QTest::newRow("Latin-1 e acute") << QByteArray("caf\xe9");
        QTest::newRow("overlong slash") << QByteArray("\xc0\xaf");
        QTest::newRow("surrogate") << QByteArray("\xed\xa0\x80");
        QTest::newRow("past U+10FFFF") << QByteArray("\xf4\x90\x80\x80");
        QTest::newRow("cut short") << QByteArray("\xe2\x82");
        QTest::newRow("continuation alone") << QByteArray("\x80");
    }
    // Regression (issue 11): such bytes became U+FFFD in converted files and bridged topics, and
    // passed validation.
    void invalidUtf8IsALocatedError()
    {
        QFETCH(QByteArray, bad);
        const QByteArray prefix = "bridge:\n  ros2mqtt:\n    - ros_topic: /a\n      mqtt_topic: ok/";
        const QByteArray text = prefix + bad + "/x\n";
        const ConfigReadResult r = read(text);
        QVERIFY(!r.parsed);
        QCOMPARE(firstCode(r), u"invalid-utf8"_s);
        QCOMPARE(r.problems.first().pos.line, 3);
        QCOMPARE(r.problems.first().pos.column,
                 prefix.size() - prefix.lastIndexOf('\n') - 1 + (bad.startsWith("caf") ? 3 : 0));
        QVERIFY(r.problems.first().message.contains(u"UTF-8"_s));
        QString error;
        QVERIFY(!noted(Pipeline::read("topics_in_order: [/a, /" + bad + "]\n"), &error));
        QVERIFY2(error.contains(u"line 1"_s), qPrintable(error));
    }

    // Regression (issue 11): writing anew lost content without a word: a block that is no map
    // became "{}", and an unknown key of a known section's name replaced the section's options.
    void writingAnewKeepsOrNamesWhatItCannotPlace()
    {
        for (ConfigLayout layout : {ConfigLayout::Ros1, ConfigLayout::Ros2}) {
            QStringList notes, dropped;
            const ConfigReadResult notAMap = read("broker: [1, 2]\n" + okBridge);
            QString text = ConfigWriter::write(notAMap.config, layout, &notes, &dropped);
            QVERIFY2(text.contains(u"broker: [1, 2]"_s), qPrintable(text));
            QVERIFY(dropped.isEmpty());

            // A key twice is refused before anything is kept (it used to be written as one).
            const ConfigReadResult twice = read("broker:\n  tls: 5\n  tls:\n    enabled: true\n" + okBridge);
            QVERIFY(!twice.parsed);
            QCOMPARE(twice.problems.first().code, u"yaml-duplicate-key"_s);
            QCOMPARE(twice.problems.first().pos.line, 2);

            // Found by fuzz_config: an unknown key holding a block list was written "extra: - 1".
            const ConfigReadResult listExtra = read(okBridge + "      extra:\n        - 1\n        - a: 2\n");
            QVERIFY(listExtra.parsed);
            text = ConfigWriter::write(listExtra.config, layout, &notes, &dropped);
            const ConfigReadResult back = read(text.toUtf8());
            QVERIFY2(back.parsed, qPrintable(text));
            QVERIFY(back.config.sameContent(listExtra.config));
        }
        // Entries the model has no place for are named by the reader, with where they are.
        const ConfigReadResult r
            = read("bridge:\n  ros2mqtt:\n    - 5\n    - {ros_topic: /a, mqtt_topic: a}\n");
        QVERIFY(r.lossy);
        QCOMPARE(r.dropped.size(), 1);
        QCOMPARE(r.dropped.first().pos.line, 2);
        QVERIFY(r.dropped.first().message.contains(u"Entry 1 of 'bridge.ros2mqtt'"_s));
    }

    void validUtf8StaysReadable()
    {
        const QByteArray text = "bridge:\n  ros2mqtt:\n    - ros_topic: /a\n      mqtt_topic: "
                                "caf\xc3\xa9/\xe2\x82\xac/\xf0\x9f\x98\x80\n";
        const ConfigReadResult r = read(text);
        QVERIFY(r.parsed);
        QCOMPARE(r.config.mappings.first().mqttTopic(), u"café/€/\U0001F600"_s);
        QVERIFY(YamlLimits::isUtf8("\xef\xbb\xbf"
                                   "bom"));
    }
};

QTEST_GUILESS_MAIN(TestHostileConfig)
#include "tst_hostileconfig.moc"
