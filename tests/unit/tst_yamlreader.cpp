// SPDX-License-Identifier: MIT
// One YAML reader and one result type: the plan, rules and pipeline readers report their errors as
// a located value (message, line, column, file), written as each reader always wrote them.
#include "files/atomicfile.h"
#include "yaml/yamlreader.h"
#include "experiment/experimentplan.h"
#include "latency/pipeline.h"
#include "resulttext.h"
#include "watch/watchrules.h"

#include <QTemporaryDir>
#include <QTest>

using namespace Qt::StringLiterals;

class TestYamlReader : public QObject
{
    Q_OBJECT

private slots:
    void planErrorsCarryLineAndColumn()
    {
        const Result<ExperimentPlan> plan
            = ExperimentPlan::read("samples: 5\nfactors:\n  qos: [0, 3]\n", u"/p"_s);
        QVERIFY(!plan);
        QCOMPARE(plan.error().message, u"qos is 0, 1 or 2"_s);
        QCOMPARE(plan.error().pos, (TextPos {2, 11}));
        QCOMPARE(plan.error().toString(), u"line 3, column 12: qos is 0, 1 or 2"_s);
        // The text form is what fromYaml() has always given.
        QString error;
        QVERIFY(!noted(ExperimentPlan::read("samples: 5\nfactors:\n  qos: [0, 3]\n", u"/p"_s), &error));
        QCOMPARE(error, plan.error().toString());
    }

    void planErrorsWithoutAPlaceHaveNone()
    {
        const Result<ExperimentPlan> plan = ExperimentPlan::read("cells: [{qos: 1}, {qos: 1}]\n", u"/p"_s);
        QVERIFY(!plan);
        QVERIFY(!plan.error().pos.isValid());
        QCOMPARE(plan.error().toString(), u"two cells are the same: qos 1"_s);
    }

    void fileErrorsNameTheFile()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(u"plan.yaml"_s);
        QVERIFY(AtomicFile::write(path, "samples: 5\nfactor: {}\n", false));
        QByteArray text;
        const Result<ExperimentPlan> plan = ExperimentPlan::readFile(path, &text);
        QVERIFY(!plan);
        QCOMPARE(plan.error().file, path);
        QCOMPARE(plan.error().pos, (TextPos {1, 0}));
        QVERIFY(text.isEmpty());
        QVERIFY2(plan.error().toString().startsWith(
                     path + u": line 2, column 1: unknown key 'factor' (known: name,"_s),
                 qPrintable(plan.error().toString()));
        const Result<WatchRules> missing = WatchRules::readFile(dir.filePath(u"none.yaml"_s));
        QVERIFY(!missing);
        QCOMPARE(missing.error().file, dir.filePath(u"none.yaml"_s));
        QVERIFY(!missing.error().pos.isValid());
        QString error;
        QVERIFY(!noted(WatchRules::readFile(dir.filePath(u"none.yaml"_s)), &error));
        QCOMPARE(error, missing.error().toString());
        QVERIFY(error.startsWith(dir.filePath(u"none.yaml"_s) + u": "_s));
    }

    void rulesAndPipelinesNameTheLineOnly()
    {
        const Result<WatchRules> rules = WatchRules::read("defaults:\n  stall_seconds: -1\n");
        QVERIFY(!rules);
        QCOMPARE(rules.error().pos.line, 1);
        QCOMPARE(rules.error().toString(),
                 u"line 2: stall_seconds takes a number ≥ 0 or {warning: N, alert: N}"_s);
        const Result<WatchRules> unknown = WatchRules::read("default: {}\n");
        QVERIFY(!unknown);
        QCOMPARE(unknown.error().toString(), u"line 1: unknown key 'default' (known: defaults, links)"_s);
        const Result<Pipeline> pipeline = Pipeline::read("topics_in_order: [/a, /b]\nhosts:\n  /c: x\n");
        QVERIFY(!pipeline);
        QCOMPARE(pipeline.error().pos, (TextPos {2, 2}));
        QCOMPARE(pipeline.error().toString(), u"line 3: hosts names /c, which is not in topics_in_order"_s);
    }

    void limitsAndSyntaxErrorsAreLocated()
    {
        const YamlReader reader;
        const Result<YAML::Node> syntax = reader.parse("a: [1,\n  2");
        QVERIFY(!syntax);
        QVERIFY(syntax.error().pos.isValid());
        QCOMPARE(syntax.error().code, u"yaml-syntax"_s);
        const Result<YAML::Node> duplicate = reader.parse("a: 1\nb: 2\na: 3\n");
        QVERIFY(!duplicate);
        QCOMPARE(duplicate.error().pos, (TextPos {2, 0}));
        QCOMPARE(duplicate.error().code, u"yaml-duplicate-key"_s);
        QVERIFY(!duplicate.error().fix.isEmpty());
        QVERIFY2(duplicate.error().message.contains(u"appears twice"_s),
                 qPrintable(duplicate.error().message));
    }

    void typedFieldsCarryTheirPlace()
    {
        const YamlReader reader;
        const Result<YAML::Node> root = reader.parse("name: x\nsamples:   42\n");
        QVERIFY(root);
        const Result<YamlField<int>> samples = reader.integer(*root, "samples", 1, 100, 7, u"bad"_s);
        QVERIFY(samples);
        QCOMPARE(samples->value, 42);
        QCOMPARE(samples->pos, (TextPos {1, 11}));
        const Result<YamlField<int>> absent = reader.integer(*root, "warmup", 0, 100, 7, u"bad"_s);
        QVERIFY(absent);
        QCOMPARE(absent->value, 7);
        QVERIFY(!absent->present());
        const Result<YamlField<int>> out = reader.integer(*root, "samples", 1, 10, 7, u"too many"_s);
        QVERIFY(!out);
        QCOMPARE(out.error().toString(), u"line 2, column 12: too many"_s);
        QVERIFY((reader.checkKeys(*root, {u"name"_s, u"samples"_s})));
        const Status unknown = reader.checkKeys(*root, {u"name"_s});
        QVERIFY(!unknown);
        QCOMPARE(unknown.error().toString(), u"line 2, column 1: unknown key 'samples' (known: name)"_s);
    }
};

QTEST_GUILESS_MAIN(TestYamlReader)
#include "tst_yamlreader.moc"
