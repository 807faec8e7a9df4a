// SPDX-License-Identifier: MIT
#include "measurepage.h"

#include "latency/seriesid.h"
#include "models/latencystatsmodel.h"
#include "session/measuresession.h"
#include "widgets/common/columnfitter.h"
#include "widgets/common/ecdfchart.h"
#include "widgets/common/livetext.h"
#include "widgets/common/namedelegate.h"
#include "widgets/common/timelinechart.h"
#include "widgets/common/viewsetup.h"
#include "widgets/measure/pipelinemodel.h"
#include "widgets/measure/runbar.h"
#include "widgets/measure/stamptopicmodel.h"

#include <algorithm>
#include <climits>
#include <QAction>
#include <QCheckBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QIdentityProxyModel>
#include <QLabel>
#include <QListView>
#include <QMenu>
#include <QMessageBox>
#include <QPushButton>
#include <QSortFilterProxyModel>
#include <QSpinBox>
#include <QSplitter>
#include <QTableView>
#include <QToolButton>
#include <QVBoxLayout>

using namespace Qt::StringLiterals;

namespace {
/// Table I's emphasis: the total in bold, crossings and derived figures in italics.
class StatsStyleProxy : public QIdentityProxyModel
{
public:
    using QIdentityProxyModel::QIdentityProxyModel;
    QVariant data(const QModelIndex& index, int role) const override
    {
        if (index.column() != LatencyStatsModel::SeriesColumn)
            return QIdentityProxyModel::data(index, role);
        if (role == Qt::DecorationRole) // a plotted series shows its colour
            return index.data(Qt::CheckStateRole).value<Qt::CheckState>() == Qt::Checked
                ? QVariant(EcdfChart::colorFor(index.row()))
                : QVariant();
        if (role != Qt::FontRole)
            return QIdentityProxyModel::data(index, role);
        const auto kind = LatencyEngine::Kind(index.data(LatencyStatsModel::KindRole).toInt());
        QFont f;
        if (kind == LatencyEngine::Kind::Total)
            f.setBold(true);
        else if (kind != LatencyEngine::Kind::Stage || index.data(LatencyStatsModel::CrossingRole).toBool())
            f.setItalic(true);
        return f;
    }
};

/// Rows pinned above the charts: the total and what is derived from it, not the stages.
bool isPinned(const QModelIndex& index)
{
    const auto kind = LatencyEngine::Kind(index.data(LatencyStatsModel::KindRole).toInt());
    return kind != LatencyEngine::Kind::Stage && kind != LatencyEngine::Kind::External;
}

/// The pinned rows of Table I.
class PinnedRowsProxy : public QSortFilterProxyModel
{
public:
    using QSortFilterProxyModel::QSortFilterProxyModel;

protected:
    bool filterAcceptsRow(int row, const QModelIndex& parent) const override
    {
        return isPinned(sourceModel()->index(row, 0, parent));
    }
};
} // namespace

MeasurePage::MeasurePage(MeasureSession* measure, QWidget* parent)
    : QWidget(parent)
    , m_measure(measure)
    , m_pipeline(new PipelineModel(this))
    , m_seen(new StampTopicModel(this))
    , m_chart(new EcdfChart(this))
    , m_statsView(new QTableView(this))
    , m_summaryView(new QTableView(this))
    , m_timeline(new TimelineChart(this))
    , m_pipelineView(new QTableView(this))
    , m_seenView(new QListView(this))
    , m_window(new QSpinBox(this))
    , m_log(new QCheckBox(tr("&Log scale"), this))
    , m_multiples(new QCheckBox(tr("Small &multiples"), this))
    , m_pause(new QAction(tr("&Pause"), this))
    , m_reset(new QAction(tr("&Reset"), this))
    , m_mode(new QLabel(this))
    , m_warning(new QLabel(this))
    , m_clocks(new LiveText(this))
    , m_counts(new LiveText(this))
    , m_runBar(new RunBar(measure, this))
{
    setObjectName(u"measurePage"_s);
    m_pipeline->setObjectName(u"pipelineModel"_s);
    m_window->setObjectName(u"windowBox"_s);
    m_log->setObjectName(u"logScaleBox"_s);
    m_multiples->setObjectName(u"smallMultiplesBox"_s);
    m_mode->setObjectName(u"modeLabel"_s);
    QLayout* controls = createControls();
    QWidget* pipelinePane = createPipelinePane();
    QWidget* chartPane = createChartPane();
    layOut(controls, pipelinePane, chartPane);
    m_measure->setPublishInterval(kRefreshMs);
    connectSession();
    onPipelineChanged();
    updateCounts();
    updateEditable();
}

QLayout* MeasurePage::createControls()
{
    auto* load = new QPushButton(tr("L&oad Pipeline…"), this);
    auto* save = new QPushButton(tr("&Save Pipeline…"), this);
    auto* automatic = new QPushButton(tr("&Automatic"), this);
    automatic->setToolTip(tr("Find the pipeline in the stamps that arrive: every stamp topic, ordered by its "
                             "mean time within the samples, hosts guessed from the names"));
    m_pipelineControls = {load, save, automatic};
    connect(load, &QPushButton::clicked, this, &MeasurePage::choosePipelineFile);
    connect(save, &QPushButton::clicked, this, &MeasurePage::chooseSaveFile);
    connect(automatic, &QPushButton::clicked, this, [this] {
        m_pipelineFile.clear();
        m_measure->setAutomatic();
        onPipelineChanged();
    });

    auto* windowLabel = new QLabel(tr("&Window:"), this);
    windowLabel->setBuddy(m_window);
    setUpWindowAndActions();
    auto* pauseButton = new QToolButton(this);
    pauseButton->setDefaultAction(m_pause);
    auto* resetButton = new QToolButton(this);
    resetButton->setDefaultAction(m_reset);
    auto* saveChart = new QPushButton(tr("E&xport Chart…"), this);
    saveChart->setToolTip(tr("Save the chart as PNG or SVG"));
    auto* copyChart = new QPushButton(tr("Cop&y Chart"), this);
    copyChart->setToolTip(tr("Copy the chart to the clipboard as an image"));
    connect(saveChart, &QPushButton::clicked, this, &MeasurePage::chooseChartFile);
    connect(copyChart, &QPushButton::clicked, m_chart, &EcdfChart::copyToClipboard);
    connect(m_log, &QCheckBox::toggled, m_chart, &EcdfChart::setLogScale);
    connect(m_multiples, &QCheckBox::toggled, m_chart, &EcdfChart::setSmallMultiples);

    auto* controls = new QHBoxLayout;
    for (QWidget* w : {load, save, automatic})
        controls->addWidget(w);
    controls->addSpacing(16);
    for (QWidget* w : std::initializer_list<QWidget*> {windowLabel, m_window, pauseButton, resetButton})
        controls->addWidget(w);
    controls->addSpacing(16);
    for (QWidget* w : std::initializer_list<QWidget*> {m_log, m_multiples, saveChart, copyChart})
        controls->addWidget(w);
    controls->addStretch();
    return controls;
}

void MeasurePage::setUpWindowAndActions()
{
    m_window->setRange(0, 100'000'000);
    m_window->setSpecialValueText(tr("whole run"));
    m_window->setSuffix(tr(" samples"));
    m_window->setValue(int(m_measure->engine().window()));
    m_window->setToolTip(
        tr("Statistics and ECDFs over the last N complete samples (the paper: 600), or 0 for the "
           "whole run"));
    m_pause->setObjectName(u"pauseAction"_s);
    m_pause->setCheckable(true);
    m_pause->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_P));
    m_pause->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    m_pause->setToolTip(tr("Freeze the chart and the table; measuring goes on (Ctrl+P)"));
    m_reset->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_R));
    m_reset->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    m_reset->setToolTip(tr("Forget every sample and count; keep the pipeline (Ctrl+R)"));
    addAction(m_pause);
    addAction(m_reset);
    connect(m_window, &QSpinBox::valueChanged, this, [this](int v) { m_measure->setWindow(v); });
    connect(m_pause, &QAction::toggled, this, [this](bool on) {
        m_measure->setPaused(on);
        updateCounts();
    });
    connect(m_reset, &QAction::triggered, this, [this] { m_measure->reset(); });
}

QWidget* MeasurePage::createPipelinePane()
{
    setUpPipelineView();
    m_seenView->setObjectName(u"stampTopicsView"_s);
    m_seenView->setModel(m_seen);
    m_seenNames = NameDelegate::install(m_seenView, 0);
    m_seenView->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff); // names shorten instead
    m_seenView->setUniformItemSizes(false);
    m_seenView->setDragEnabled(true);
    m_seenView->setSelectionMode(QAbstractItemView::ExtendedSelection);
    m_seenView->setToolTip(tr("Drag a stamp topic into the pipeline, or press Enter to append it"));
    connect(m_seenView, &QListView::activated, this, &MeasurePage::addSeenTopic);

    auto* pane = new QWidget(this);
    auto* layout = new QVBoxLayout(pane);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(
        new QLabel(tr("<b>Pipeline</b>: stamp topics in the order a sample passes them"), pane));
    layout->addWidget(m_mode);
    m_mode->setWordWrap(true);
    layout->addWidget(m_pipelineView, 3);
    auto* seenLabel = new QLabel(tr("Stamp &topics seen:"), pane);
    seenLabel->setBuddy(m_seenView);
    m_seenNames->setCaption(seenLabel); // it says the prefix the names leave out
    layout->addWidget(seenLabel);
    layout->addWidget(m_seenView, 1);
    return pane;
}

void MeasurePage::setUpPipelineView()
{
    m_pipelineView->setObjectName(u"pipelineView"_s);
    m_pipelineView->setModel(m_pipeline);
    m_pipelineView->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_pipelineView->setDragDropMode(QAbstractItemView::DragDrop);
    m_pipelineView->setDefaultDropAction(Qt::MoveAction);
    m_pipelineView->setDragDropOverwriteMode(false);
    m_pipelineView->setDropIndicatorShown(true);
    m_pipelineView->setAcceptDrops(true);
    m_pipelineView->verticalHeader()->hide();
    m_pipelineView->verticalHeader()->setDefaultSectionSize(m_pipelineView->fontMetrics().height() + 8);
    m_pipelineView->setWordWrap(false);
    NameDelegate::install(m_pipelineView, PipelineModel::TopicColumn); // stamp topics differ inside
    m_pipelineView->horizontalHeader()->setSectionResizeMode(PipelineModel::TopicColumn,
                                                             QHeaderView::Stretch);
    (new ColumnFitter(m_pipelineView))->figures({PipelineModel::IndexColumn});
    m_pipelineView->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed
                                    | QAbstractItemView::AnyKeyPressed);
    m_pipeline->setStampCounter([this](const QString& t) { return m_measure->discovery().stampCount(t); });
    connect(m_pipeline, &PipelineModel::edited, this, &MeasurePage::applyEdit);

    const auto addAction = [this](const QString& text, const QKeySequence& key) {
        auto* action = new QAction(text, m_pipelineView);
        action->setShortcut(key);
        action->setShortcutContext(Qt::WidgetShortcut);
        m_pipelineView->addAction(action);
        return action;
    };
    QAction* up = addAction(tr("Move Up"), QKeySequence(Qt::CTRL | Qt::Key_Up));
    QAction* down = addAction(tr("Move Down"), QKeySequence(Qt::CTRL | Qt::Key_Down));
    QAction* remove = addAction(tr("Remove from Pipeline"), QKeySequence::Delete);
    m_pipelineView->setContextMenuPolicy(Qt::ActionsContextMenu);
    connect(remove, &QAction::triggered, this, &MeasurePage::removeSelectedStamps);
    connect(up, &QAction::triggered, this, [this] { moveSelectedStamp(-1); });
    connect(down, &QAction::triggered, this, [this] { moveSelectedStamp(+1); });
}

QWidget* MeasurePage::createChartPane()
{
    auto* style = new StatsStyleProxy(this);
    style->setSourceModel(m_measure->statsModel());
    m_statsView->setObjectName(u"statsView"_s);
    m_statsView->setModel(style);
    ViewSetup::records(m_statsView);
    m_statsView->horizontalHeader()->setSectionResizeMode(LatencyStatsModel::SeriesColumn,
                                                          QHeaderView::Stretch);
    QList<int> figures;
    for (int c = 0; c < LatencyStatsModel::ColumnCount; ++c)
        if (c != LatencyStatsModel::SeriesColumn)
            figures << c;
    (new ColumnFitter(m_statsView))->figures(figures); // measured once a second, not every tick
    m_statsView->verticalHeader()->setDefaultSectionSize(m_statsView->fontMetrics().height() + 8);
    for (int c : {LatencyStatsModel::P90Column, LatencyStatsModel::P95Column, LatencyStatsModel::P999Column})
        m_statsView->setColumnHidden(c, true);
    m_statsView->horizontalHeader()->setContextMenuPolicy(Qt::CustomContextMenu);
    connect(m_statsView->horizontalHeader(), &QWidget::customContextMenuRequested, this,
            &MeasurePage::showColumnMenu);
    m_chart->setSource(&m_measure->engine().pipelineSeries());
    m_chart->setSeries(m_measure->statsModel()->checkedSeries());
    m_chart->setMinimumHeight(240);
    m_timeline->setTimeline(&m_measure->engine().timeline());
    m_timeline->setMinimumWidth(220);
    setUpSummaryView(style);

    auto* charts = new QSplitter(Qt::Horizontal, this);
    charts->addWidget(m_chart);
    charts->addWidget(m_timeline);
    charts->setStretchFactor(0, 3);
    charts->setStretchFactor(1, 2);
    auto* split = new QSplitter(Qt::Vertical, this);
    split->addWidget(charts);
    split->addWidget(m_statsView);
    split->setStretchFactor(0, 3);
    split->setStretchFactor(1, 2);
    split->setSizes({470, 330});
    // The total and the derived rows above the charts: seen whatever the splitters and the
    // stage table's scroll position.
    auto* pane = new QWidget(this);
    auto* layout = new QVBoxLayout(pane);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(2);
    // A figure that contradicts the pipeline is said where it is, not drawn as a result.
    m_warning->setObjectName(u"measureWarning"_s);
    m_warning->setWordWrap(true);
    m_warning->setTextFormat(Qt::RichText);
    m_warning->setFrameShape(QFrame::StyledPanel);
    m_warning->setContentsMargins(6, 3, 6, 3);
    m_warning->setStyleSheet(u"QLabel#measureWarning { background: #fff3cd; color: #664d03; }"_s);
    m_warning->hide();
    connect(m_warning, &QLabel::linkActivated, this, &MeasurePage::onWarningLink);
    layout->addWidget(m_warning);
    m_clocks->setObjectName(u"measureClocks"_s);
    m_clocks->setWordWrap(true);
    m_clocksTip = tr("Each host's clock against the pipeline's first host, from the clock service's "
                     "probes: the crossings between measured hosts are corrected by it (rows \"clocks "
                     "measured\"), each within the uncertainty shown.");
    m_clocks->setToolTip(m_clocksTip);
    m_clocks->hide();
    layout->addWidget(m_clocks);
    layout->addWidget(m_summaryView);
    layout->addWidget(split, 1);
    return pane;
}

void MeasurePage::setUpSummaryView(QAbstractItemModel* styled)
{
    auto* pinned = new PinnedRowsProxy(this);
    pinned->setDynamicSortFilter(false); // a row's kind changes only with a reset: no refilter per tick
    pinned->setSourceModel(styled);
    m_summaryView->setObjectName(u"summaryView"_s);
    m_summaryView->setModel(pinned);
    ViewSetup::records(m_summaryView);
    m_summaryView->verticalHeader()->setDefaultSectionSize(m_statsView->verticalHeader()->defaultSectionSize());
    m_summaryView->setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    m_summaryView->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    m_summaryView->setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Fixed);
    m_summaryView->horizontalHeader()->setSectionResizeMode(QHeaderView::Interactive);
    // The columns of the stage table below, as wide and as shown.
    for (int c = 0; c < LatencyStatsModel::ColumnCount; ++c)
        m_summaryView->setColumnHidden(c, m_statsView->isColumnHidden(c));
    connect(m_statsView->horizontalHeader(), &QHeaderView::sectionResized, m_summaryView,
            [this](int column, int, int width) { m_summaryView->horizontalHeader()->resizeSection(column, width); });
    connect(m_summaryView->horizontalHeader(), &QHeaderView::sectionResized, m_statsView,
            [this](int column, int, int width) {
                if (m_statsView->horizontalHeader()->sectionSize(column) != width)
                    m_statsView->horizontalHeader()->resizeSection(column, width);
            });
    // Its own figures are measured too: the total is the widest of them (a 111 ms max was cut to
    // "1…1" when the widths came from the stage rows alone); the wider of the two wins both.
    QList<int> figures;
    for (int c = 0; c < LatencyStatsModel::ColumnCount; ++c)
        if (c != LatencyStatsModel::SeriesColumn)
            figures << c;
    (new ColumnFitter(m_summaryView))->figures(figures);
    QAbstractItemModel* stats = m_statsView->model();
    connect(stats, &QAbstractItemModel::modelReset, this, &MeasurePage::updatePinnedRows);
    connect(stats, &QAbstractItemModel::layoutChanged, this, &MeasurePage::updatePinnedRows);
    connect(stats, &QAbstractItemModel::rowsInserted, this, &MeasurePage::updatePinnedRows);
    connect(stats, &QAbstractItemModel::rowsRemoved, this, &MeasurePage::updatePinnedRows);
    updatePinnedRows();
}

/// The pinned rows leave the stage table; the summary is as high as its rows.
void MeasurePage::updatePinnedRows()
{
    QAbstractItemModel* stats = m_statsView->model();
    for (int r = 0; r < stats->rowCount(); ++r)
        m_statsView->setRowHidden(r, isPinned(stats->index(r, 0)));
    const int rows = m_summaryView->model()->rowCount();
    m_summaryView->setVisible(rows > 0);
    const int frame = 2 * m_summaryView->frameWidth();
    m_summaryView->setFixedHeight(m_summaryView->horizontalHeader()->sizeHint().height()
                                  + rows * m_summaryView->verticalHeader()->defaultSectionSize() + frame);
    for (int c = 0; c < LatencyStatsModel::ColumnCount; ++c)
        m_summaryView->horizontalHeader()->resizeSection(c, m_statsView->horizontalHeader()->sectionSize(c));
}

void MeasurePage::showColumnMenu(const QPoint& at)
{
    QMenu menu;
    for (int c = 1; c < LatencyStatsModel::ColumnCount; ++c) {
        QAction* a = menu.addAction(m_statsView->model()->headerData(c, Qt::Horizontal).toString());
        a->setCheckable(true);
        a->setChecked(!m_statsView->isColumnHidden(c));
        connect(a, &QAction::toggled, this, [this, c](bool on) {
            m_statsView->setColumnHidden(c, !on);
            m_summaryView->setColumnHidden(c, !on);
        });
    }
    menu.exec(m_statsView->horizontalHeader()->mapToGlobal(at));
}

void MeasurePage::layOut(QLayout* controls, QWidget* pipelinePane, QWidget* chartPane)
{
    auto* split = new QSplitter(Qt::Horizontal, this);
    split->addWidget(pipelinePane);
    split->addWidget(chartPane);
    split->setStretchFactor(0, 2);
    split->setStretchFactor(1, 5);
    // The stamp topics get room for their whole names where the window has it (a wide screen),
    // the charts and the tables the rest; scaled to the window when first shown.
    ViewSetup::initialSizes(split, {470, 810});

    auto* layout = new QVBoxLayout(this);
    layout->addLayout(controls);
    layout->addWidget(m_runBar);
    layout->addWidget(split, 1);
    layout->addWidget(m_counts);
    m_counts->setObjectName(u"measureCounts"_s);
    m_counts->setWordWrap(true); // a long line must not widen the window beyond the screen
}

void MeasurePage::connectSession()
{
    const auto updateChartSeries = [this] { m_chart->setSeries(m_measure->statsModel()->checkedSeries()); };
    LatencyStatsModel* stats = m_measure->statsModel();
    connect(stats, &LatencyStatsModel::checkedChanged, this, updateChartSeries);
    connect(stats, &QAbstractItemModel::modelReset, this, updateChartSeries);
    connect(stats, &QAbstractItemModel::rowsInserted, this, updateChartSeries);
    connect(m_measure, &MeasureSession::updated, this, &MeasurePage::onUpdated);
    connect(m_measure, &MeasureSession::pipelineChanged, this, &MeasurePage::onPipelineChanged);
    connect(m_measure, &MeasureSession::stampTopicsChanged, this,
            [this] { m_seen->update(m_measure->discovery(), m_measure->pipeline()); });
    connect(m_measure, &MeasureSession::clocksChanged, this, &MeasurePage::updateClocks);
    connect(m_measure, &MeasureSession::recordingChanged, this, &MeasurePage::updateEditable);
    connect(m_measure, &MeasureSession::showingRunChanged, this, &MeasurePage::updateEditable);
}

void MeasurePage::updateEditable()
{
    // A run's pipeline is fixed: while recording, and while a recorded run is on screen.
    const bool editable = !m_measure->isRecording() && !m_measure->isShowingRun();
    for (QWidget* w : std::as_const(m_pipelineControls))
        w->setEnabled(editable);
    m_pipelineView->setEditTriggers(editable
                                        ? QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed
                                            | QAbstractItemView::AnyKeyPressed
                                        : QAbstractItemView::NoEditTriggers);
    m_pipelineView->setAcceptDrops(editable);
    m_reset->setEnabled(editable);
    m_window->setEnabled(!m_measure->isRecording());
}

Status MeasurePage::saveChart(const QString& path)
{
    return m_chart->save(path);
}

void MeasurePage::chooseChartFile()
{
    const QString path = QFileDialog::getSaveFileName(this, tr("Export Chart"), u"latency-ecdf.svg"_s,
                                                      tr("SVG (*.svg);;PNG (*.png)"));
    if (path.isEmpty())
        return;
    if (const Status saved = saveChart(path); !saved)
        QMessageBox::warning(this, tr("Export Chart"), saved.error().toString());
}

void MeasurePage::applyEdit(const Pipeline& pipeline)
{
    Pipeline edited = pipeline;
    edited.setWindow(int(m_measure->engine().window())); // the window is the page's, not the edit's
    m_measure->setPipeline(edited);
}

void MeasurePage::showEvent(QShowEvent* event)
{
    QWidget::showEvent(event);
    m_measure->setShown(true); // the figures of the time it was hidden, at once
}

void MeasurePage::hideEvent(QHideEvent* event)
{
    QWidget::hideEvent(event);
    m_measure->setShown(false); // the engine measures on; nothing is pushed to the views
}

void MeasurePage::onUpdated()
{
    if (ViewSetup::hiddenInShownWindow(this)) {
        // Another page is shown and this one never was (it had no hide event): stop pushing too.
        m_measure->setShown(false);
        return;
    }
    if (m_chart->isVisible())
        m_chart->refresh();
    if (m_timeline->isVisible())
        m_timeline->refresh();
    m_pipeline->refreshCounts();
    m_seen->update(m_measure->discovery(), m_measure->pipeline(), m_measure->malformedStampsByTopic());
    updateCounts();
    updateWarning();
    updateClocks();
}

void MeasurePage::updateClocks()
{
    const QString text = m_measure->clocksText();
    m_clocks->setVisible(!text.isEmpty());
    if (m_clocks->text() != text)
        m_clocks->setText(text);
    const QString sync = m_measure->clockSyncText();
    const QString tip = m_clocksTip + (sync.isEmpty() ? QString() : u"\n\n"_s + sync);
    if (m_clocks->toolTip() != tip)
        m_clocks->setToolTip(tip);
}

void MeasurePage::updateWarning()
{
    const QList<LatencyWarning>& warnings = m_measure->statsModel()->warnings();
    if (warnings.isEmpty()) {
        m_warning->hide();
        m_warning->clear();
        return;
    }
    QString text = u"<b>⚠ "_s + tr("Not a measurement:").toHtmlEscaped() + u"</b> "_s;
    text += LatencyWarnings::lines(warnings).join(u"; "_s).toHtmlEscaped() + u". "_s;
    text += tr("%1 or %2.")
                .arg(u"<a href=\"hosts\">"_s + tr("Set hosts").toHtmlEscaped() + u"</a>"_s,
                     u"<a href=\"load\">"_s + tr("load a pipeline").toHtmlEscaped() + u"</a>"_s);
    m_warning->setText(text);
    m_warning->setToolTip(LatencyWarnings::fixInWindow());
    m_warning->show();
}

void MeasurePage::onWarningLink(const QString& link)
{
    if (link == u"load"_s) {
        choosePipelineFile();
        return;
    }
    // The first host of the pipeline, ready to be typed over.
    const QModelIndex host = m_pipeline->index(0, PipelineModel::HostColumn);
    if (!host.isValid())
        return;
    m_pipelineView->setFocus();
    m_pipelineView->setCurrentIndex(host);
    m_pipelineView->edit(host);
}

void MeasurePage::onPipelineChanged()
{
    m_pipeline->setPipeline(m_measure->pipeline());
    m_seen->update(m_measure->discovery(), m_measure->pipeline());
    const QSignalBlocker block(m_window);
    m_window->setValue(int(m_measure->engine().window()));
    if (m_measure->isAutomatic())
        m_mode->setText(
            m_measure->pipeline().isEmpty()
                ? tr("Automatic: waiting for stamps (benchmarking_suite/TimeStamped on ROS or MQTT, or JSON "
                     "stamps on MQTT).")
                : tr("Automatic: ordered by the stamps' times, hosts guessed from the names. Drag rows to "
                     "reorder, double-click a host to change it."));
    else if (m_measure->isShowingRun())
        m_mode->setText(tr("The recorded run's pipeline."));
    else if (!m_pipelineFile.isEmpty())
        m_mode->setText(tr("From %1.").arg(QFileInfo(m_pipelineFile).fileName()));
    else
        m_mode->setText(tr("Edited by hand."));
    m_chart->refresh();
    m_timeline->refresh();
    updateWarning();
}

void MeasurePage::updateCounts()
{
    const LatencyEngine& e = m_measure->engine();
    const SampleJoiner::Counters& c = e.counters();
    QString text = tr("Samples: %1 complete · %2 dropped · %3 incomplete · %4 duplicate stamps · %5 from "
                      "unknown topics")
                       .arg(c.complete)
                       .arg(c.dropped())
                       .arg(e.pending())
                       .arg(c.duplicates)
                       .arg(c.unknownTopic);
    // Samples begun while a stamp topic was not heard yet lost nothing: they are no drops.
    if (c.beforeAllTopics)
        text += tr(" · %n begun before every stamp topic was heard", nullptr,
                   int(std::min<quint64>(c.beforeAllTopics, INT_MAX)));
    if (!e.joiner().allTopicsSeen() && e.joiner().topicCount() > 0) {
        QStringList silent;
        for (int t = 0; t < e.joiner().topicCount() && silent.size() < 3; ++t)
            if (!e.joiner().topicSeen(t))
                silent << e.pipeline().topics().value(t);
        text += tr(" · waiting for the first stamp of %1").arg(silent.join(u", "));
    }
    if (const quint64 bad = m_measure->malformedStamps()) {
        // The worst topics by name: a lab needs to know which device sends garbage.
        const auto [worst, topics] = m_measure->worstMalformedTopics(3);
        QStringList names;
        for (const auto& [count, topic] : worst)
            names << tr("%1 on %2").arg(count).arg(topic);
        if (topics > qsizetype(worst.size()))
            names << tr("%n more topic(s)", nullptr, int(topics - qsizetype(worst.size())));
        text += tr(" · %1 malformed: %2 (last: %3)")
                    .arg(bad)
                    .arg(names.join(u", "), m_measure->lastStampError());
    }
    // Below the stages, out of sight at 1280x800 until scrolled to: said where they are.
    const PipelineSeries& series = e.pipelineSeries();
    const QList<int> single = series.externalWithValues();
    if (const auto observed = std::count_if(single.cbegin(), single.cend(), [&](int i) {
            return SeriesId::isObserved(series.info(i).label);
        }))
        text += tr(" · %n observed hop(s) without stamps: the last rows of the stage table", nullptr,
                   int(observed));
    if (const int left = m_measure->observedLeftOut())
        text += tr(" · the observed hop latency of %n more link(s) is on the Links page only (the first "
                   "links to match have a series here, a bounded number)",
                   nullptr, left);
    if (const quint64 dropped = m_measure->observedDropped())
        text += tr(" · %1 observed hop latencies dropped unmeasured (more came between two reads than a "
                   "link keeps)")
                    .arg(dropped);
    if (m_measure->isPaused())
        text += tr(" · paused");
    m_counts->setText(text);
}

Status MeasurePage::loadPipeline(const QString& path)
{
    const Result<Pipeline> p = Pipeline::readFile(path);
    if (!p)
        return p.error();
    m_pipelineFile = path;
    m_measure->setPipeline(*p);
    onPipelineChanged();
    return {};
}

Status MeasurePage::savePipeline(const QString& path)
{
    if (Status saved = m_measure->pipeline().save(path); !saved)
        return saved;
    m_pipelineFile = path;
    onPipelineChanged();
    return {};
}

void MeasurePage::choosePipelineFile()
{
    const QString path
        = QFileDialog::getOpenFileName(this, tr("Load Pipeline"), QFileInfo(m_pipelineFile).path(),
                                       tr("Pipelines (*.yaml *.yml);;All files (*)"));
    if (path.isEmpty())
        return;
    if (const Status loaded = loadPipeline(path); !loaded)
        QMessageBox::warning(this, tr("Load Pipeline"), loaded.error().toString());
}

void MeasurePage::chooseSaveFile()
{
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Save Pipeline"), m_pipelineFile.isEmpty() ? u"pipeline.yaml"_s : m_pipelineFile,
        tr("Pipelines (*.yaml *.yml)"));
    if (path.isEmpty())
        return;
    if (const Status saved = savePipeline(path); !saved)
        QMessageBox::warning(this, tr("Save Pipeline"), saved.error().toString());
}

void MeasurePage::removeSelectedStamps()
{
    QList<int> rows;
    for (const QModelIndex& i : m_pipelineView->selectionModel()->selectedRows())
        rows << i.row();
    if (rows.isEmpty() && m_pipelineView->currentIndex().isValid())
        rows << m_pipelineView->currentIndex().row();
    if (!rows.isEmpty())
        applyEdit(m_pipeline->withoutRows(rows));
}

void MeasurePage::moveSelectedStamp(int delta)
{
    const QModelIndex current = m_pipelineView->currentIndex();
    if (!current.isValid())
        return;
    const int to = current.row() + delta;
    if (to < 0 || to >= m_pipeline->rowCount())
        return;
    applyEdit(m_pipeline->withRowMoved(current.row(), to));
    m_pipelineView->setCurrentIndex(m_pipeline->index(to, current.column()));
}

void MeasurePage::addSeenTopic(const QModelIndex& index)
{
    QStringList topics;
    for (const QModelIndex& i : m_seenView->selectionModel()->selectedIndexes())
        topics << i.data(StampTopicModel::TopicRole).toString();
    if (topics.isEmpty())
        topics << index.data(StampTopicModel::TopicRole).toString();
    applyEdit(m_pipeline->withTopics(topics, -1));
}
