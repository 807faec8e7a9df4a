// SPDX-License-Identifier: MIT
// The mapping and problem models over a document: consistent (QAbstractItemModelTester) and
// fine-grained (row signals, not resets, for edits).
#include "config/configdocument.h"
#include "config/mappingmodel.h"
#include "config/problemmodel.h"
#include "fixtures.h"

#include <QAbstractItemModelTester>
#include <QSignalSpy>
#include <QSortFilterProxyModel>
#include <QTest>

using namespace Qt::StringLiterals;

class TestConfigModels : public QObject
{
    Q_OBJECT
private slots:
    void mappingModelFollowsTheDocument()
    {
        ConfigDocument doc;
        MappingModel model(&doc);
        QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::QtTest);
        QSortFilterProxyModel proxy;
        proxy.setSourceModel(&model);
        proxy.setSortRole(MappingModel::SortRole);
        proxy.sort(MappingModel::RosTopicColumn);
        QAbstractItemModelTester proxyTester(&proxy, QAbstractItemModelTester::FailureReportingMode::QtTest);

        QVERIFY(doc.load(Fixtures::path(u"benchmarking_suite/mqtt_client_cloud.yaml"_s)).ok);
        QCOMPARE(model.rowCount(), 11);
        QCOMPARE(model.index(0, MappingModel::DirectionColumn).data().toString(),
                 MappingModel::directionText(Direction::Mqtt2Ros));
        QCOMPARE(model.index(0, MappingModel::RosTopicColumn).data().toString(),
                 u"/benchmarking_suite/pointcloud"_s);
        QVERIFY(model.index(0, MappingModel::OptionsColumn).data().toString().contains(u"$(arg qos)"_s));

        QSignalSpy inserted(&model, &QAbstractItemModel::rowsInserted);
        QSignalSpy removed(&model, &QAbstractItemModel::rowsRemoved);
        QSignalSpy changed(&model, &QAbstractItemModel::dataChanged);
        QSignalSpy reset(&model, &QAbstractItemModel::modelReset);

        doc.insertMappings(2, {Mapping::create(Direction::Ros2Mqtt, u"/x"_s, u"x/#"_s)});
        QCOMPARE(inserted.size(), 1);
        QCOMPARE(inserted[0][1].toInt(), 2);
        QCOMPARE(model.rowCount(), 12);
        // The new mapping publishes on a wildcard: its row shows an error.
        const QModelIndex x = model.index(2, 0);
        QCOMPARE(x.data(MappingModel::SeverityRole).toInt(), int(Severity::Error));
        QVERIFY(x.data(Qt::ToolTipRole).toString().contains(u"wildcard"_s));

        // Editing through the model goes to the document (or the edit handler).
        QVERIFY(model.setData(model.index(2, MappingModel::MqttTopicColumn), u"x/fixed"_s));
        QCOMPARE(doc.mapping(2).mqttTopic(), u"x/fixed"_s);
        QCOMPARE(model.index(2, 0).data(MappingModel::SeverityRole).toInt(), -1);
        QVERIFY(!changed.isEmpty());

        const quint64 id = model.index(2, 0).data(MappingModel::MappingIdRole).value<quint64>();
        doc.removeMappings({id, doc.mapping(0).id, doc.mapping(1).id});
        QCOMPARE(model.rowCount(), 9);
        QCOMPARE(removed.size(), 1); // rows 0..2 are one contiguous run
        QCOMPARE(reset.size(), 0);
    }

    void editHandlerReceivesEdits()
    {
        ConfigDocument doc;
        doc.insertMappings(0, {Mapping::create(Direction::Mqtt2Ros, u"/a"_s, u"a"_s)});
        MappingModel model(&doc);
        Mapping before, after;
        model.setEditHandler([&](const Mapping& b, const Mapping& a) {
            before = b;
            after = a;
        });
        QVERIFY(model.setData(model.index(0, MappingModel::RosTopicColumn), u" /b "_s));
        QCOMPARE(before.rosTopic(), u"/a"_s);
        QCOMPARE(after.rosTopic(), u"/b"_s);
        QCOMPARE(doc.mapping(0).rosTopic(), u"/a"_s); // the handler decides
        QVERIFY(!model.setData(model.index(0, MappingModel::DirectionColumn), u"x"_s));
    }

    void problemModelListsErrorsFirst()
    {
        ConfigDocument doc;
        ProblemModel problems(&doc);
        QAbstractItemModelTester tester(&problems, QAbstractItemModelTester::FailureReportingMode::QtTest);
        QSignalSpy counts(&problems, &ProblemModel::countsChanged);
        doc.insertMappings(0,
                           {Mapping::create(Direction::Ros2Mqtt, u"/a"_s, u"/a"_s),
                            Mapping::create(Direction::Ros2Mqtt, u"/a"_s, u"b"_s)});
        QVERIFY(!counts.isEmpty());
        QCOMPARE(problems.errorCount(), 1);
        QCOMPARE(problems.warningCount(), 1);
        QCOMPARE(problems.index(0, 0).data(ProblemModel::SeverityRole).toInt(), int(Severity::Error));
        QCOMPARE(problems.index(0, 0).data(ProblemModel::MappingIdRole).value<quint64>(), doc.mapping(1).id);
        QCOMPARE(problems.index(1, 0).data(ProblemModel::FieldRole).toString(), u"mqtt_topic"_s);
        QVERIFY(problems.index(1, 0).data(Qt::ToolTipRole).toString().contains(u"→"_s));
    }

    void documentTracksModification()
    {
        ConfigDocument doc;
        QVERIFY(doc.load(Fixtures::path(u"mqtt_client/ros1-era-params.yaml"_s)).ok);
        QSignalSpy modified(&doc, &ConfigDocument::modifiedChanged);
        Mapping m = doc.mapping(0);
        const Mapping original = m;
        m.set(u"primitive"_s, u"true"_s);
        doc.replaceMapping(m);
        QVERIFY(doc.isModified());
        doc.replaceMapping(original);
        QVERIFY(!doc.isModified()); // back to what is on disk
        QCOMPARE(modified.size(), 2);
    }
};

QTEST_GUILESS_MAIN(TestConfigModels)
#include "tst_configmodels.moc"
