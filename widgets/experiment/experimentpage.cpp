// SPDX-License-Identifier: MIT
#include "experimentpage.h"

#include "files/atomicfile.h"
#include "experiment/experimentevent.h"
#include "experiment/experimentprocess.h"
#include "experiment/experimentreportjob.h"
#include "latency/latencyseriesset.h"
#include "widgets/common/columnfitter.h"
#include "widgets/common/ecdfchart.h"

#include <QCheckBox>
#include <QComboBox>
#include <QCoreApplication>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFontDatabase>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QPointer>
#include <QProgressBar>
#include <QPushButton>
#include <QScrollBar>
#include <QShortcut>
#include <QSplitter>
#include <QTableWidget>
#include <QTabWidget>
#include <QTextBrowser>
#include <QTimer>
#include <QVBoxLayout>

using namespace Qt::StringLiterals;

namespace {
constexpr int kMaxLogLines = 2000;
QColor stateColor(CellStatus::State s)
{
    switch (s) {
    case CellStatus::Pending:
        return {};
    case CellStatus::Running:
        return QColor(0x4e, 0x79, 0xa7, 70); // the palette's blue, light
    case CellStatus::Complete:
        return QColor(0x59, 0xa1, 0x4f, 70);
    case CellStatus::Failed:
        return QColor(0xe1, 0x57, 0x59, 90);
    }
    return {};
}

} // namespace

ExperimentPage::ExperimentPage(QWidget* parent)
    : QWidget(parent)
    , m_editor(new QPlainTextEdit(this))
    , m_planStatus(new QLabel(this))
    , m_folder(new QLineEdit(this))
    , m_examples(new QComboBox(this))
    , m_grid(new QTableWidget(this))
    , m_gridFitter(new ColumnFitter(m_grid))
    , m_views(new QTabWidget(this))
    , m_chart(new EcdfChart(this))
    , m_reportView(new QTextBrowser(this))
    , m_statistic(new QComboBox(this))
    , m_run(new QPushButton(tr("&Run"), this))
    , m_resume(new QPushButton(tr("Res&ume"), this))
    , m_stop(new QPushButton(tr("S&top"), this))
    , m_export(new QPushButton(tr("&Export Report…"), this))
    , m_progress(new QProgressBar(this))
    , m_status(new QLabel(this))
    , m_log(new QPlainTextEdit(this))
    , m_check(new QTimer(this))
    , m_redraw(new QTimer(this))
    , m_process(new ExperimentProcess(this))
    , m_series(std::make_unique<LatencySeriesSet>())
{
    setObjectName(u"experimentPage"_s);
    // Named for tests and tools, which find the page's parts as a user would.
    m_editor->setObjectName(u"planEditor"_s);
    m_planStatus->setObjectName(u"planStatus"_s);
    m_grid->setObjectName(u"cellGrid"_s);
    m_views->setObjectName(u"experimentViews"_s);
    m_chart->setObjectName(u"totalsChart"_s);
    m_reportView->setObjectName(u"reportView"_s);
    m_run->setObjectName(u"runButton"_s);
    m_resume->setObjectName(u"resumeButton"_s);
    m_stop->setObjectName(u"stopButton"_s);
    m_progress->setObjectName(u"experimentProgress"_s);
    m_status->setObjectName(u"experimentStatus"_s);
    m_log->setObjectName(u"experimentLog"_s);
    auto* split = new QSplitter(Qt::Horizontal, this);
    split->addWidget(createPlanPane());
    split->addWidget(createCellsPane());
    split->addWidget(createViewsPane());
    split->setStretchFactor(0, 2);
    split->setStretchFactor(1, 3);
    split->setStretchFactor(2, 4);
    split->setSizes({300, 420, 560}); // the plan is narrow; the cells and the chart need room
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(createRunBar());
    layout->addWidget(split, 1);

    m_check->setSingleShot(true);
    m_check->setInterval(300);
    connect(m_check, &QTimer::timeout, this, &ExperimentPage::checkPlan);
    connect(m_editor, &QPlainTextEdit::textChanged, this, [this] {
        m_planEdited = true;
        m_check->start();
    });
    m_chart->setSource(m_series.get());
    m_redraw->setInterval(250);
    connect(m_redraw, &QTimer::timeout, this, [this] {
        if (m_series->revision() == m_drawn)
            return;
        m_drawn = m_series->revision();
        QStringList ids;
        for (int i = 0; i < int(m_cells.size()); ++i)
            if (m_series->find(seriesName(i)))
                ids << LatencySeriesSet::idOf(seriesName(i));
        m_chart->setSeries(ids);
        m_chart->refresh();
    });
    m_redraw->start();
    connect(m_process, &ExperimentProcess::event, this, &ExperimentPage::handleEvent);
    connect(m_process, &ExperimentProcess::logLine, this, &ExperimentPage::showLogLine);
    connect(m_process, &ExperimentProcess::finished, this, &ExperimentPage::processFinished);
    connect(m_process, &ExperimentProcess::failedToStart, this, [this](const QString& why) {
        m_status->setText(tr("The experiment did not start: %1").arg(why));
        updateButtons();
    });
    m_status->setText(tr("Open a plan or an example, choose a folder, and run it."));
    updateButtons();
}

ExperimentPage::~ExperimentPage()
{
    // The child and the report's worker are children: each waits for its end, briefly.
    if (m_reportJob)
        m_reportJob->disconnect(this);
    m_process->disconnect(this);
}

/// The run controls: the folder, run, resume, stop, progress.
QLayout* ExperimentPage::createRunBar()
{
    auto* bar = new QHBoxLayout;
    auto* folderLabel = new QLabel(tr("&Folder:"), this);
    folderLabel->setBuddy(m_folder);
    m_folder->setPlaceholderText(tr("where the runs go (a new folder, or one to resume)"));
    m_folder->setClearButtonEnabled(true);
    connect(m_folder, &QLineEdit::editingFinished, this, &ExperimentPage::loadState);
    auto* browse = new QPushButton(tr("&Browse…"), this);
    connect(browse, &QPushButton::clicked, this, &ExperimentPage::chooseFolder);
    m_run->setToolTip(tr("Run every cell of the plan into a new folder (Ctrl+R)"));
    m_run->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_R));
    m_resume->setToolTip(tr("Go on with the folder: skip the complete cells, redo the others"));
    m_stop->setToolTip(tr("Stop after cleaning up; Resume goes on"));
    const auto start = [this](bool resume) {
        if (const Status started = run(resume); !started)
            QMessageBox::warning(this, tr("Experiment"), started.error().toString());
    };
    connect(m_run, &QPushButton::clicked, this, [start] { start(false); });
    connect(m_resume, &QPushButton::clicked, this, [start] { start(true); });
    connect(m_stop, &QPushButton::clicked, this, &ExperimentPage::stop);
    m_progress->setRange(0, 1);
    m_progress->setValue(0);
    m_progress->setMaximumWidth(220);
    bar->addWidget(folderLabel);
    bar->addWidget(m_folder, 1);
    bar->addWidget(browse);
    bar->addWidget(m_run);
    bar->addWidget(m_resume);
    bar->addWidget(m_stop);
    bar->addWidget(m_progress);
    return bar;
}

/// The plan: open, examples, the editor and what its text makes.
QWidget* ExperimentPage::createPlanPane()
{
    auto* pane = new QWidget(this);
    auto* layout = new QVBoxLayout(pane);
    layout->setContentsMargins(0, 0, 0, 0);
    auto* buttons = new QHBoxLayout;
    auto* open = new QPushButton(tr("&Open Plan…"), pane);
    connect(open, &QPushButton::clicked, this, &ExperimentPage::choosePlan);
    auto* save = new QPushButton(tr("Save Plan &As…"), pane);
    connect(save, &QPushButton::clicked, this, &ExperimentPage::savePlanAs);
    auto* openFolderButton = new QPushButton(tr("Open F&older…"), pane);
    openFolderButton->setToolTip(tr("An experiment's folder: its plan, cells and report"));
    connect(openFolderButton, &QPushButton::clicked, this, [this] {
        const QString dir = QFileDialog::getExistingDirectory(this, tr("Open Experiment"), folder());
        if (dir.isEmpty())
            return;
        if (const Status opened = openFolder(dir); !opened)
            QMessageBox::warning(this, tr("Open Experiment"), opened.error().toString());
    });
    m_examples->addItem(tr("Examples…"));
    const QDir examples(u":/examples"_s);
    for (const QString& name : examples.entryList({u"experiment-*.yaml"_s}, QDir::Files, QDir::Name))
        m_examples->addItem(name, examples.filePath(name));
    m_examples->setEnabled(m_examples->count() > 1);
    m_examples->setToolTip(tr("The plans that reproduce the shapes of the paper's Tables I-V"));
    connect(m_examples, &QComboBox::activated, this, &ExperimentPage::loadExample);
    buttons->addWidget(open);
    buttons->addWidget(save);
    buttons->addWidget(openFolderButton);
    buttons->addStretch(1);
    m_editor->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    m_editor->setLineWrapMode(QPlainTextEdit::NoWrap);
    m_editor->setPlaceholderText(tr("name: QoS study\nsamples: 600\nfactors:\n  qos: [0, 1, 2]"));
    m_editor->setAccessibleName(tr("Experiment plan"));
    m_planStatus->setTextFormat(Qt::PlainText); // a plan's name or error is no markup
    m_planStatus->setWordWrap(true);
    m_planStatus->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addLayout(buttons);
    layout->addWidget(m_examples);
    layout->addWidget(m_editor, 1);
    layout->addWidget(m_planStatus);
    return pane;
}

/// The cells: one row each, coloured by state; a finished one opens on the Measure page.
QWidget* ExperimentPage::createCellsPane()
{
    auto* split = new QSplitter(Qt::Vertical, this);
    m_grid->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_grid->setSelectionMode(QAbstractItemView::SingleSelection);
    m_grid->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_grid->verticalHeader()->setVisible(false);
    m_grid->horizontalHeader()->setStretchLastSection(true);
    m_grid->setAccessibleName(tr("Cells"));
    m_grid->setToolTip(tr("Double-click or Enter: open a finished cell's run on the Measure page"));
    connect(m_grid, &QTableWidget::cellActivated, this, [this](int row, int) { openCell(row); });
    m_log->setReadOnly(true);
    m_log->setMaximumBlockCount(kMaxLogLines);
    m_log->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    m_log->setAccessibleName(tr("Experiment log"));
    m_status->setTextFormat(Qt::PlainText); // the child's lines and the cells' labels are no markup
    m_status->setWordWrap(true);
    auto* top = new QWidget(split);
    auto* layout = new QVBoxLayout(top);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_grid, 1);
    layout->addWidget(m_status);
    split->addWidget(top);
    split->addWidget(m_log);
    split->setStretchFactor(0, 3);
    split->setStretchFactor(1, 1);
    return split;
}

/// The live ECDF and the report.
QWidget* ExperimentPage::createViewsPane()
{
    auto* report = new QWidget(this);
    auto* layout = new QVBoxLayout(report);
    layout->setContentsMargins(0, 0, 0, 0);
    auto* row = new QHBoxLayout;
    auto* statisticLabel = new QLabel(tr("S&tatistic:"), report);
    statisticLabel->setBuddy(m_statistic);
    for (const auto s : {ExperimentReport::Statistic::Mean, ExperimentReport::Statistic::Median,
                         ExperimentReport::Statistic::Std, ExperimentReport::Statistic::P99})
        m_statistic->addItem(ExperimentReport::statisticName(s), int(s));
    connect(m_statistic, &QComboBox::currentIndexChanged, this, &ExperimentPage::showReport);
    auto* refresh = new QPushButton(tr("Re&fresh"), report);
    connect(refresh, &QPushButton::clicked, this, &ExperimentPage::refreshReport);
    connect(m_export, &QPushButton::clicked, this, &ExperimentPage::chooseExport);
    row->addWidget(statisticLabel);
    row->addWidget(m_statistic);
    row->addStretch(1);
    row->addWidget(refresh);
    row->addWidget(m_export);
    layout->addLayout(row);
    layout->addWidget(m_reportView, 1);
    m_views->addTab(m_chart, tr("Totals (ECDF)"));
    m_views->addTab(report, tr("Report"));
    return m_views;
}

void ExperimentPage::setPlanText(const QString& text)
{
    m_editor->setPlainText(text);
    m_planEdited = false;
    checkPlan();
}

QString ExperimentPage::planText() const
{
    return m_editor->toPlainText();
}

void ExperimentPage::setPlanPath(const QString& path)
{
    m_planPath = path;
    m_planEdited = false;
    checkPlan();
}

void ExperimentPage::setFolder(const QString& directory)
{
    m_folder->setText(QDir::toNativeSeparators(directory));
    loadState();
}

QString ExperimentPage::folder() const
{
    return QDir::fromNativeSeparators(m_folder->text().trimmed());
}

/// Parses the editor's text: the cells it makes, or the error with its line.
void ExperimentPage::checkPlan()
{
    m_check->stop();
    if (isRunning())
        return; // the grid is the running experiment's
    const QString base = m_planPath.isEmpty() ? QDir::currentPath() : QFileInfo(m_planPath).path();
    Result<ExperimentPlan> plan = ExperimentPlan::read(planText().toUtf8(), base);
    m_plan = plan ? std::optional<ExperimentPlan>(std::move(plan).value()) : std::nullopt;
    if (!m_plan) {
        m_planStatus->setText(
            planText().trimmed().isEmpty() ? QString() : tr("Not a plan: %1").arg(plan.error().toString()));
        m_planStatus->setStyleSheet(u"color: #c0392b;"_s);
        updateButtons();
        return;
    }
    if (m_plan->name.isEmpty())
        m_plan->name = m_planPath.isEmpty() ? tr("experiment") : QFileInfo(m_planPath).completeBaseName();
    double seconds = 0;
    for (const ExperimentCell& c : std::as_const(m_plan->cells))
        seconds += m_plan->expectedSeconds(c);
    m_planStatus->setStyleSheet(QString());
    m_planStatus->setText(tr("%1: %n cell(s) of %2 samples, about %3", nullptr, int(m_plan->cells.size()))
                              .arg(m_plan->name)
                              .arg(m_plan->samples)
                              .arg(ExperimentPlan::durationText(seconds)));
    // Typing that leaves the cells as they were (a comment, the samples) keeps the grid, its
    // states and curves; the folder is read again only for other cells.
    QStringList ids;
    for (const ExperimentCell& c : std::as_const(m_plan->cells))
        ids << c.id();
    const bool same = ids == m_cellIds && m_plan->factors == m_gridFactors;
    m_cells = m_plan->cells;
    if (same)
        return;
    m_cellIds = ids;
    m_gridFactors = m_plan->factors;
    m_statuses = QList<CellStatus>(m_cells.size());
    m_series = std::make_unique<LatencySeriesSet>();
    m_chart->setSource(m_series.get());
    m_chart->setSeries({});
    m_drawn = ~quint64(0);
    rebuildGrid();
    loadState();
}

/// The state of the folder's cells, when the folder holds this plan's experiment.
void ExperimentPage::loadState()
{
    if (isRunning() || !m_plan)
        return;
    const QString dir = folder();
    if (!ExperimentReport::isExperiment(dir)) {
        for (int i = 0; i < int(m_statuses.size()); ++i) {
            m_statuses[i] = CellStatus();
            updateRow(i);
        }
        m_report.reset();
        m_reportFolder.clear();
        m_reportView->setPlainText(tr("No report yet: the folder holds no experiment."));
        updateButtons();
        return;
    }
    if (const Result<QList<CellStatus>> state = ExperimentFolder(dir).readState(*m_plan)) {
        m_statuses = *state;
        for (int i = 0; i < int(m_statuses.size()); ++i)
            updateRow(i);
        m_grid->resizeColumnsToContents();
        showCounts();
    } else {
        m_status->setText(state.error().toString());
    }
    updateButtons();
    if (dir != m_reportFolder) // a run's end and Refresh read it again
        refreshReport();
}

void ExperimentPage::rebuildGrid()
{
    // The levels first (what tells the cells apart), then where each stands, its id last.
    const QStringList factors = m_plan ? m_plan->factors : QStringList();
    QStringList headers = factors;
    headers << tr("State") << tr("Samples") << tr("Total median") << tr("Total p99") << tr("Cell");
    m_grid->clear();
    m_grid->setColumnCount(int(headers.size()));
    m_grid->setHorizontalHeaderLabels(headers);
    const int first = int(factors.size());
    m_gridFitter->figures({first, first + 1, first + 2, first + 3}); // state, samples, median, p99
    m_grid->setRowCount(int(m_cells.size()));
    for (int i = 0; i < int(m_cells.size()); ++i) {
        const ExperimentCell& c = m_cells[i];
        for (int f = 0; f < int(factors.size()); ++f) {
            QString level;
            for (const auto& [factor, value] : c.levels)
                if (factor == factors[f])
                    level = value;
            m_grid->setItem(i, f, new QTableWidgetItem(level));
        }
        for (int col = int(factors.size()); col < m_grid->columnCount() - 1; ++col)
            m_grid->setItem(i, col, new QTableWidgetItem);
        m_grid->setItem(i, m_grid->columnCount() - 1, new QTableWidgetItem(c.id()));
        updateRow(i);
    }
    m_grid->resizeColumnsToContents();
}

void ExperimentPage::updateRow(int row)
{
    if (row < 0 || row >= m_grid->rowCount() || row >= m_statuses.size())
        return;
    const CellStatus& s = m_statuses[row];
    const int first = stateColumn();
    const LatencySeries* totals = m_series->find(seriesName(row));
    const auto ms = [](double v) { return std::isfinite(v) ? QString::number(v, 'f', 1) : QString(); };
    const LatencyStats stats = totals ? totals->stats() : LatencyStats();
    const QStringList texts {CellStatus::stateName(s.state),
                             s.samples > 0 ? QString::number(s.samples) : QString(),
                             totals ? ms(stats.median) : QString(), totals ? ms(stats.p99) : QString()};
    for (int col = 0; col < m_grid->columnCount(); ++col) {
        QTableWidgetItem* item = m_grid->item(row, col);
        if (!item)
            continue;
        if (col >= first && col < first + texts.size()) {
            item->setText(texts[col - first]);
            if (col > first)
                item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
        }
        // A cell not run yet keeps the view's own background (an invalid colour would paint black).
        if (const QColor colour = stateColor(s.state); colour.isValid())
            item->setBackground(colour);
        else
            item->setData(Qt::BackgroundRole, QVariant());
        QString tip = m_cells[row].label() + u"\n"_s + CellStatus::stateName(s.state);
        if (!s.reason.isEmpty())
            tip += u": "_s + s.reason;
        if (s.state == CellStatus::Complete)
            tip += u"\n"_s + tr("Double-click to open %1 on the Measure page").arg(s.run);
        item->setToolTip(tip);
    }
}

/// How many cells are done (the progress bar) and, when none runs, what that means.
void ExperimentPage::showCounts()
{
    int complete = 0;
    int failed = 0;
    for (const CellStatus& c : std::as_const(m_statuses)) {
        complete += c.state == CellStatus::Complete;
        failed += c.state == CellStatus::Failed;
    }
    m_progress->setRange(0, std::max(1, int(m_statuses.size())));
    m_progress->setValue(complete + failed);
    if (!isRunning())
        m_status->setText(
            tr("%1 of %2 cells complete, %3 failed.").arg(complete).arg(m_statuses.size()).arg(failed));
}

int ExperimentPage::stateColumn() const
{
    return m_plan ? int(m_plan->factors.size()) : 0;
}

void ExperimentPage::updateButtons()
{
    const bool running = isRunning();
    const bool plan = m_plan.has_value();
    const bool existing = ExperimentReport::isExperiment(folder());
    m_run->setEnabled(!running && plan);
    m_resume->setEnabled(!running && plan && existing);
    m_stop->setEnabled(running);
    m_editor->setReadOnly(running);
    m_folder->setReadOnly(running);
    m_export->setEnabled(m_report.has_value());
}

bool ExperimentPage::isRunning() const
{
    return m_process->isRunning();
}

Status ExperimentPage::run(bool resume)
{
    if (isRunning())
        return LocatedError {tr("An experiment is running already.")};
    checkPlan();
    if (!m_plan)
        return LocatedError {m_planStatus->text()};
    const QString dir = folder();
    if (dir.isEmpty())
        return LocatedError {tr("Choose the folder the experiment's runs go to.")};
    if (!resume && ExperimentReport::isExperiment(dir))
        return LocatedError {
            tr("%1 holds an experiment already: Resume goes on with it, or choose another folder.")
                .arg(QDir::toNativeSeparators(dir))};
    // The child runs the plan's file: an edited or untitled plan is saved first.
    if (m_planPath.isEmpty() || m_planEdited) {
        if (m_planPath.isEmpty() || m_planPath.startsWith(u':')) {
            if (!QDir().mkpath(dir))
                return LocatedError {tr("Cannot make the folder %1.").arg(QDir::toNativeSeparators(dir))};
            m_planPath = QDir(dir).absoluteFilePath(ExperimentFolder::planFileName()); // the copy it keeps
        }
        if (Status written = AtomicFile::write(m_planPath, planText().toUtf8()); !written)
            return written;
        m_planEdited = false;
    }
    if (!resume) {
        m_statuses = QList<CellStatus>(m_cells.size());
        m_series = std::make_unique<LatencySeriesSet>();
        m_chart->setSource(m_series.get());
        m_chart->setSeries({});
        m_drawn = ~quint64(0);
        for (int i = 0; i < int(m_cells.size()); ++i)
            updateRow(i);
    }
    m_process->start(m_program.isEmpty() ? QCoreApplication::applicationFilePath() : m_program, m_planPath,
                     dir, resume);
    m_log->appendPlainText(u"$ bridgescope "_s + m_process->arguments().join(u' '));
    showCounts();
    m_status->setText(tr("Starting…"));
    m_views->setCurrentWidget(m_chart);
    updateButtons();
    return {};
}

void ExperimentPage::stop()
{
    if (!isRunning())
        return;
    m_status->setText(tr("Stopping after cleaning up…"));
    m_process->stop(); // SIGTERM: the command stops as on Ctrl+C
}

void ExperimentPage::showLogLine(const QString& line)
{
    m_log->appendPlainText(line);
    m_status->setText(line.left(300));
}

/// An event of `bridgescope experiment`: a cell started or finished, progress with totals
/// (read and bounded by ExperimentEvent).
void ExperimentPage::handleEvent(const ExperimentEvent& event)
{
    const ExperimentEvent* e = &event;
    if (e->kind == ExperimentEvent::Kind::Throughput) {
        m_log->appendPlainText(tr("throughput: %1 Hz, %2 of %3 samples%4")
                                   .arg(e->rateHz)
                                   .arg(e->throughputSamples)
                                   .arg(e->expected)
                                   .arg(e->sustainable ? QString() : tr(", not sustained")));
        return;
    }
    const int i = e->index;
    if (i >= m_statuses.size() || (!e->cell.isEmpty() && e->cell != m_cells[i].id()))
        return; // not a cell of this plan
    CellStatus& s = m_statuses[i];
    switch (e->kind) {
    case ExperimentEvent::Kind::Started:
        s = CellStatus();
        s.state = CellStatus::Running;
        m_series->clear(seriesName(i)); // a cell done again starts afresh
        m_grid->selectRow(i);
        break;
    case ExperimentEvent::Kind::Progress:
        s.samples = e->samples;
        for (double ms : e->totalMs)
            m_series->add(seriesName(i), qint64(ms * 1e6));
        m_status->setText(e->warmingUp ? tr("Cell %1 of %2: %3, warming up; about %4 left")
                                             .arg(i + 1)
                                             .arg(m_cells.size())
                                             .arg(m_cells[i].label(), ExperimentPlan::durationText(e->remainingS))
                                       : tr("Cell %1 of %2: %3, %4 of %5 samples; about %6 left")
                                             .arg(i + 1)
                                             .arg(m_cells.size())
                                             .arg(m_cells[i].label())
                                             .arg(s.samples)
                                             .arg(e->of)
                                             .arg(ExperimentPlan::durationText(e->remainingS)));
        break;
    case ExperimentEvent::Kind::Finished:
        s.state = e->complete() ? CellStatus::Complete : CellStatus::Failed;
        s.samples = e->samples;
        s.run = ExperimentFolder::runPathOf(m_cells[i]); // where the runner puts it, whatever the line says
        s.reason = e->reason;
        showCounts();
        break;
    case ExperimentEvent::Kind::Throughput:
        return;
    }
    updateRow(i);
    if (e->kind != ExperimentEvent::Kind::Progress)
        m_grid->resizeColumnsToContents();
}

void ExperimentPage::processFinished(ExperimentExit status, int exitCode)
{
    for (int i = 0; i < int(m_statuses.size()); ++i)
        if (m_statuses[i].state == CellStatus::Running) { // stopped: the folder's state says pending
            m_statuses[i].state = CellStatus::Pending;
            updateRow(i);
        }
    switch (status) {
    case ExperimentExit::Crashed:
        m_status->setText(tr("The experiment crashed; Resume goes on with it."));
        break;
    case ExperimentExit::Complete:
        m_status->setText(tr("Every cell complete."));
        break;
    case ExperimentExit::Stopped:
        m_status->setText(tr("Stopped; Resume goes on."));
        break;
    case ExperimentExit::CellFailed:
        m_status->setText(tr("Done, but a cell failed: see its tooltip and the log."));
        break;
    case ExperimentExit::Usage:
        break; // the command's own message is the last line shown
    }
    if (const qint64 refused = m_process->refusedLines())
        m_log->appendPlainText(
            tr("%n line(s) of the experiment's output were no event and were left out.", nullptr, int(refused)));
    m_log->appendPlainText(tr("exit status %1").arg(exitCode));
    updateButtons();
    refreshReport();
    emit experimentFinished(exitCode);
}

/// Loads the folder's report on a worker thread; the grid's figures and the ECDF of the cells
/// that have no live totals come from it too.
void ExperimentPage::refreshReport()
{
    const QString dir = folder();
    if (!ExperimentReport::isExperiment(dir))
        return;
    if (m_reportJob) {
        m_reportAgain = true;
        return;
    }
    m_reportFolder = dir;
    m_reportJob = new ExperimentReportJob(dir, this);
    connect(m_reportJob, &ExperimentReportJob::finished, this,
            [this](std::shared_ptr<const ExperimentReport> report, const QString& error) {
                m_reportJob->deleteLater();
                m_reportJob = nullptr;
                m_report = report ? std::optional<ExperimentReport>(*report) : std::nullopt;
                m_reportError = error;
                takeReport();
                if (std::exchange(m_reportAgain, false))
                    refreshReport();
            });
    m_reportJob->start();
}

/// The grid's figures and the ECDF of the cells that have no live totals, from the report.
void ExperimentPage::takeReport()
{
    if (m_report && m_plan && m_report->cells().size() == m_cells.size()) {
        for (int i = 0; i < int(m_cells.size()); ++i) {
            const ExperimentReport::Cell& c = m_report->cells()[i];
            if (!isRunning())
                m_statuses[i] = c.status;
            if (c.total && !m_series->find(seriesName(i)))
                for (qint64 v : c.total->values())
                    m_series->add(seriesName(i), v);
            updateRow(i);
        }
    }
    showReport();
    updateButtons();
    emit reportUpdated();
}

void ExperimentPage::showReport()
{
    if (!m_report) {
        m_reportView->setPlainText(m_reportError.isEmpty() ? tr("No report yet.") : m_reportError);
        return;
    }
    const auto statistic = ExperimentReport::Statistic(m_statistic->currentData().toInt());
    const int top = m_reportView->verticalScrollBar() ? m_reportView->verticalScrollBar()->value() : 0;
    m_reportView->setHtml(m_report->toHtml({statistic}, false));
    m_reportView->verticalScrollBar()->setValue(top);
}

void ExperimentPage::openCell(int row)
{
    if (row < 0 || row >= m_statuses.size())
        return;
    const CellStatus& s = m_statuses[row];
    if (s.state != CellStatus::Complete) {
        m_status->setText(tr("Cell %1 is %2: only a complete cell has a run to open.")
                              .arg(m_cells[row].id(), CellStatus::stateName(s.state)));
        return;
    }
    emit openRunRequested(QDir(folder()).filePath(s.run));
}

QString ExperimentPage::seriesName(int cell) const
{
    if (cell < 0 || cell >= m_cells.size())
        return {};
    // Short, for the chart's legend: the levels, with the factor's name only where a level is a
    // bare number ("qos 1, 25%", not "qos 1, payload 25%"); the grid's headers name the factors.
    const ExperimentCell& c = m_cells[cell];
    QStringList parts;
    for (const auto& [factor, level] : c.levels) {
        bool number = false;
        level.toDouble(&number);
        parts << (number ? factor + u' ' + level : level);
    }
    const QString name = parts.isEmpty() ? c.id() : parts.join(u", "_s);
    return c.repetition > 0 ? tr("%1 (#%2)").arg(name).arg(c.repetition + 1) : name;
}
