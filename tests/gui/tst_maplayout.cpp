// SPDX-License-Identifier: MIT
// Issue 40: the Map page at 1280x800 on the demo lab, the page a lab leaves open. Both mapping
// column titles read `…marking_suite/`, topic cells `/b…/t…/m…/o…/in`, options `st…ps`, and the
// hint and the inspector's fields were cut. Every mapping of both demo configs shows its topic
// names readable (whole where the table has room, else by NameDelegate's rules: the last segment
// always), titles, options and health whole, the hint and the inspector's fields whole, and the
// discovered ROS topics as a namespace tree whose rows show their segments whole. A broken or too
// large config opens read-only, its text shown with its error's line marked.
#include "app/gui/mainwindow.h"
#include "config/configdocument.h"
#include "config/mappingmodel.h"
#include "demo/demolab.h"
#include "mqtt/mqttprofile.h"
#include "namecheck.h"
#include "resulttext.h"
#include "session/livesession.h"
#include "topics/topictablemodel.h"
#include "viewaudit.h"
#include "viewhelpers.h"
#include "widgets/common/nameheader.h"
#include "widgets/discover/discoverpage.h"
#include "widgets/map/configeditor.h"
#include "widgets/map/configfilecontroller.h"
#include "widgets/map/configtabs.h"
#include "widgets/map/mappage.h"
#include "widgets/map/mappinginspector.h"
#include "widgets/map/yamlpreview.h"
#include "windowparts.h"

#include <QComboBox>
#include <QFile>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QRegularExpression>
#include <QScrollBar>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QTextBlock>
#include <QTreeView>

using namespace Qt::StringLiterals;
using ViewHelpers::named;
using ViewHelpers::only;
using namespace WindowParts;

namespace {
/// What of the mapping table is cut: a title, an options or health cell; empty when nothing.
QString cutInMappingTable(QTableView* table)
{
    const QAbstractItemModel* model = table->model();
    auto* header = qobject_cast<NameHeader*>(table->horizontalHeader());
    if (!header)
        return u"no NameHeader"_s;
    QFont bold = header->font();
    bold.setBold(true); // a section over selected rows is drawn bold
    const QFontMetrics fm(bold);
    QStyleOptionHeader option;
    option.initFrom(header);
    const int margin = header->style()->pixelMetric(QStyle::PM_HeaderMargin, &option, header);
    for (int c = 0; c < model->columnCount(); ++c) {
        if (table->isColumnHidden(c))
            continue;
        const QString title = header->title(c);
        int room = header->sectionSize(c) - 2 * margin;
        if (header->isSortIndicatorShown() && header->sortIndicatorSection() == c)
            room -= header->style()->pixelMetric(QStyle::PM_HeaderMarkSize, &option, header) + margin;
        if (fm.horizontalAdvance(title) > room)
            return u"title '%1' needs %2 px, has %3"_s.arg(title).arg(fm.horizontalAdvance(title)).arg(room);
    }
    const QStyleOptionViewItem cell = cellOption(table);
    for (int r = 0; r < model->rowCount(); ++r) {
        for (int c : {int(MappingModel::DirectionColumn), int(MappingModel::OptionsColumn),
                      int(MappingModel::HealthColumn)}) {
            const QModelIndex index = model->index(r, c);
            const int needs = table->itemDelegateForIndex(index)->sizeHint(cell, index).width();
            if (needs > table->columnWidth(c))
                return u"'%1' needs %2 px, has %3"_s.arg(index.data().toString())
                    .arg(needs)
                    .arg(table->columnWidth(c));
        }
    }
    if (table->horizontalScrollBar()->isVisible())
        return u"the table scrolls sideways"_s;
    return {};
}

/// A label shows its whole text: wrapped within its height, or on one line within its width.
QString labelCut(const QLabel* label)
{
    if (!label->isVisible() || label->text().isEmpty())
        return {};
    const bool fits = label->wordWrap() ? label->heightForWidth(label->width()) <= label->height()
                                        : label->sizeHint().width() <= label->width();
    return fits ? QString()
                : u"label '%1' cut (%2x%3)"_s.arg(label->text()).arg(label->width()).arg(label->height());
}

/// Every visible line edit, combo box and label of `widget` shows its text whole.
QString fieldsCut(const QWidget* widget)
{
    for (const QLineEdit* edit : widget->findChildren<QLineEdit*>()) {
        if (edit->isVisible() && edit->fontMetrics().horizontalAdvance(edit->text()) + 12 > edit->width())
            return u"field %1: '%2' in %3 px"_s.arg(edit->objectName(), edit->text()).arg(edit->width());
    }
    for (const QComboBox* box : widget->findChildren<QComboBox*>()) {
        if (box->isVisible() && box->fontMetrics().horizontalAdvance(box->currentText()) + 24 > box->width())
            return u"choice %1: '%2' in %3 px"_s.arg(box->objectName(), box->currentText()).arg(box->width());
    }
    for (const QLabel* label : widget->findChildren<QLabel*>())
        if (const QString cut = labelCut(label); !cut.isEmpty())
            return cut;
    return {};
}

/// The words above a read-only file's text (that it is read-only, why and where), or null.
const QLabel* readOnlyNote(const ConfigEditor* editor)
{
    for (const QLabel* label : only<YamlPreview>(*editor)->findChildren<QLabel*>())
        if (label->isVisible() && label->text().contains(u"Read-only"_s))
            return label;
    return nullptr;
}

/// Retries `check` while the columns fit themselves (100 ms after a change; figures grow once a second).
template<class Check> QString settled(Check check)
{
    QString problem;
    (void)QTest::qWaitFor([&] { return (problem = check()).isEmpty(); }, 4000);
    return problem;
}
} // namespace

class TestMapLayout : public QObject
{
    Q_OBJECT
private:
    DemoLab m_lab;
    std::unique_ptr<MainWindow> m_window;

private slots:
    void initTestCase()
    {
        DemoLab::Options options;
        options.program = QStringLiteral(BRIDGESCOPE_BINARY);
        options.payloadBytes = 20000; // the page is tested, not the lab
        QString error;
        QVERIFY2(noted(m_lab.start(options), &error), qPrintable(error));
        m_window = std::make_unique<MainWindow>();
        MainWindow* w = m_window.get();
        w->discoverPage()->setRosMasterUri(m_lab.rosMasterUri());
        w->discoverPage()->connectBroker(MqttProfile::fromUrl(m_lab.brokerUrl()));
        QVERIFY(w->files()->openFile(m_lab.vehicleConfigPath()));
        QVERIFY(w->files()->openFile(m_lab.cloudConfigPath()));
        // The paper's vehicle config: the suite's long stamp topics.
        QVERIFY(w->files()->openFile(QStringLiteral(BRIDGESCOPE_SOURCE_DIR "/resources/examples/paper_vehicle.yaml")));
        w->resize(1280, 800);
        w->pages()->setCurrentWidget(mapPage(*w));
        w->show();
        QVERIFY(QTest::qWaitForWindowExposed(w));
        QTRY_COMPARE(w->size(), QSize(1280, 800));
        QTRY_VERIFY_WITH_TIMEOUT(w->session()->rosTopics()->rowCount() >= 19, 20000);
    }

    void mappingsReadableAt1280x800_data()
    {
        QTest::addColumn<int>("tab");
        QTest::newRow("vehicle") << 0;
        QTest::newRow("cloud") << 1;
        QTest::newRow("paper vehicle") << 2;
    }

    void mappingsReadableAt1280x800()
    {
        QFETCH(int, tab);
        MainWindow* w = m_window.get();
        MapPage* page = mapPage(*w);
        w->files()->activate(tab);
        QTableView* table = page->editor()->table();
        const QAbstractItemModel* model = table->model();
        QVERIFY(model->rowCount() >= 2);
        // Health with figures: both rates and a latency are the widest it gets.
        QTRY_VERIFY_WITH_TIMEOUT(!model->index(0, MappingModel::HealthColumn).data().toString().isEmpty(), 20000);
        if (tab < 2) // the paper's topics are not in the demo lab
            QTRY_VERIFY_WITH_TIMEOUT(
                model->index(0, MappingModel::HealthColumn).data().toString().contains(u"Hz"_s), 20000);
        if (const QString dir = qEnvironmentVariable("BRIDGESCOPE_SCREENSHOT_DIR"); !dir.isEmpty()) {
            table->selectRow(0);
            // figures grow once a second: the picture once none is cut
            (void)QTest::qWaitFor([&w] { return ViewAudit::elidedFiguresIn(mapPage(*w)).isEmpty(); }, 3000);
            w->grab().save(dir + u"/map-1280x800-%1.png"_s.arg(tab));
        }
        for (int column : {int(MappingModel::RosTopicColumn), int(MappingModel::MqttTopicColumn)}) {
            const QString problem = settled([&] { return namesShownProblem(table, column, 2); });
            QVERIFY2(problem.isEmpty(), qPrintable(problem));
        }
        const QString cut = settled([&] { return cutInMappingTable(table); });
        QVERIFY2(cut.isEmpty(), qPrintable(cut));
        // The hint (in the topics panel) is read whole.
        const auto* hint = page->findChild<QLabel*>(u"mapHint"_s);
        QVERIFY(hint);
        QVERIFY2(labelCut(hint).isEmpty(), qPrintable(labelCut(hint)));
        // The inspector of the first mapping: its fields whole.
        table->selectRow(0);
        MappingInspector* inspector = only<MappingInspector>(*page->editor());
        QTRY_VERIFY(!named<QLineEdit>(*inspector, u"ros_topic"_s)->text().isEmpty());
        const QString fields = settled([&] { return fieldsCut(inspector); });
        QVERIFY2(fields.isEmpty(), qPrintable(fields));
        // The discovered ROS topics: a namespace tree, every row's segment whole.
        auto* ros = qobject_cast<QTreeView*>(named<QTreeView>(*page, u"mapRosTopics"_s));
        QVERIFY2(ros, "the Map's ROS topics are no namespace tree");
        const QString names = settled([&] { return treeNamesShownProblem(ros, 0, 19); });
        QVERIFY2(names.isEmpty(), qPrintable(names));

    }

    // Folded away, the topics panel gives its width to the mappings: their names show whole.
    void theTopicsPanelFoldsAway()
    {
        MainWindow* w = m_window.get();
        MapPage* page = mapPage(*w);
        w->files()->activate(0);
        QTableView* table = page->editor()->table();
        const int before = table->width();
        named<QAction>(*page, u"topicsPanelAction"_s)->setChecked(false);
        QTRY_VERIFY(table->width() > before + 200);
        const QString problem = settled([&] {
            for (int c : {int(MappingModel::RosTopicColumn), int(MappingModel::MqttTopicColumn)}) {
                auto* names = qobject_cast<NameDelegate*>(table->itemDelegateForColumn(c));
                for (int r = 0; r < table->model()->rowCount(); ++r) {
                    const QModelIndex index = table->model()->index(r, c);
                    if (names->displayedText(index) != index.data().toString())
                        return u"%1 shows as %2"_s.arg(index.data().toString(), names->displayedText(index));
                }
            }
            return cutInMappingTable(table);
        });
        named<QAction>(*page, u"topicsPanelAction"_s)->setChecked(true);
        QVERIFY2(problem.isEmpty(), qPrintable(problem));
    }

    // A config that does not read opens read-only, its text shown with the error's line marked
    // and said; nothing can be edited or saved (before, it was refused: nothing to look at).
    void aBrokenConfigOpensReadOnlyWithItsErrorLocated()
    {
        MainWindow* w = m_window.get();
        QTemporaryDir dir;
        const QString path = dir.filePath(u"broken.yaml"_s);
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        const QByteArray text = "bridge:\n  ros2mqtt:\n    - ros_topic: /a\n      mqtt_topic: a\n"
                                "    - ros_topic: [/b\n      mqtt_topic: b\n";
        f.write(text);
        f.close();
        QVERIFY(w->files()->openFile(path));
        QVERIFY(w->document()->filePath().endsWith(u"broken.yaml"_s));
        auto* tabs = mapPage(*w)->findChild<ConfigTabs*>();
        QVERIFY(tabs);
        QVERIFY2(tabs->tabText(tabs->currentIndex()).contains(u"read-only"_s),
                 qPrintable(tabs->tabText(tabs->currentIndex())));
        ConfigEditor* editor = mapPage(*w)->editor();
        auto* inspectorTabs = editor->findChild<QTabWidget*>(u"inspectorTabs"_s);
        QCOMPARE(inspectorTabs->currentWidget(), static_cast<QWidget*>(only<YamlPreview>(*editor)));
        QTRY_COMPARE(only<YamlPreview>(*editor)->text(), QString::fromUtf8(text));
        // Why, where, and that it is read-only, above the text, whole.
        const QLabel* noteLabel = readOnlyNote(editor);
        QVERIFY(noteLabel);
        const QString note = noteLabel->text();
        QVERIFY2(QRegularExpression(u"Line \\d+, column \\d+: "_s).match(note).hasMatch(), qPrintable(note));
        const QString noteCut = settled([&] { return labelCut(noteLabel); });
        QVERIFY2(noteCut.isEmpty(), qPrintable(noteCut));
        // The line is marked and the cursor is on it.
        auto* view = only<YamlPreview>(*editor)->findChild<QPlainTextEdit*>(u"previewText"_s);
        const QList<QTextEdit::ExtraSelection> marks = view->extraSelections();
        QVERIFY(!marks.isEmpty());
        const int line = marks.first().cursor.block().blockNumber();
        QVERIFY2(note.contains(u"Line %1,"_s.arg(line + 1)), qPrintable(note));
        QCOMPARE(view->textCursor().block().blockNumber(), line);
        // Nothing edits it: no mapping is added, nothing is saved over it.
        QVERIFY(!editor->table()->isEnabled());
        QVERIFY(!editor->addRos2MqttAction()->isEnabled());
        editor->addMapping(Direction::Ros2Mqtt);
        QCOMPARE(w->document()->mappingCount(), 0);
        QCOMPARE(w->document()->save(path, ConfigLayout::Ros1, true).status, ConfigDocument::SaveResult::Failed);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QCOMPARE(f.readAll(), text);
        f.close();
        QVERIFY(w->files()->closeConfig(w->files()->currentIndex()));
    }

    // A file past the size limit: its first part, bounded, and its size said in MB.
    void aHugeConfigOpensReadOnlyInPart()
    {
        MainWindow* w = m_window.get();
        QTemporaryDir dir;
        const QString path = dir.filePath(u"huge.yaml"_s);
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("bridge:\n  ros2mqtt:\n");
        const QByteArray block = "    - ros_topic: /a\n      mqtt_topic: a\n";
        while (f.size() < 17 * 1024 * 1024 + 300 * 1024)
            f.write(block);
        f.close();
        QVERIFY(w->files()->openFile(path));
        ConfigEditor* editor = mapPage(*w)->editor();
        QTRY_VERIFY(readOnlyNote(editor) && readOnlyNote(editor)->text().contains(u" MB"_s));
        const QString note = readOnlyNote(editor)->text();
        QVERIFY2(note.contains(u"The file is 17 MB, the limit is 8 MB."_s), qPrintable(note));
        QVERIFY2(note.contains(u"Only the first 1.0 MB of 17.3 MB are shown."_s), qPrintable(note));
        QVERIFY(!note.contains(u"8388608"_s));
        const QString shown = only<YamlPreview>(*editor)->text();
        QVERIFY(shown.startsWith(u"bridge:\n  ros2mqtt:\n"_s));
        QVERIFY2(shown.size() <= 1024 * 1024, qPrintable(QString::number(shown.size())));
        QVERIFY(w->files()->closeConfig(w->files()->currentIndex()));
    }

    void cleanupTestCase() { m_window.reset(); }
};

QTEST_MAIN(TestMapLayout)
#include "tst_maplayout.moc"
