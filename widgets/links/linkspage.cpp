// SPDX-License-Identifier: MIT
#include "linkspage.h"

#include "config/configreader.h"
#include "fleet/fleetsource.h"
#include "watch/watchsession.h"
#include "widgets/common/columnfitter.h"
#include "widgets/common/figuresortproxy.h"
#include "widgets/common/livetext.h"
#include "widgets/common/namedelegate.h"
#include "widgets/common/ratechart.h"
#include "widgets/common/viewsetup.h"
#include "widgets/links/fleetview.h"
#include "widgets/links/linkmodel.h"
#include "widgets/links/ruleseditor.h"
#include "yaml/yamlreader.h"

#include <algorithm>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPainter>
#include <QPushButton>
#include <QSettings>
#include <QSortFilterProxyModel>
#include <QSplitter>
#include <QStackedWidget>
#include <QStyledItemDelegate>
#include <QSystemTrayIcon>
#include <QTableView>
#include <QTreeWidget>
#include <QVBoxLayout>

using namespace Qt::StringLiterals;

namespace {
QColor levelColor(int level)
{
    switch (LinkLevel(level)) {
    case LinkLevel::Ok:
        return QColor(0x2e, 0x7d, 0x32);
    case LinkLevel::Warning:
        return QColor(0xef, 0x8f, 0x00);
    case LinkLevel::Alert:
        return QColor(0xc6, 0x28, 0x28);
    }
    return QColor(0x9e, 0x9e, 0x9e); // unknown: the watcher cannot see a side
}

/// The state as a coloured dot before its words; the history as a sparkline.
class LinkDelegate : public QStyledItemDelegate
{
public:
    using QStyledItemDelegate::QStyledItemDelegate;

    void paint(QPainter* painter, const QStyleOptionViewItem& option, const QModelIndex& index) const override
    {
        if (index.column() != LinkModel::HistoryColumn) {
            QStyledItemDelegate::paint(painter, option, index);
            return;
        }
        // Background and selection only: the cell has no text.
        QStyleOptionViewItem background = option;
        background.text.clear();
        background.features &= ~QStyleOptionViewItem::HasDisplay;
        const QWidget* widget = option.widget;
        (widget ? widget->style() : QApplication::style())
            ->drawControl(QStyle::CE_ItemViewItem, &background, painter, widget);
        const QList<double> values = index.data(LinkModel::HistoryRole).value<QList<double>>();
        if (values.size() < 2)
            return;
        const double top = std::max(1.0, *std::max_element(values.cbegin(), values.cend()));
        const QRectF r = QRectF(option.rect).adjusted(3, 3, -3, -3);
        QPolygonF line;
        for (qsizetype i = 0; i < values.size(); ++i)
            line << QPointF(r.left() + r.width() * double(i) / double(values.size() - 1),
                            r.bottom() - r.height() * values[i] / top);
        painter->save();
        painter->setRenderHint(QPainter::Antialiasing);
        painter->setPen(QPen(option.state & QStyle::State_Selected ? option.palette.highlightedText().color()
                                                                   : option.palette.text().color(),
                             1.2));
        painter->drawPolyline(line);
        painter->restore();
    }

    void initStyleOption(QStyleOptionViewItem* option, const QModelIndex& index) const override
    {
        QStyledItemDelegate::initStyleOption(option, index);
        const QVariant level = index.data(LinkModel::LevelRole);
        if (index.column() == 0 && level.isValid()) {
            QPixmap dot(10, 10);
            dot.fill(Qt::transparent);
            QPainter p(&dot);
            p.setRenderHint(QPainter::Antialiasing);
            p.setBrush(levelColor(level.toInt()));
            p.setPen(Qt::NoPen);
            p.drawEllipse(0, 0, 10, 10);
            option->icon = QIcon(dot);
            option->features |= QStyleOptionViewItem::HasDecoration;
            option->decorationSize = QSize(10, 10);
        }
    }
};

} // namespace

LinksPage::LinksPage(WatchSession* watch, QWidget* parent)
    : QWidget(parent)
    , m_watch(watch)
    , m_model(new LinkModel(watch->monitor(), this))
    , m_eventModel(new EventLogModel(watch->monitor(), this))
    , m_proxy(new FigureSortProxy(LinkModel::ValueRole, this))
{
    setObjectName(u"linksPage"_s);
    m_eventModel->setObjectName(u"eventModel"_s);
    m_watch->setLinkLimit(
        WatchSession::kWindowLinkLimit); // what a lab's master and broker carry for a window
    QLayout* bar = createBar();
    auto* top = new QSplitter(Qt::Horizontal, this);
    top->addWidget(createLinkTable());
    top->addWidget(createDetailPane());
    top->setStretchFactor(0, 4);
    top->setStretchFactor(1, 1);
    ViewSetup::initialSizes(top, {1060, 220}); // the detail pane gives way to the links' names
    auto* bottom = new QSplitter(Qt::Horizontal, this);
    bottom->addWidget(createConfigList());
    bottom->addWidget(createEventLog());
    bottom->setStretchFactor(0, 1);
    bottom->setStretchFactor(1, 2);
    auto* split = new QSplitter(Qt::Vertical, this);
    split->addWidget(top);
    split->addWidget(bottom);
    split->setStretchFactor(0, 3);
    split->setStretchFactor(1, 1);
    auto* local = new QWidget(this);
    auto* localLayout = new QVBoxLayout(local);
    localLayout->setContentsMargins(0, 0, 0, 0);
    localLayout->addLayout(bar);
    localLayout->addWidget(split, 1);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 0);
    layout->addLayout(createSourceChoice(local));
    layout->addWidget(m_sources, 1);

    LinkMonitor* monitor = watch->monitor();
    connect(monitor, &LinkMonitor::refreshed, this, [this] {
        if (ViewSetup::hiddenInShownWindow(this))
            return; // drawn when shown (showEvent)
        updateSummary();
        if (!m_links->currentIndex().isValid() && m_proxy->rowCount() > 0)
            m_links->setCurrentIndex(m_proxy->index(0, 0)); // the detail pane is never empty for nothing
        showDetail();
    });
    connect(monitor, &LinkMonitor::eventStarted, this, &LinksPage::notify);
    updateSummary();
    showPlan();
}

LinksPage::~LinksPage() = default;

void LinksPage::showEvent(QShowEvent* event)
{
    QWidget::showEvent(event);
    updateSummary();
    showDetail();
}

QLayout* LinksPage::createSourceChoice(QWidget* local)
{
    m_fleet = new FleetView(this);
    m_sources = new QStackedWidget(this);
    m_sources->addWidget(local);
    m_sources->addWidget(m_fleet);
    m_sourceChoice = new QComboBox(this);
    m_sourceChoice->setObjectName(u"linkSource"_s);
    m_sourceChoice->addItem(tr("This window's watch"));
    m_sourceChoice->addItem(tr("Prometheus server…"));
    m_sourceChoice->setToolTip(tr("Where the links come from: the bridges this window watches itself, or "
                                  "every host's watch as a Prometheus server has them (nothing subscribed)"));
    auto* label = new QLabel(tr("&Links from:"), this);
    label->setBuddy(m_sourceChoice);
    connect(m_sourceChoice, &QComboBox::currentIndexChanged, this, [this](int index) {
        m_sources->setCurrentIndex(index);
        QSettings().setValue(u"links/source"_s, index == 1 ? u"prometheus"_s : u"watch"_s);
        m_fleet->source()->setRules(m_watch->monitor()->ruleBook().rules()); // as the local links'
        if (index == 1 && !m_fleet->isRefreshing())
            m_fleet->connectToRemembered();
        else if (index == 0)
            m_fleet->stop();
    });
    if (QSettings().value(u"links/source"_s).toString() == "prometheus"_L1)
        m_sourceChoice->setCurrentIndex(1);
    auto* row = new QHBoxLayout;
    row->addWidget(label);
    row->addWidget(m_sourceChoice);
    row->addStretch(1);
    return row;
}

void LinksPage::showFleet(const QString& url)
{
    const QSignalBlocker quiet(m_sourceChoice);
    m_sourceChoice->setCurrentIndex(1);
    m_sources->setCurrentIndex(1);
    QSettings().setValue(u"links/source"_s, u"prometheus"_s);
    m_fleet->source()->setRules(m_watch->monitor()->ruleBook().rules());
    m_fleet->connectTo(url);
}

QLayout* LinksPage::createBar()
{
    auto* add = new QPushButton(tr("&Add Configs…"), this);
    add->setToolTip(tr("List more bridge configs (one per vehicle or robot); check one to watch it"));
    auto* rules = new QPushButton(tr("R&ules…"), this);
    rules->setToolTip(tr("Edit the thresholds (a rules YAML) every link is held to"));
    auto* discovered = new QCheckBox(tr("&Discovered"), this);
    discovered->setObjectName(u"discoveredLinks"_s);
    discovered->setToolTip(tr("Also watch the links mqtt_client announces on the broker that no open "
                              "config maps (their MQTT end)"));
    discovered->setChecked(m_watch->isDiscovering());
    connect(discovered, &QCheckBox::toggled, m_watch, &WatchSession::setDiscovering);
    m_filter = new QLineEdit(this);
    m_filter->setObjectName(u"linkFilter"_s);
    m_filter->setPlaceholderText(tr("Filter links…"));
    m_filter->setClearButtonEnabled(true);
    m_summary = new QLabel(this);
    m_summary->setObjectName(u"linkSummary"_s);
    connect(add, &QPushButton::clicked, this, &LinksPage::chooseConfigs);
    connect(rules, &QPushButton::clicked, this, &LinksPage::editRules);
    connect(m_filter, &QLineEdit::textChanged, m_proxy, &QSortFilterProxyModel::setFilterFixedString);
    auto* bar = new QHBoxLayout;
    bar->addWidget(add);
    bar->addWidget(rules);
    bar->addWidget(discovered);
    bar->addWidget(m_filter, 1);
    bar->addWidget(m_summary, 2);
    return bar;
}

QWidget* LinksPage::createLinkTable()
{
    m_proxy->setSourceModel(m_model);
    m_proxy->setFilterKeyColumn(-1);
    m_proxy->setFilterCaseSensitivity(Qt::CaseInsensitive);
    m_links = new QTableView(this);
    m_links->setObjectName(u"linkTable"_s);
    m_links->setModel(m_proxy);
    m_links->setItemDelegate(new LinkDelegate(m_links));
    ViewSetup::records(m_links);
    m_links->setSortingEnabled(true);
    m_links->sortByColumn(LinkModel::BridgeColumn, Qt::AscendingOrder);
    // The topics get the room: names are what people look for. The figures and the state (during
    // an outage its reasons, `source stopped`) take the width they need, measured when they change.
    QHeaderView* header = m_links->horizontalHeader();
    header->setSectionResizeMode(QHeaderView::Interactive);
    m_links->setColumnWidth(LinkModel::HistoryColumn, 60); // a sparkline: room left for the names at 1280x800
    m_links->setColumnHidden(LinkModel::LastEventColumn, true); // the event log says it; the tooltip too
    NameDelegate::install(m_links, LinkModel::SourceColumn);
    NameDelegate::install(m_links, LinkModel::DestinationColumn);
    auto* fitter = new ColumnFitter(m_links);
    fitter->figures({LinkModel::StateColumn, LinkModel::BridgeColumn, LinkModel::DirectionColumn,
                     LinkModel::SourceRateColumn, LinkModel::DestinationRateColumn, LinkModel::LossColumn,
                     LinkModel::P50Column, LinkModel::P99Column, LinkModel::ObservedColumn});
    fitter->fill({LinkModel::SourceColumn, LinkModel::DestinationColumn});
    connect(m_links->selectionModel(), &QItemSelectionModel::currentRowChanged, this, &LinksPage::showDetail);
    return m_links;
}

QWidget* LinksPage::createDetailPane()
{
    auto* pane = new QWidget(this);
    auto* v = new QVBoxLayout(pane);
    v->setContentsMargins(0, 0, 0, 0);
    // The link's name changes with the selection, its figures every second: a LiveText repaints
    // itself alone, where a word-wrapped QLabel's new text relaid out and repainted the pane.
    m_detailTitle = new QLabel(tr("Select a link to see its history."), pane);
    m_detailTitle->setObjectName(u"linkDetailTitle"_s);
    m_detailTitle->setWordWrap(true);
    m_detailTitle->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_detail = new LiveText(pane);
    m_detail->setObjectName(u"linkDetail"_s);
    m_detail->setWordWrap(true);
    m_rateChart = new RateChart(pane);
    m_latencyChart = new RateChart(pane);
    v->addWidget(m_detailTitle);
    v->addWidget(m_detail);
    v->addWidget(new QLabel(tr("Destination rate:"), pane));
    v->addWidget(m_rateChart, 1);
    v->addWidget(new QLabel(tr("Latency p99:"), pane));
    v->addWidget(m_latencyChart, 1);
    pane->setMinimumWidth(200);
    return pane;
}

QWidget* LinksPage::createEventLog()
{
    m_events = new QTableView(this);
    m_events->setObjectName(u"eventLog"_s);
    m_events->setModel(m_eventModel);
    m_events->setItemDelegate(new LinkDelegate(m_events));
    ViewSetup::records(m_events);
    m_events->horizontalHeader()->setSectionResizeMode(EventLogModel::WhatColumn, QHeaderView::Stretch);
    m_events->setColumnWidth(EventLogModel::SubjectColumn, 320);
    return m_events;
}

QWidget* LinksPage::createConfigList()
{
    auto* pane = new QWidget(this);
    auto* v = new QVBoxLayout(pane);
    v->setContentsMargins(0, 0, 0, 0);
    m_configList = new QTreeWidget(pane);
    m_configList->setObjectName(u"watchConfigs"_s);
    m_configList->setRootIsDecorated(false);
    m_configList->setUniformRowHeights(true);
    m_configList->setHeaderLabels({tr("Watch config"), tr("Links"), tr("ROS"), tr("ROS 2"), tr("MQTT")});
    m_configList->setToolTip(tr("Check a config to watch its links (Space checks the current one). Opening "
                                "or editing a config subscribes to nothing; watching subscribes to the "
                                "topics counted here, at most %1 links in all.")
                                 .arg(WatchSession::kWindowLinkLimit));
    auto* caption = new QLabel(tr("&Configs (checked: watched)"), pane);
    caption->setBuddy(m_configList);
    m_plan = new QLabel(pane);
    m_plan->setObjectName(u"watchPlan"_s);
    m_plan->setWordWrap(true);
    m_plan->setTextInteractionFlags(Qt::TextSelectableByMouse);
    v->addWidget(caption);
    v->addWidget(m_configList, 1);
    v->addWidget(m_plan);
    connect(m_configList, &QTreeWidget::itemChanged, this, &LinksPage::configChecked);
    connect(m_configList, &QTreeWidget::currentItemChanged, this, &LinksPage::showPlan);
    return pane;
}

void LinksPage::setMapConfigs(const QList<WatchSession::Config>& configs)
{
    const auto key = [](const WatchSession::Config& c) { return c.file.isEmpty() ? c.name : c.file; };
    QHash<QString, bool> watched;
    for (const Listed& l : std::as_const(m_configs))
        if (!l.added)
            watched.insert(key(l.config), l.watched);
    QList<Listed> next;
    for (const WatchSession::Config& c : configs) {
        if (c.name.isEmpty())
            continue;
        Listed l {c, false, watched.value(key(c), false)};
        if (!c.file.isEmpty() && m_watchWhenListed.remove(c.file))
            l.watched = true;
        next << l;
    }
    for (const Listed& l : std::as_const(m_configs))
        if (l.added)
            next << l;
    m_configs = next;
    if (const Status applied = applyConfigs(); !applied) {
        // An edit made the watched configs pass the limit: watching stops, and says why.
        for (Listed& l : m_configs)
            l.watched = false;
        static_cast<void>(applyConfigs()); // none watched: within any limit
        listConfigs();
        m_plan->setText(tr("Watching stopped: %1").arg(applied.error().toString()));
        return;
    }
    listConfigs();
}

Status LinksPage::addConfigFiles(const QStringList& paths, bool watch)
{
    QList<Listed> added;
    for (const QString& path : paths) {
        const Result<QByteArray> bytes = YamlReader::readFile(path);
        const ConfigReadResult read = bytes ? ConfigReader::read(*bytes) : ConfigReadResult();
        if (!read.parsed)
            return LocatedError {tr("%1 is not a bridge config that can be read").arg(path)};
        added.append({{QFileInfo(path).completeBaseName(), QFileInfo(path).absoluteFilePath(), read.config},
                      true,
                      watch});
    }
    const QList<Listed> before = m_configs;
    m_configs << added;
    if (Status applied = applyConfigs(); !applied) {
        m_configs = before;
        m_plan->setText(applied.error().toString());
        return applied;
    }
    listConfigs();
    return {};
}

Status LinksPage::setWatched(const QString& name, bool watched)
{
    const QString file = QFileInfo(name).absoluteFilePath();
    qsizetype at = -1;
    for (qsizetype i = 0; i < m_configs.size() && at < 0; ++i)
        if (m_configs[i].config.name == name || m_configs[i].config.file == file)
            at = i;
    if (at < 0)
        return LocatedError {tr("No config %1 is open").arg(name)};
    if (m_configs[at].watched == watched)
        return {};
    m_configs[at].watched = watched;
    const Status applied = applyConfigs();
    if (applied) {
        listConfigs();
        return {};
    }
    m_configs[at].watched = !watched;
    const LocatedError refused {
        tr("Watching %1 refused: %2").arg(m_configs[at].config.name, applied.error().toString())};
    listConfigs();
    m_plan->setText(refused.message);
    return refused;
}

void LinksPage::watchWhenListed(const QString& file)
{
    m_watchWhenListed.insert(QFileInfo(file).absoluteFilePath());
}

Status LinksPage::applyConfigs()
{
    QList<WatchSession::Config> configs;
    for (const Listed& l : std::as_const(m_configs))
        if (l.watched)
            configs << l.config;
    if (Status set = m_watch->setConfigs(configs); !set)
        return set;
    m_model->refresh();
    updateSummary();
    return {};
}

void LinksPage::listConfigs()
{
    // Rows are updated in place: this runs from a row's check (inside its delegate's event), where
    // deleting the row would pull it from under the view.
    const QSignalBlocker blocker(m_configList);
    while (m_configList->topLevelItemCount() > m_configs.size())
        delete m_configList->takeTopLevelItem(m_configList->topLevelItemCount() - 1);
    while (m_configList->topLevelItemCount() < m_configs.size())
        new QTreeWidgetItem(m_configList);
    for (int row = 0; row < m_configs.size(); ++row) {
        const Listed& l = m_configs[row];
        const WatchSession::Plan plan = m_watch->planOf(l.config);
        QTreeWidgetItem* item = m_configList->topLevelItem(row);
        item->setFlags(item->flags() | Qt::ItemIsUserCheckable);
        item->setText(0, l.config.name);
        item->setToolTip(0, l.config.file.isEmpty() ? tr("not saved yet") : l.config.file);
        item->setCheckState(0, l.watched ? Qt::Checked : Qt::Unchecked);
        int column = 1;
        for (qsizetype n : {qsizetype(plan.links), plan.rosTopics.size(), plan.ros2Topics.size(),
                            plan.mqttTopics.size()}) {
            item->setText(column, QString::number(n));
            item->setTextAlignment(column++, Qt::AlignRight | Qt::AlignVCenter);
        }
    }
    for (int c = 0; c < m_configList->columnCount(); ++c)
        m_configList->resizeColumnToContents(c);
    if (!m_configList->currentItem() && m_configList->topLevelItemCount() > 0)
        m_configList->setCurrentItem(m_configList->topLevelItem(0));
    showPlan();
}

void LinksPage::showPlan()
{
    const int row
        = m_configList->currentItem() ? m_configList->indexOfTopLevelItem(m_configList->currentItem()) : -1;
    if (row < 0 || row >= m_configs.size()) {
        m_plan->setText(tr("Open a bridge config on the Map page, or add one here; check it to watch it."));
        m_plan->setToolTip(QString());
        return;
    }
    const Listed& l = m_configs[row];
    const WatchSession::Plan plan = m_watch->planOf(l.config);
    const QString counts = tr("%1 ROS topics at the master, %2 on the ROS 2 domain and %3 MQTT topics")
                               .arg(plan.rosTopics.size())
                               .arg(plan.ros2Topics.size())
                               .arg(plan.mqttTopics.size());
    QString text = l.watched
        ? tr("%1 is watched (links: %2): subscribed to %3.").arg(l.config.name).arg(plan.links).arg(counts)
        : tr("%1 is not watched. Watching it would subscribe to %2 (links: %3).")
              .arg(l.config.name, counts)
              .arg(plan.links);
    if (m_watch->linkLimit() > 0 && plan.links > m_watch->linkLimit())
        text += u' ' + tr("That is more than the %1 links a window watches.").arg(m_watch->linkLimit());
    m_plan->setText(text);
    // The topics themselves, a bounded list: a config may map thousands.
    constexpr qsizetype kListed = 40;
    QStringList lines;
    const auto list = [&](const QString& title, const QStringList& topics) {
        if (topics.isEmpty())
            return;
        lines << title;
        for (qsizetype i = 0; i < std::min(topics.size(), kListed); ++i)
            lines << u"  "_s + topics[i];
        if (topics.size() > kListed)
            lines << u"  "_s + tr("… and %1 more").arg(topics.size() - kListed);
    };
    list(tr("ROS (master):"), plan.rosTopics);
    list(tr("ROS 2:"), plan.ros2Topics);
    list(tr("MQTT:"), plan.mqttTopics);
    m_plan->setToolTip(lines.join(u'\n'));
}

void LinksPage::configChecked(QTreeWidgetItem* item)
{
    const int row = m_configList->indexOfTopLevelItem(item);
    if (row < 0 || row >= m_configs.size())
        return;
    const bool checked = item->checkState(0) == Qt::Checked;
    if (checked != m_configs[row].watched) {
        const QString key
            = m_configs[row].config.file.isEmpty() ? m_configs[row].config.name : m_configs[row].config.file;
        static_cast<void>(setWatched(key, checked)); // a refusal is shown in the plan line
    }
}

void LinksPage::chooseConfigs()
{
    const QStringList paths = QFileDialog::getOpenFileNames(
        this, tr("Watch Bridge Configs"), QString(), tr("Bridge configs (*.yaml *.yml);;All files (*)"));
    if (paths.isEmpty())
        return;
    if (const Status added = addConfigFiles(paths); !added)
        m_plan->setText(added.error().toString());
}

void LinksPage::editRules()
{
    RulesEditor editor(m_watch->monitor()->ruleBook().rules(), this);
    if (editor.exec() == QDialog::Accepted && editor.rules()) {
        m_watch->setRules(*editor.rules());
        m_fleet->source()->setRules(*editor.rules()); // the fleet's links are held to the same
    }
}

void LinksPage::updateSummary()
{
    const LinkMonitor* monitor = m_watch->monitor();
    int counts[3] = {0, 0, 0};
    int unknown = 0;
    for (int i = 0; i < monitor->linkCount(); ++i) {
        if (monitor->unknown(i).isEmpty())
            ++counts[int(monitor->level(i))];
        else
            ++unknown;
    }
    if (monitor->linkCount() == 0) {
        m_summary->setText(tr("No links watched: check a config below to watch it."));
        return;
    }
    QString text = tr("%n link(s): %1 ok, %2 warning, %3 alert", nullptr, monitor->linkCount())
                       .arg(counts[0])
                       .arg(counts[1])
                       .arg(counts[2]);
    if (unknown > 0)
        text += tr(", %1 unknown (the watch's own connection is down)").arg(unknown);
    m_summary->setText(text);
}

void LinksPage::showDetail()
{
    const QModelIndex current = m_proxy->mapToSource(m_links->currentIndex());
    const LinkMonitor* monitor = m_watch->monitor();
    const int i = current.isValid() ? monitor->indexOf(current.data(LinkModel::LinkIdRole).toString()) : -1;
    if (i < 0)
        return;
    const LinkDef& d = monitor->link(i);
    const LinkFigures f = monitor->figures(i);
    const QString title = tr("<b>%1</b> → <b>%2</b> (%3)")
                              .arg(d.sourceTopic().toHtmlEscaped(), d.destinationTopic().toHtmlEscaped(),
                                   d.bridge().toHtmlEscaped());
    if (m_detailTitle->text() != title)
        m_detailTitle->setText(title);
    m_detail->setText(tr("%1 messages at the source, %2 at the destination, %3 lost, %4 Header.seq gaps, "
                         "%5 duplicates, %6 reordered, %7 stalls")
                          .arg(f.source.messages)
                          .arg(f.destination.messages)
                          .arg(f.lost)
                          .arg(f.seqGaps)
                          .arg(f.duplicates)
                          .arg(f.reordered)
                          .arg(f.stalls)
                      + u'\n' + LinkModel::latencySourceText(f.latencySource) + u'\n'
                      + LinkModel::observedLine(d, f));
    QList<double> rates;
    QList<double> p99;
    for (const LinkMonitor::HistoryPoint& h : monitor->history(i)) {
        rates << h.rateHz;
        if (std::isfinite(h.p99Ms)) // seconds without stamps are left out
            p99 << h.p99Ms;
    }
    m_rateChart->setSamples(rates, tr("Hz"));
    m_latencyChart->setSamples(p99, tr("ms"));
}

void LinksPage::notify(const WatchEvent& event)
{
    if (event.level != LinkLevel::Alert || (window() && window()->isActiveWindow()))
        return;
    ++m_notified;
    const QString title = tr("Bridgescope: %1").arg(event.reasons.join(u", "_s));
    if (QSystemTrayIcon::isSystemTrayAvailable()) {
        if (!m_tray) {
            m_tray = new QSystemTrayIcon(QApplication::windowIcon(), this);
            m_tray->show();
        }
        m_tray->showMessage(title, event.detail, QSystemTrayIcon::Warning, 10000);
    }
    QApplication::alert(window()); // the task bar entry asks for attention where there is no tray
}
