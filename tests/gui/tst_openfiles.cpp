// SPDX-License-Identifier: MIT
// Open anything: files dropped on the window, given on the command line (as a desktop's %F gives
// them) or picked from Open Recent go where they belong: bridge configs to Map (a tab each), a
// pipeline and one measurement to Measure, several measurements to Reports, an experiment's folder
// to Experiments; what does not open is said and changes nothing.
#include "app/gui/mainwindow.h"
#include "config/configdocument.h"
#include "experiment/experimentrunner.h"
#include "fixtures.h"
#include "latency/pipeline.h"
#include "record/suitecsv.h"
#include "resulttext.h"
#include "session/measuresession.h"
#include "stampbag.h"
#include "syntheticrun.h"
#include "viewhelpers.h"
#include "widgets/links/linkmodel.h"
#include "widgets/discover/discoverpage.h"
#include "widgets/experiment/experimentpage.h"
#include "widgets/links/linkspage.h"
#include "widgets/map/configfilecontroller.h"
#include "widgets/map/configtabs.h"
#include "widgets/map/mappage.h"
#include "widgets/measure/measurepage.h"
#include "widgets/measure/runbar.h"
#include "widgets/reports/reportspage.h"
#include "windowparts.h"

#include <QAction>
#include <QDragEnterEvent>
#include <QListWidget>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QProcess>
#include <QSettings>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QTreeWidget>

using namespace Qt::StringLiterals;
using ViewHelpers::named;
using namespace WindowParts;

namespace {
/// Drops `paths` as a file manager would: drag enter, then drop, at the middle of `target`.
bool drop(QWidget* target, const QStringList& paths)
{
    QMimeData mime;
    QList<QUrl> urls;
    for (const QString& p : paths)
        urls << QUrl::fromLocalFile(p);
    mime.setUrls(urls);
    const QPoint at = target->rect().center();
    QDragEnterEvent enter(at, Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(target, &enter);
    if (!enter.isAccepted())
        return false;
    QDropEvent dropped(QPointF(at), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(target, &dropped);
    QCoreApplication::processEvents(); // the window opens them once the drop has ended
    return dropped.isAccepted();
}

QStringList tabTexts(MapPage* page)
{
    QStringList texts;
    for (int i = 0; i < named<ConfigTabs>(*page, u"configTabs"_s)->count(); ++i)
        texts << named<ConfigTabs>(*page, u"configTabs"_s)->tabText(i);
    return texts;
}

/// The configs the Links page lists (watched or not: opening one watches nothing).
QStringList listedConfigs(LinksPage* page)
{
    QStringList names;
    for (int r = 0; r < named<QTreeWidget>(*page, u"watchConfigs"_s)->topLevelItemCount(); ++r)
        names << named<QTreeWidget>(*page, u"watchConfigs"_s)->topLevelItem(r)->text(0);
    return names;
}
} // namespace

class TestOpenFiles : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;
    QString m_config, m_otherConfig, m_pipeline, m_csvA, m_csvB, m_bag, m_experiment, m_plan;

    static QMenu* recentMenu(MainWindow& w)
    {
        for (QAction* a : w.menuBar()->actions())
            if (a->menu())
                for (QAction* b : a->menu()->actions())
                    if (b->menu() && b->text().contains(u"Recent"_s))
                        return b->menu();
        return nullptr;
    }

    QString write(const QString& name, const QByteArray& bytes)
    {
        const QString path = m_dir.filePath(name);
        QFile f(path);
        if (!f.open(QIODevice::WriteOnly) || f.write(bytes) != bytes.size())
            qFatal("cannot write %s", qPrintable(path));
        return path;
    }

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        QSettings::setDefaultFormat(QSettings::IniFormat); // recent files go to the temporary folder
        QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, m_dir.path());
        QSettings().clear();
        m_config = write(u"vehicle.yaml"_s,
                         Fixtures::read(u"benchmarking_suite/mqtt_client_vehicle_pointcloud.yaml"_s));
        m_otherConfig
            = write(u"cloud.yaml"_s, Fixtures::read(u"benchmarking_suite/mqtt_client_cloud.yaml"_s));
        m_pipeline = write(u"logger.yaml"_s,
                           Fixtures::read(u"benchmarking_suite/metrics_logger_mqtt_interface.yaml"_s));
        const SyntheticRun a = SyntheticRun::paper(50, 0, 1);
        m_csvA = write(u"a.csv"_s, SuiteCsv::write(a.topics, a.samples));
        const SyntheticRun b = SyntheticRun::paper(60, 0, 2);
        m_csvB = write(u"b.csv"_s, SuiteCsv::write(b.topics, b.samples));
        // A bag recorded with rosbag's own API: the suite's stamps and more.
        m_bag = m_dir.filePath(u"stamps.bag"_s);
        StampBag::write(m_bag, SyntheticRun::paper(20, 0, 4));
        // An experiment's folder: its plan and its (empty) state.
        QVERIFY(QDir(m_dir.path()).mkdir(u"exp"_s));
        m_experiment = m_dir.filePath(u"exp"_s);
        QFile plan(QStringLiteral(BRIDGESCOPE_SOURCE_DIR)
                   + u"/resources/examples/experiment-table3-qos.yaml"_s);
        QVERIFY(plan.open(QIODevice::ReadOnly));
        write(u"exp/"_s + ExperimentFolder::planFileName(), plan.readAll());
        write(u"exp/"_s + ExperimentFolder::stateFileName(), "{}");
        // A plan alone, as a file manager or the command line gives it.
        QFile size(QStringLiteral(BRIDGESCOPE_SOURCE_DIR) + u"/resources/examples/experiment-table1-methods.yaml"_s);
        QVERIFY(size.open(QIODevice::ReadOnly));
        m_plan = write(u"size-study.yaml"_s, size.readAll());
    }

    // A lab has two ends: both configs are on Map, each with its name, its health and its edits,
    // saved each to its own file; the window's title names the one shown.
    void everyConfigOnMapSavedPerFile()
    {
        QTemporaryDir dir;
        const auto copy = [&](const QString& from, const QString& name) {
            const QString to = dir.filePath(name);
            QFile::copy(from, to);
            return to;
        };
        const QString vehicle = copy(m_config, u"vehicle.yaml"_s);
        const QString cloud = copy(m_otherConfig, u"cloud.yaml"_s);
        MainWindow w;
        w.resize(1280, 800);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(w.openPaths({vehicle, cloud}).isEmpty());
        ConfigTabs* tabs = named<ConfigTabs>(*mapPage(w), u"configTabs"_s);
        QCOMPARE(tabTexts(mapPage(w)), QStringList({u"vehicle.yaml"_s, u"cloud.yaml"_s}));
        QCOMPARE(tabs->currentIndex(), 0);
        QVERIFY(tabs->isVisible() && tabs->geometry().intersects(mapPage(w)->rect()));
        QVERIFY2(w.windowTitle().startsWith(u"vehicle.yaml"_s), qPrintable(w.windowTitle()));
        mapPage(w)->updateHealth();
        QVERIFY2(tabs->tabToolTip(1).contains(cloud) && tabs->tabToolTip(1).contains(u"mapping"_s),
                 qPrintable(tabs->tabToolTip(1)));

        // An edit of each, then a save of the second only.
        const int vehicleMappings = w.document()->mappingCount();
        w.document()->removeMappings({w.document()->mapping(0).id});
        QCOMPARE(tabs->tabText(0), u"vehicle.yaml •"_s);
        tabs->setCurrentIndex(1);
        QCOMPARE(w.document()->filePath(), cloud);
        QVERIFY2(w.windowTitle().startsWith(u"cloud.yaml"_s), qPrintable(w.windowTitle()));
        const int cloudMappings = w.document()->mappingCount();
        w.document()->removeMappings({w.document()->mapping(0).id});
        QVERIFY(w.files()->save());
        QCOMPARE(tabTexts(mapPage(w)), QStringList({u"vehicle.yaml •"_s, u"cloud.yaml"_s}));
        ConfigDocument reread;
        QVERIFY(reread.load(cloud).ok);
        QCOMPARE(reread.mappingCount(), cloudMappings - 1);
        QVERIFY(reread.load(vehicle).ok);
        QCOMPARE(reread.mappingCount(), vehicleMappings); // not saved yet

        // Back to the first: its edit waited; saved to its own file.
        tabs->setCurrentIndex(0);
        QCOMPARE(w.document()->filePath(), vehicle);
        QCOMPARE(w.document()->mappingCount(), vehicleMappings - 1);
        QVERIFY(w.document()->isModified());
        QVERIFY(w.files()->save());
        QVERIFY(reread.load(vehicle).ok);
        QCOMPARE(reread.mappingCount(), vehicleMappings - 1);
        QCOMPARE(tabTexts(mapPage(w)), QStringList({u"vehicle.yaml"_s, u"cloud.yaml"_s}));

        // Opening one again shows it; closing one leaves the other.
        QVERIFY(w.openPaths({cloud}).isEmpty());
        QCOMPARE(tabs->count(), 2);
        QCOMPARE(w.document()->filePath(), cloud);
        QVERIFY(w.files()->closeConfig(1));
        QCOMPARE(tabTexts(mapPage(w)), QStringList({u"vehicle.yaml"_s}));
        QCOMPARE(w.document()->filePath(), vehicle);
    }

    void eachKindByDrop()
    {
        MainWindow w;
        w.resize(1280, 800);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));

        QVERIFY(drop(&w, {m_config}));
        QCOMPARE(w.pages()->currentWidget(), mapPage(w));
        QCOMPARE(w.document()->filePath(), m_config);

        w.pages()->setCurrentWidget(w.discoverPage());
        QVERIFY(drop(&w, {m_pipeline}));
        QCOMPARE(w.pages()->currentWidget(), w.measurePage());
        QCOMPARE(w.measure()->pipeline().topics(), Pipeline::readFile(m_pipeline)->topics());
        QCOMPARE(w.document()->filePath(), m_config); // the config stays

        // One measurement: shown on the Measure page.
        w.pages()->setCurrentWidget(w.discoverPage());
        QVERIFY(drop(&w, {m_csvA}));
        QCOMPARE(w.pages()->currentWidget(), w.measurePage());
        QVERIFY(w.measure()->isShowingRun());
        // Saved as a run file, the run opens by drop too.
        const QString run = m_dir.filePath(u"a.bsrun"_s);
        QString error;
        QVERIFY2(noted(w.measurePage()->runBar()->saveRunAs(run), &error), qPrintable(error));
        w.measurePage()->runBar()->backToLive();
        QVERIFY(!w.measure()->isShowingRun());
        w.pages()->setCurrentWidget(mapPage(w));
        QVERIFY(drop(&w, {run}));
        QCOMPARE(w.pages()->currentWidget(), w.measurePage());
        QVERIFY(w.measure()->isShowingRun());

        // A bag alone: shown on the Measure page too (read by the bag helper process).
        w.measurePage()->runBar()->backToLive();
        w.pages()->setCurrentWidget(w.discoverPage());
        QVERIFY(drop(&w, {m_bag}));
        QTRY_COMPARE(w.pages()->currentWidget(), w.measurePage());
        QVERIFY(w.measure()->isShowingRun());

        // Several: compared on the Reports page, bags among them.
        QVERIFY(drop(&w, {m_csvA, m_csvB, m_bag}));
        QCOMPARE(w.pages()->currentWidget(), reportsPage(w));
        QCOMPARE(reportsPage(w)->inputs(), QStringList({m_csvA, m_csvB, m_bag}));

        // An experiment's folder.
        QVERIFY(drop(&w, {m_experiment}));
        QCOMPARE(w.pages()->currentWidget(), experimentPage(w));
        QVERIFY(experimentPage(w)->planText().contains(u"qos"_s));

        // A plan: to the Experiments page, not refused as a config (issue 33).
        w.pages()->setCurrentWidget(w.discoverPage());
        QVERIFY(drop(&w, {m_plan}));
        QCOMPARE(w.pages()->currentWidget(), experimentPage(w));
        QVERIFY(experimentPage(w)->planText().contains(u"Methods (Table I)"_s));

        // Two configs: both on Map, a tab each, the first shown; Links lists both.
        QVERIFY(drop(&w, {m_otherConfig, m_config}));
        QCOMPARE(w.pages()->currentWidget(), mapPage(w));
        QCOMPARE(w.document()->filePath(), m_otherConfig);
        QCOMPARE(tabTexts(mapPage(w)), QStringList({u"vehicle.yaml"_s, u"cloud.yaml"_s}));
        QTRY_VERIFY(listedConfigs(w.linksPage()).contains(u"vehicle"_s));
        QTRY_VERIFY(listedConfigs(w.linksPage()).contains(u"cloud"_s));

        // Open Recent has runs and pipelines as well as configs, and opens each where it belongs.
        QMenu* recent = recentMenu(w);
        QVERIFY(recent);
        QStringList entries;
        for (QAction* a : recent->actions())
            entries << a->text();
        for (const QString& name : {u"a.bsrun"_s, u"logger.yaml"_s, u"a.csv"_s, u"b.csv"_s, u"stamps.bag"_s,
                                    u"exp"_s, u"cloud.yaml"_s})
            QVERIFY2(entries.join(u'\n').contains(name), qPrintable(entries.join(u'\n')));
        w.pages()->setCurrentWidget(mapPage(w));
        for (QAction* a : recent->actions())
            if (a->text().startsWith(u"a.bsrun"_s)) {
                a->trigger(); // the menu is made anew: its actions go
                break;
            }
        QTRY_COMPARE(w.pages()->currentWidget(), w.measurePage());
    }

    void whatDoesNotOpenIsSaid()
    {
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(drop(&w, {m_config}));
        const QString notAConfig = write(u"broken.yaml"_s, "bridge: [unclosed\n");
        const QString plainFolder = m_dir.filePath(u"plain"_s);
        QVERIFY(QDir().mkpath(plainFolder));
        const QString damagedRun = write(u"damaged.bsrun"_s, "not a run file");
        QVERIFY(drop(&w, {notAConfig, plainFolder, m_dir.filePath(u"gone.bsrun"_s), damagedRun}));
        auto* box = w.findChild<QMessageBox*>(u"openErrors"_s);
        QVERIFY(box);
        // A config that does not read opens read-only, its error shown there (issue 40).
        QVERIFY2(!box->informativeText().contains(u"broken.yaml"_s), qPrintable(box->informativeText()));
        QVERIFY(box->informativeText().contains(u"plain"_s));
        QVERIFY(box->informativeText().contains(u"gone.bsrun"_s));
        QVERIFY(box->informativeText().contains(u"damaged.bsrun"_s));
        QVERIFY(!w.measure()->isShowingRun());
        QCOMPARE(w.files()->openCount(), 2);
        QCOMPARE(w.files()->pathOf(0), m_config); // nothing lost
        QVERIFY(w.files()->pathOf(1).endsWith(u"broken.yaml"_s) && w.files()->isReadOnly(1));
        box->accept();
    }

    void reportsPageKeepsMeasurementsAndPassesTheRest()
    {
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        w.pages()->setCurrentWidget(reportsPage(w));
        // Its own drop adds measurements as inputs, even one; a config is not its to take.
        QVERIFY(drop(reportsPage(w), {m_csvA}));
        QCOMPARE(reportsPage(w)->inputs(), QStringList {m_csvA});
        QCOMPARE(w.pages()->currentWidget(), reportsPage(w));
        QVERIFY(!w.measure()->isShowingRun());
        // A config dragged over it is not its to take: the page leaves it to the window (Qt passes
        // an ignored drag on to the parent), which opens it on the Map page.
        QMimeData mime;
        mime.setUrls({QUrl::fromLocalFile(m_config)});
        QDragEnterEvent enter(QPoint(5, 5), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
        static_cast<QObject*>(reportsPage(w))->event(&enter); // the page alone, not its parents
        QVERIFY(!enter.isAccepted());
        QVERIFY(drop(&w, {m_config}));
        QCOMPARE(w.pages()->currentWidget(), mapPage(w));
        QCOMPARE(reportsPage(w)->inputs(), QStringList {m_csvA});
        // It opens them the window's one way: a measurement never opened before goes among the
        // recent files as from any other drop.
        const QString fresh = m_dir.filePath(u"fresh.csv"_s);
        QVERIFY(QFile::copy(m_csvB, fresh));
        w.pages()->setCurrentWidget(reportsPage(w));
        QVERIFY(drop(reportsPage(w), {fresh}));
        QCOMPARE(w.pages()->currentWidget(), reportsPage(w));
        QCOMPARE(reportsPage(w)->inputs(), (QStringList {m_csvA, fresh}));
        QStringList entries;
        for (QAction* a : recentMenu(w)->actions())
            entries << a->text();
        QVERIFY2(entries.join(u'\n').contains(u"fresh.csv"_s), qPrintable(entries.join(u'\n')));
    }

    void commandLineOpensEveryFile()
    {
        // As a desktop's `Exec=bridgescope %F` starts it: several files of different kinds.
        const QString png = m_dir.filePath(u"shot.png"_s);
        const auto run = [&](const QStringList& files) {
            QProcess p;
            QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
            env.insert(u"QT_QPA_PLATFORM"_s, u"offscreen"_s);
            env.insert(u"XDG_CONFIG_HOME"_s, m_dir.filePath(u"config"_s));
            p.setProcessEnvironment(env);
            // --verbose: the window says where each file opened.
            p.start(QStringLiteral(BRIDGESCOPE_BINARY),
                    QStringList {u"--verbose"_s, u"--screenshot"_s, png, u"--after"_s, u"0.5"_s} + files);
            p.waitForFinished(60000);
            return std::pair {p.exitCode(), QString::fromUtf8(p.readAllStandardError())};
        };
        const auto openedOn = [](const QString& err, const QString& path, const QString& page) {
            return err.contains(u"opened %1 on the %2 page"_s.arg(path, page));
        };
        const auto [exit, err]
            = run({m_config, m_otherConfig, m_pipeline, m_csvA, m_csvB, m_bag, m_experiment});
        QVERIFY2(exit == 0 && QFile::exists(png), qPrintable(err));
        QVERIFY2(openedOn(err, m_config, u"Map"_s), qPrintable(err));
        QVERIFY2(openedOn(err, m_otherConfig, u"Map"_s), qPrintable(err));
        QVERIFY2(openedOn(err, m_pipeline, u"Measure"_s), qPrintable(err));
        for (const QString& measurement : {m_csvA, m_csvB, m_bag})
            QVERIFY2(openedOn(err, measurement, u"Reports"_s), qPrintable(err));
        QVERIFY2(openedOn(err, m_experiment, u"Experiments"_s), qPrintable(err));
        const auto [planExit, planErr] = run({m_plan});
        QCOMPARE(planExit, 0);
        QVERIFY2(openedOn(planErr, m_plan, u"Experiments"_s), qPrintable(planErr));
        // One measurement of each kind alone: the Measure page.
        for (const QString& measurement : {m_csvA, m_bag}) {
            const auto [oneExit, oneErr] = run({measurement});
            QCOMPARE(oneExit, 0);
            QVERIFY2(openedOn(oneErr, measurement, u"Measure"_s), qPrintable(oneErr));
        }
        // One that does not open among them: said on stderr; a scripted run (a screenshot) ends with 2.
        const auto [badExit, badErr] = run({m_config, m_dir.filePath(u"gone.csv"_s), m_csvA});
        QCOMPARE(badExit, 2);
        QVERIFY2(badErr.contains(u"gone.csv: no such file"_s), qPrintable(badErr));
        // The others open all the same, and only the missing one is said.
        QVERIFY2(openedOn(badErr, m_config, u"Map"_s), qPrintable(badErr));
        QVERIFY2(openedOn(badErr, m_csvA, u"Measure"_s), qPrintable(badErr));
        QVERIFY(!badErr.contains(u"vehicle.yaml:"_s) && !badErr.contains(u"a.csv:"_s));
    }
};

QTEST_MAIN(TestOpenFiles)
#include "tst_openfiles.moc"
