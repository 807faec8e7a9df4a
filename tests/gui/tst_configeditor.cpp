// SPDX-License-Identifier: MIT
// The config editor driven like a user would: open a real file, edit in the inspector and the
// table, undo, redo, save, and check the file on disk (comments included).
#include "app/gui/mainwindow.h"
#include "config/configdocument.h"
#include "config/configreader.h"
#include "config/mappingmodel.h"
#include "config/problemmodel.h"
#include "fixtures.h"
#include "viewhelpers.h"
#include "widgets/common/problemspanel.h"
#include "widgets/map/configeditor.h"
#include "widgets/map/configfilecontroller.h"
#include "widgets/map/mappingfilterproxy.h"
#include "widgets/map/mappinginspector.h"
#include "widgets/map/optionform.h"
#include "widgets/map/settingsinspector.h"
#include "widgets/map/yamlpreview.h"
#include "windowparts.h"

#include <QAbstractItemModelTester>
#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QLabel>
#include <QLineEdit>
#include <QMenuBar>
#include <QStandardPaths>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>
#include <QTreeView>
#include <QUndoStack>

using namespace Qt::StringLiterals;
using ViewHelpers::named;
using ViewHelpers::only;
using namespace WindowParts;

namespace {
QByteArray readFile(const QString& path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

QStringList commentLines(const QByteArray& text)
{
    QStringList out;
    for (const QString& l : QString::fromUtf8(text).split(u'\n')) {
        if (l.contains(u'#'))
            out << l;
    }
    return out;
}

using ViewHelpers::menuAction;

// Replaces a line edit's text the way a user does: select all, type, press Enter.
void typeInto(QLineEdit* edit, const QString& text)
{
    edit->setFocus();
    edit->selectAll();
    QTest::keyClicks(edit, text);
    QTest::keyClick(edit, Qt::Key_Return);
}

int visibleRows(ConfigEditor* editor)
{
    return editor->table()->model()->rowCount();
}
} // namespace

class TestConfigEditor : public QObject
{
    Q_OBJECT
private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void editUndoRedoSaveKeepsComments()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(u"aws.yaml"_s);
        QVERIFY(QFile::copy(Fixtures::path(u"mqtt_client/ros1-era-params.aws.yaml"_s), path));
        QFile::setPermissions(path, QFileDevice::ReadOwner | QFileDevice::WriteOwner);
        const QByteArray original = readFile(path);

        MainWindow w;
        QVERIFY(w.files()->openFile(path));
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        ConfigEditor* editor = w.configEditor();
        MappingInspector* inspector = only<MappingInspector>(*editor);
        QCOMPARE(visibleRows(editor), 2);
        QVERIFY(!w.isWindowModified());

        // Click the mapping in the table: the inspector shows it.
        QTableView* table = editor->table();
        const QModelIndex first = table->model()->index(0, MappingModel::RosTopicColumn);
        QTest::mouseClick(table->viewport(), Qt::LeftButton, {}, table->visualRect(first).center());
        QCOMPARE(named<QLineEdit>(*inspector, u"ros_topic"_s)->text(), u"/ping/primitive"_s);

        // Edit the MQTT topic and the QoS in the inspector.
        typeInto(named<QLineEdit>(*inspector, u"mqtt_topic"_s), u"pingpong/edited"_s);
        auto* qos
            = qobject_cast<QLineEdit*>(inspector->form(Direction::Ros2Mqtt)->editor(u"advanced.mqtt.qos"_s));
        QVERIFY(qos);
        typeInto(qos, u"1"_s);
        QCOMPARE(w.document()->mapping(0).mqttTopic(), u"pingpong/edited"_s);
        QCOMPARE(w.document()->mapping(0).value(u"advanced.mqtt.qos"_s), u"1"_s);
        QCOMPARE(undoStack(w)->count(), 2);
        QVERIFY(w.isWindowModified());

        // Undo both, redo both, through the Edit menu.
        QAction* undo = menuAction(w, u"Edit"_s, u"Undo Set advanced.mqtt.qos"_s);
        QVERIFY(undo);
        undo->trigger();
        QVERIFY(!w.document()->mapping(0).isSet(u"advanced.mqtt.qos"_s));
        QCOMPARE(qos->text(), QString());
        undoStack(w)->undo();
        QCOMPARE(w.document()->mapping(0).mqttTopic(), u"pingpong/primitive"_s);
        QCOMPARE(named<QLineEdit>(*inspector, u"mqtt_topic"_s)->text(), u"pingpong/primitive"_s);
        QVERIFY(!w.isWindowModified()); // back to what is on disk
        undoStack(w)->redo();
        undoStack(w)->redo();
        QCOMPARE(w.document()->mapping(0).mqttTopic(), u"pingpong/edited"_s);
        QCOMPARE(qos->text(), u"1"_s);

        // Save through the File menu: the file is edited in place.
        QAction* save = menuAction(w, u"File"_s, u"Save"_s);
        QVERIFY(save);
        save->trigger();
        QVERIFY(!w.isWindowModified());
        QVERIFY(undoStack(w)->isClean());
        const QByteArray saved = readFile(path);
        QCOMPARE(commentLines(saved), commentLines(original));
        QVERIFY(saved.contains("    version: *tls_1_2\n"));
        QVERIFY(saved.contains("tls_1_2: &tls_1_2 3\n"));
        QVERIFY(saved.contains("    - ros_topic: /ping/primitive\n      mqtt_topic: pingpong/edited\n"
                               "      primitive: true\n      advanced:\n        mqtt:\n          qos: 1\n"));
        QCOMPARE(readFile(path + u".bak"_s), original);

        // Reloaded, the file holds exactly what was edited.
        const ConfigReadResult back = ConfigReader::read(saved);
        QCOMPARE(back.config.mappings[0].mqttTopic(), u"pingpong/edited"_s);
        QCOMPARE(back.config.mappings[1].mqttTopic(), u"pingpong/primitive"_s);
        QCOMPARE(back.config.client.values.text(u"tls.version"_s), u"3"_s);
    }

    void problemsAreShownAndLeadToTheMapping()
    {
        MainWindow w;
        QVERIFY(w.files()->openFile(Fixtures::path(u"mqtt_client/ros1-era-params.yaml"_s)));
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        ConfigEditor* editor = w.configEditor();
        MappingInspector* inspector = only<MappingInspector>(*editor);
        ProblemModel* problems = editor->problems()->model();
        QCOMPARE(problems->errorCount(), 0);
        // The whole chain the table shows (filter over icons over mappings) stays consistent.
        QAbstractItemModelTester tableTester(editor->table()->model(),
                                             QAbstractItemModelTester::FailureReportingMode::QtTest);
        QAbstractItemModelTester problemTester(
            named<QTreeView>(*editor->problems(), u"problemsView"_s)->model(),
            QAbstractItemModelTester::FailureReportingMode::QtTest);

        // Editing a topic in the table itself: a wildcard in a published topic is an error.
        QTableView* table = editor->table();
        const QModelIndex mqtt = table->model()->index(0, MappingModel::MqttTopicColumn);
        table->setCurrentIndex(mqtt);
        table->edit(mqtt);
        auto* cell = qobject_cast<QLineEdit*>(QApplication::focusWidget());
        QVERIFY(cell);
        QCOMPARE(cell->text(), u"pingpong/ros"_s);
        cell->selectAll();
        QTest::keyClicks(cell, u"pingpong/#"_s);
        QTest::keyClick(cell, Qt::Key_Return);
        // The delegate commits on the next turn of the event loop.
        QTRY_COMPARE(w.document()->mapping(0).mqttTopic(), u"pingpong/#"_s);
        QCOMPARE(problems->errorCount(), 1);
        QCOMPARE(undoStack(w)->count(), 1);
        QCOMPARE(mqtt.siblingAtColumn(0).data(Qt::DecorationRole).isNull(), false);

        // Activating the problem selects the mapping and focuses the field.
        table->clearSelection();
        QTreeView* view = named<QTreeView>(*editor->problems(), u"problemsView"_s);
        view->setCurrentIndex(view->model()->index(0, 0));
        emit view->activated(view->model()->index(0, 0));
        QCOMPARE(editor->selectedIds(), QList<quint64> {w.document()->mapping(0).id});
        QVERIFY(named<QLineEdit>(*inspector, u"mqtt_topic"_s)->hasFocus());
        QVERIFY(inspector->findChild<QLabel*>(u"problems"_s)->text().contains(u"wildcard"_s));

        // "With problems" shows just that mapping.
        named<MappingFilterProxy>(*editor, u"mappingFilterProxy"_s)->setOnlyProblems(true);
        QCOMPARE(visibleRows(editor), 1);
        named<MappingFilterProxy>(*editor, u"mappingFilterProxy"_s)->setOnlyProblems(false);
        QTest::keyClicks(editor->filterEdit(), u"pong/ros"_s);
        QCOMPARE(visibleRows(editor), 1);
        editor->filterEdit()->clear();
        QCOMPARE(visibleRows(editor), 4);
    }

    void addDeleteAndMultiSelectionEdit()
    {
        MainWindow w;
        QVERIFY(w.files()->openFile(Fixtures::path(u"mqtt_client/ros1-era-params.yaml"_s)));
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        ConfigEditor* editor = w.configEditor();
        MappingInspector* inspector = only<MappingInspector>(*editor);
        ConfigDocument* doc = w.document();

        // Insert adds a mapping and puts the cursor on its ROS topic.
        editor->table()->setFocus();
        QTest::keyClick(editor->table(), Qt::Key_Insert);
        QCOMPARE(doc->mappingCount(), 5);
        QVERIFY(named<QLineEdit>(*inspector, u"ros_topic"_s)->hasFocus());
        QTest::keyClicks(named<QLineEdit>(*inspector, u"ros_topic"_s), u"/lidar/points"_s);
        QTest::keyClick(named<QLineEdit>(*inspector, u"ros_topic"_s), Qt::Key_Tab);
        QCOMPARE(doc->mapping(4).rosTopic(), u"/lidar/points"_s);

        // Select the two ros2mqtt mappings and set QoS 2 on both in one step.
        editor->selectMappings({doc->mapping(0).id, doc->mapping(1).id});
        QCOMPARE(inspector->mappings().size(), 2);
        QVERIFY(!named<QLineEdit>(*inspector, u"ros_topic"_s)->isEnabled());
        const int before = undoStack(w)->count();
        auto* qos
            = qobject_cast<QLineEdit*>(inspector->form(Direction::Ros2Mqtt)->editor(u"advanced.mqtt.qos"_s));
        QCOMPARE(qos->placeholderText(), u"default: 0"_s);
        typeInto(qos, u"2"_s);
        QCOMPARE(doc->mapping(0).value(u"advanced.mqtt.qos"_s), u"2"_s);
        QCOMPARE(doc->mapping(1).value(u"advanced.mqtt.qos"_s), u"2"_s);
        QCOMPARE(undoStack(w)->count(), before + 1);
        auto* retained = qobject_cast<QComboBox*>(
            inspector->form(Direction::Ros2Mqtt)->editor(u"advanced.mqtt.retained"_s));
        retained->setCurrentIndex(retained->findData(u"true"_s));
        emit retained->activated(retained->currentIndex());
        QCOMPARE(doc->mapping(1).value(u"advanced.mqtt.retained"_s), u"true"_s);

        // Delete removes the selection; undo puts it back in place.
        editor->table()->setFocus();
        QTest::keyClick(editor->table(), Qt::Key_Delete);
        QCOMPARE(doc->mappingCount(), 3);
        undoStack(w)->undo();
        QCOMPARE(doc->mappingCount(), 5);
        QCOMPARE(doc->mapping(0).rosTopic(), u"/ping/ros"_s);
        QCOMPARE(doc->mapping(1).rosTopic(), u"/ping/primitive"_s);

        // Broker settings edit through their own form.
        only<SettingsInspector>(*editor)->focusField(OptionScope::Broker, u"port"_s);
        auto* port = qobject_cast<QLineEdit*>(
            only<SettingsInspector>(*editor)->form(OptionScope::Broker)->editor(u"port"_s));
        typeInto(port, u"8883"_s);
        QCOMPARE(doc->config().broker.values.text(u"port"_s), u"8883"_s);

        // The preview shows the ROS 2 layout on request.
        only<YamlPreview>(*editor)->setLayout(ConfigLayout::Ros2);
        only<YamlPreview>(*editor)->refreshNow();
        QVERIFY(only<YamlPreview>(*editor)->text().contains(u"ros__parameters:"_s));
        QVERIFY(only<YamlPreview>(*editor)->text().contains(u"/lidar/points:"_s));
    }

    void unreadableFilesAreReportedAndNothingIsLost()
    {
        QTemporaryDir dir;
        const QString bad = dir.filePath(u"bad.yaml"_s);
        QFile f(bad);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("bridge: [\n");
        f.close();
        MainWindow w;
        QVERIFY(w.files()->openFile(Fixtures::path(u"mqtt_client/ros1-era-params.yaml"_s)));
        // A broken file opens read-only in a tab of its own (issue 40); one that cannot be read
        // at all is refused.
        QVERIFY(w.files()->openFile(bad));
        QVERIFY(w.document()->isReadOnly());
        QVERIFY(!w.files()->openFile(dir.filePath(u"missing.yaml"_s)));
        // The open document stays, in its tab, with its mappings.
        QCOMPARE(w.files()->openCount(), 2);
        w.files()->activate(0);
        QCOMPARE(w.document()->mappingCount(), 4);
        QVERIFY(w.document()->filePath().endsWith(u"ros1-era-params.yaml"_s));
        QVERIFY(!w.document()->isReadOnly());
    }
};

QTEST_MAIN(TestConfigEditor)
#include "tst_configeditor.moc"
