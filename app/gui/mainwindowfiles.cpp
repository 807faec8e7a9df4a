// SPDX-License-Identifier: MIT
// Opening anything: File › Open, Open Recent, a drop on the window and the command line all send
// files through MainWindow::openPaths, which opens each where it belongs.
#include "app/gui/mainwindow.h"
#include "base/logging.h"
#include "files/regularfile.h"
#include "experiment/experimentreport.h"
#include "report/runloader.h"
#include "widgets/common/droppedfiles.h"
#include "widgets/experiment/experimentpage.h"
#include "widgets/links/linkspage.h"
#include "widgets/map/configfilecontroller.h"
#include "widgets/map/mappage.h"
#include "widgets/map/recentfiles.h"
#include "widgets/measure/measurepage.h"
#include "widgets/measure/runbar.h"
#include "widgets/reports/reportspage.h"

#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QMessageBox>
#include <QRegularExpression>
#include <QStatusBar>
#include <QTabWidget>

using namespace Qt::StringLiterals;

namespace {

enum class Kind { Config, Pipeline, Plan, Measurement, Experiment, Folder };

/// What a file is, from its first bytes: a run or a bag, a suite CSV (by name), a pipeline (YAML
/// with `topics_in_order`), an experiment plan (YAML with `factors` or `cells`), else a bridge config (whose
/// reader says what is wrong if it is none).
Kind kindOf(const QString& path)
{
    const QFileInfo info(path);
    if (info.isDir())
        return ExperimentReport::isExperiment(path) ? Kind::Experiment : Kind::Folder;
    if (RunLoader::isMeasurement(path))
        return Kind::Measurement;
    if (const Result<QByteArray> bytes = RegularFile::readHead(path, 256 * 1024)) {
        static const QRegularExpression pipelineKey(u"(^|\\n)topics_in_order\\s*:"_s);
        static const QRegularExpression planKey(u"(^|\\n)(factors|cells)\\s*:"_s);
        const QString head = QString::fromUtf8(*bytes);
        if (pipelineKey.match(head).hasMatch())
            return Kind::Pipeline;
        if (planKey.match(head).hasMatch())
            return Kind::Plan;
    }
    return Kind::Config;
}

/// The paths given, by kind, in their order, and those that are none.
struct Sorted
{
    QStringList configs, pipelines, plans, measurements, experiments;
    QStringList errors;
};

Sorted sortByKind(const QStringList& paths)
{
    Sorted s;
    for (const QString& path : paths) {
        if (!QFileInfo::exists(path)) {
            s.errors << MainWindow::tr("%1: no such file or folder").arg(path);
            continue;
        }
        switch (kindOf(path)) {
        case Kind::Config:
            s.configs << path;
            break;
        case Kind::Pipeline:
            s.pipelines << path;
            break;
        case Kind::Plan:
            s.plans << path;
            break;
        case Kind::Measurement:
            s.measurements << path;
            break;
        case Kind::Experiment:
            s.experiments << path;
            break;
        case Kind::Folder:
            s.errors << MainWindow::tr("%1: a folder, but not an experiment's (it has no experiment plan)").arg(path);
            break;
        }
    }
    return s;
}

} // namespace

QStringList MainWindow::openPaths(const QStringList& paths, Measurements to)
{
    Sorted sorted = sortByKind(paths);
    QStringList& errors = sorted.errors;
    const QStringList& measurements = sorted.measurements;
    // The page to show: that of the first path that opened.
    qsizetype firstOpened = paths.size();
    QWidget* page = nullptr;
    const auto opened = [&](const QString& path, QWidget* where) {
        qCDebug(lcConfig).noquote() << "opened" << path << "on the"
                                    << m_pages->tabText(m_pages->indexOf(where)).remove(u'&') << "page";
        const qsizetype at = paths.indexOf(path);
        if (at < firstOpened) {
            firstOpened = at;
            page = where;
        }
    };
    const auto fail = [&](const QString& path, const QString& error) {
        if (!error.isEmpty()) // empty: the user cancelled
            errors << QFileInfo(path).fileName() + u": "_s + error;
    };
    QString error;
    // Every bridge config opens on the Map page, a tab each (a lab has two ends); the Links page
    // lists them all, and watches those the user checks there.
    QString firstConfig;
    for (const QString& path : std::as_const(sorted.configs)) {
        if (m_files->openFile(path, &error)) {
            opened(path, m_map);
            if (firstConfig.isEmpty())
                firstConfig = QFileInfo(path).absoluteFilePath();
        } else {
            fail(path, error);
        }
    }
    for (int i = 0; i < m_files->openCount(); ++i) // the first given is the one shown
        if (!firstConfig.isEmpty() && m_files->pathOf(i) == firstConfig)
            m_files->activate(i);
    for (const QString& path : std::as_const(sorted.pipelines)) { // the last one stays
        if (const Status loaded = m_measurePage->loadPipeline(path)) {
            m_recent->add(path);
            opened(path, m_measurePage);
        } else {
            fail(path, loaded.error().toString());
        }
    }
    // One measurement is shown on the Measure page; several are compared on the Reports page.
    if (measurements.size() == 1 && to == Measurements::Show) {
        if (const Status run = m_measurePage->runBar()->openRun(measurements.first())) {
            m_recent->add(measurements.first());
            opened(measurements.first(), m_measurePage);
        } else {
            fail(measurements.first(), run.error().toString());
        }
    } else if (!measurements.isEmpty()) {
        m_reports->addInputs(measurements); // it checks each and lists what does not read
        for (const QString& path : measurements) {
            m_recent->add(path);
            opened(path, m_reports);
        }
    }
    for (const QString& path : std::as_const(sorted.plans)) { // the last one stays
        if (const Status plan = m_experiments->openPlan(path)) {
            m_recent->add(path);
            opened(path, m_experiments);
        } else {
            fail(path, plan.error().toString());
        }
    }
    for (const QString& path : std::as_const(sorted.experiments)) {
        if (const Status folder = m_experiments->openFolder(path)) {
            m_recent->add(path);
            opened(path, m_experiments);
        } else {
            fail(path, folder.error().toString());
        }
    }
    if (page)
        m_pages->setCurrentWidget(page);
    return errors;
}

QStringList MainWindow::openAndReport(const QStringList& paths, Measurements measurements)
{
    const QStringList errors = openPaths(paths, measurements);
    if (errors.isEmpty())
        return errors;
    statusBar()->showMessage(errors.first(), 10000);
    // Not modal to the program: a drop's source is not kept waiting, and nothing else is blocked.
    auto* box = new QMessageBox(QMessageBox::Warning, tr("Open"),
                                tr("Could not open %n file(s).", nullptr, int(errors.size())),
                                QMessageBox::Ok, this);
    box->setObjectName(u"openErrors"_s);
    box->setInformativeText(errors.join(u'\n'));
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();
    return errors;
}

void MainWindow::chooseFiles()
{
    const QStringList paths
        = QFileDialog::getOpenFileNames(this, tr("Open"), QString(),
                                        tr("Bridgescope files (*.yaml *.yml *.bsrun *.csv *.bag);;Bridge "
                                           "configs and pipelines (*.yaml *.yml);;"
                                           "Runs, suite CSV and bags (*.bsrun *.csv *.bag);;All files (*)"));
    if (!paths.isEmpty())
        openAndReport(paths);
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event)
{
    if (!droppedFiles(event->mimeData()).isEmpty())
        event->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* event)
{
    const QStringList files = droppedFiles(event->mimeData());
    if (files.isEmpty())
        return;
    event->acceptProposedAction();
    // After the drop has ended: opening may ask (unsaved changes) or show progress.
    QMetaObject::invokeMethod(
        this, [this, files] { openAndReport(files); }, Qt::QueuedConnection);
}
