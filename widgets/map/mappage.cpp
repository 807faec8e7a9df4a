// SPDX-License-Identifier: MIT
#include "mappage.h"

#include "base/wallclock.h"
#include "config/configdocument.h"
#include "config/mappingfactory.h"
#include "config/mappingmodel.h"
#include "models/mqtttopicfilter.h"
#include "models/mqtttopictree.h"
#include "session/discoverylints.h"
#include "session/graphstatus.h"
#include "session/mappinghealthevaluator.h"
#include "topics/topictablemodel.h"
#include "topics/topictree.h"
#include "widgets/common/viewsetup.h"
#include "widgets/map/bridgedtopicsproxy.h"
#include "widgets/map/configeditor.h"
#include "widgets/map/configfilecontroller.h"
#include "widgets/map/configtabs.h"
#include "widgets/map/undocommands.h"

#include <chrono>
#include <memory>
#include <QAction>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMimeData>
#include <QSortFilterProxyModel>
#include <QSplitter>
#include <QTableView>
#include <QTimer>
#include <QToolButton>
#include <QTreeView>
#include <QUndoStack>
#include <QVBoxLayout>

using namespace Qt::StringLiterals;

MapPage::MapPage(const Parts& parts, ConfigDocument* document, QUndoStack* undoStack, QWidget* parent)
    : QWidget(parent)
    , m_parts(parts)
    , m_mqttMonitored(parts.sources.subscriptions(SourceGraph::Mqtt))
    , m_doc(document)
    , m_undo(undoStack)
    , m_editor(new ConfigEditor(document, undoStack, this))
    , m_healthTimer(new QTimer(this))
{
    QLayout* bar = createBar();
    // The mappings take most of the width (their topics whole); the discovered topics are trees
    // in a panel beside them that folds away when the mappings need more.
    auto* split = new QSplitter(Qt::Horizontal, this);
    split->setObjectName(u"mapSplit"_s);
    split->addWidget(createTopicsPanel());
    split->addWidget(m_editor);
    split->setStretchFactor(0, 0);
    split->setStretchFactor(1, 1);
    split->setCollapsible(1, false);
    ViewSetup::initialSizes(split, {370, 910});
    auto* v = new QVBoxLayout(this);
    v->setContentsMargins(4, 4, 4, 0);
    v->addLayout(bar);
    v->addWidget(split, 1);

    setUpDrops();
    connect(document, &ConfigDocument::resetDone, this, [this] {
        m_prefix->setText(m_doc->config().client.values.text(u"id"_s));
        updateBridgedTopics();
        updateHealth();
    });
    connect(document, &ConfigDocument::problemsChanged, this, &MapPage::updateBridgedTopics);
    connect(m_healthTimer, &QTimer::timeout, this, &MapPage::updateHealth);
    m_healthTimer->start(1000);
}

/// Keyboard bridging and the prefix new MQTT topics get.
QLayout* MapPage::createBar()
{
    m_toMqtt = new QAction(tr("Bridge Selected ROS Topics to MQTT"), this);
    m_toMqtt->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_M));
    m_toMqtt->setIconText(tr("ROS → MQTT"));
    m_toMqtt->setToolTip(
        tr("Bridge the selected ROS topics; under the selected MQTT level, if any (Ctrl+Shift+M)"));
    m_toRos = new QAction(tr("Bridge Selected MQTT Topics to ROS"), this);
    m_toRos->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_R));
    m_toRos->setIconText(tr("MQTT → ROS"));
    m_toRos->setToolTip(
        tr("Bridge the selected MQTT topics; beside the selected ROS topic, if any (Ctrl+Shift+R)"));
    addAction(m_toMqtt);
    addAction(m_toRos);
    connect(m_toMqtt, &QAction::triggered, this, &MapPage::bridgeSelectedRos);
    connect(m_toRos, &QAction::triggered, this, &MapPage::bridgeSelectedMqtt);

    m_showTopics = new QAction(tr("Discovered Topics"), this);
    m_showTopics->setObjectName(u"topicsPanelAction"_s);
    m_showTopics->setCheckable(true);
    m_showTopics->setChecked(true);
    m_showTopics->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_T));
    m_showTopics->setToolTip(tr("Show or fold away the discovered ROS and MQTT topics (Ctrl+Shift+T)"));
    addAction(m_showTopics);

    auto* bar = new QHBoxLayout;
    auto* panelButton = new QToolButton(this);
    panelButton->setDefaultAction(m_showTopics);
    panelButton->setToolButtonStyle(Qt::ToolButtonTextOnly);
    bar->addWidget(panelButton);
    bar->addSpacing(12);
    auto* bridgeLabel = new QLabel(tr("Bridge selected:"), this);
    bar->addWidget(bridgeLabel);
    for (QAction* a : {m_toMqtt, m_toRos}) {
        auto* b = new QToolButton(this);
        b->setDefaultAction(a);
        b->setToolButtonStyle(Qt::ToolButtonTextOnly);
        bar->addWidget(b);
    }
    m_prefix = new QLineEdit(this);
    m_prefix->setObjectName(u"mqttPrefix"_s);
    m_prefix->setPlaceholderText(tr("none"));
    m_prefix->setToolTip(
        tr("New MQTT topics go below this prefix (for example the client id), unless dropped on a level"));
    m_prefix->setMaximumWidth(220);
    m_prefix->setMinimumWidth(180); // a bridge's id (`mqtt_interface_vehicle`) whole
    auto* prefixLabel = new QLabel(tr("MQTT &prefix:"), this);
    prefixLabel->setBuddy(m_prefix);
    bar->addSpacing(12);
    bar->addWidget(prefixLabel);
    bar->addWidget(m_prefix);
    bar->addStretch(1);
    return bar;
}

/// The discovered topics beside the mappings: how to drag, the ROS tree above the MQTT tree.
QWidget* MapPage::createTopicsPanel()
{
    m_topicsPanel = new QWidget(this);
    m_topicsPanel->setObjectName(u"topicsPanel"_s);
    auto* v = new QVBoxLayout(m_topicsPanel);
    v->setContentsMargins(0, 0, 0, 0);
    // Wrapped in the panel's width, never cut.
    m_hint = new QLabel(tr("Drag ROS topics onto the MQTT tree, MQTT topics onto a ROS namespace (or onto "
                           "one ROS topic to publish there); drop a topic on a mapping to retarget it."),
                        m_topicsPanel);
    m_hint->setObjectName(u"mapHint"_s);
    m_hint->setWordWrap(true);
    m_hint->setStyleSheet(u"color: palette(mid)"_s);
    v->addWidget(m_hint);
    auto* topics = new QSplitter(Qt::Vertical, m_topicsPanel);
    topics->setObjectName(u"topicsSplit"_s);
    topics->addWidget(createRosPane());
    topics->addWidget(createMqttPane());
    v->addWidget(topics, 1);
    connect(m_showTopics, &QAction::toggled, m_topicsPanel, &QWidget::setVisible);
    return m_topicsPanel;
}

/// Discovered ROS topics as a namespace tree (as the MQTT topics below), the bridged ones marked.
QWidget* MapPage::createRosPane()
{
    m_rosTree = new TopicTree(this);
    m_rosTree->setSourceModel(m_parts.rosTopics);
    m_rosBridged = new BridgedTopicsProxy(TopicTableModel::TopicRole, this);
    m_rosBridged->setSourceModel(m_rosTree);
    m_rosFilter = new QSortFilterProxyModel(this);
    m_rosFilter->setSourceModel(m_rosBridged);
    m_rosFilter->setRecursiveFilteringEnabled(true); // a match keeps its namespaces
    m_rosFilter->setFilterRole(TopicTree::PathRole);
    m_rosFilter->setFilterKeyColumn(TopicTree::TopicColumn);
    m_rosFilter->setFilterCaseSensitivity(Qt::CaseInsensitive);
    auto* box = new QWidget(this);
    auto* v = new QVBoxLayout(box);
    v->setContentsMargins(0, 0, 0, 0);
    auto* filter = new QLineEdit(box);
    filter->setObjectName(u"rosTopicFilter"_s);
    filter->setPlaceholderText(tr("Filter ROS topics…"));
    filter->setClearButtonEnabled(true);
    v->addWidget(filter);
    m_rosView = new QTreeView(box);
    m_rosView->setObjectName(u"mapRosTopics"_s);
    m_rosView->setModel(m_rosFilter);
    m_rosView->setUniformRowHeights(true);
    m_rosView->setIndentation(12); // deep names keep room for their segments
    ViewSetup::dragsCopies(m_rosView);
    QHeaderView* header = m_rosView->header();
    header->setStretchLastSection(false);
    header->setSectionResizeMode(TopicTree::TopicColumn, QHeaderView::Stretch);
    header->setSectionResizeMode(TopicTree::TypeColumn, QHeaderView::Interactive);
    // The names get the panel's width; a type shows its last segment (whole in its tooltip).
    m_rosView->setColumnHidden(TopicTree::PublishersColumn, true);
    m_rosView->setColumnWidth(TopicTree::TypeColumn, 105); // `PointCloud2`, `PoseStamped` in bold
    v->addWidget(m_rosView, 1);
    connect(filter, &QLineEdit::textChanged, m_rosFilter, [this](const QString& text) {
        m_rosFilter->setFilterFixedString(text);
        if (!text.isEmpty())
            m_rosView->expandAll(); // what matched, shown
    });
    // Namespaces open as they appear, as the MQTT tree's levels: names read down the tree.
    connect(m_rosFilter, &QAbstractItemModel::rowsInserted, m_rosView,
            [this](const QModelIndex& parent, int first, int last) {
                for (int r = first; r <= last; ++r)
                    m_rosView->expand(m_rosFilter->index(r, 0, parent));
                if (parent.isValid())
                    m_rosView->expand(parent);
            });
    connect(m_rosFilter, &QAbstractItemModel::modelReset, m_rosView, &QTreeView::expandAll);
    m_rosView->expandAll();
    return box;
}

/// Discovered MQTT topics, the bridged ones marked.
QWidget* MapPage::createMqttPane()
{
    m_mqttBridged = new BridgedTopicsProxy(MqttTopicTree::FullTopicRole, this);
    m_mqttBridged->setSourceModel(m_parts.mqttTopics);
    m_mqttFilter = new MqttTopicFilter(this);
    m_mqttFilter->setSourceModel(m_mqttBridged);
    auto* mqttBox = new QWidget(this);
    auto* mv = new QVBoxLayout(mqttBox);
    mv->setContentsMargins(0, 0, 0, 0);
    auto* mqttFilterEdit = new QLineEdit(mqttBox);
    mqttFilterEdit->setPlaceholderText(tr("Filter MQTT topics…"));
    mqttFilterEdit->setClearButtonEnabled(true);
    mv->addWidget(mqttFilterEdit);
    m_mqttView = new QTreeView(mqttBox);
    m_mqttView->setObjectName(u"mapMqttTopics"_s);
    m_mqttView->setModel(m_mqttFilter);
    for (int c = 0; c < MqttTopicTree::ColumnCount; ++c)
        m_mqttView->setColumnHidden(c,
                                    c != MqttTopicTree::TopicColumn && c != MqttTopicTree::RateColumn
                                        && c != MqttTopicTree::RosTypeColumn);
    ViewSetup::topicTree(m_mqttView, MqttTopicTree::TopicColumn);
    ViewSetup::dragsCopies(m_mqttView);
    m_mqttView->setColumnWidth(MqttTopicTree::TopicColumn, 200);
    mv->addWidget(m_mqttView, 1);
    connect(mqttFilterEdit, &QLineEdit::textChanged, m_mqttFilter, &MqttTopicFilter::setText);
    return mqttBox;
}

/// Topics dropped on the mapping table, on the ROS table or on the MQTT tree become mappings.
void MapPage::setUpDrops()
{
    QTableView* table = m_editor->table();
    table->setAcceptDrops(true);
    table->setDragDropMode(QAbstractItemView::DropOnly);
    table->setDropIndicatorShown(true);
    table->setDragDropOverwriteMode(true);
    m_editor->model()->setDropHandler(
        [this](const QMimeData* data, int row) { return dropOnMappings(data, row); });
    m_parts.rosTopics->setDropHandler([this](const QMimeData* data, const QString& target) {
        return !bridgeMqttTopics(TopicMime::decode(data, TopicMime::mqttType()), target).isEmpty();
    });
    m_parts.ros2Topics->setDropHandler([this](const QMimeData* data, const QString& target) {
        return !bridgeMqttTopics(TopicMime::decode(data, TopicMime::mqttType()), target).isEmpty();
    });
    m_rosTree->setDropHandler([this](const QMimeData* data, const QString& target) {
        return !bridgeMqttTopics(TopicMime::decode(data, TopicMime::mqttType()), target).isEmpty();
    });
    m_parts.mqttTopics->setDropHandler([this](const QMimeData* data, const QString& target) {
        return !bridgeRosTopics(TopicMime::decode(data, TopicMime::rosType()), target).isEmpty();
    });
}

namespace {
MappingFactory::MqttFacts factsOf(const MqttTopicTree* tree, const QString& topic)
{
    MappingFactory::MqttFacts f;
    const auto info = tree->topicData().info(topic);
    if (!info)
        return f;
    f.seen = true;
    if (info->rosType)
        f.announcedType = info->rosType->name;
    if (const auto* h = tree->topicData().history(topic); h && !h->empty())
        f.lastPayload = h->back().payload;
    return f;
}
} // namespace

// mqtt_client keys ros2mqtt by ROS topic and mqtt2ros by MQTT topic: a second mapping of the same
// source would be dropped by it, so bridging an already bridged source moves its mapping instead
// (taking over the options proposed for the new destination, never removing any).
void MapPage::plan(Plan& p, const BridgeConfig& config, const Mapping& proposed)
{
    for (const Mapping& m : config.mappings) {
        if (m.direction != proposed.direction || m.sourceTopic() != proposed.sourceTopic())
            continue;
        Mapping moved = m;
        for (const QString& path : proposed.block.values.paths()) {
            if (!moved.isSet(path) || path == u"ros_topic"_s || path == u"mqtt_topic"_s)
                moved.block.values.copyFrom(proposed.block.values, path);
        }
        if (!moved.sameContent(m)) {
            p.before << m;
            p.after << moved;
        }
        return;
    }
    p.created << proposed;
}

QList<quint64> MapPage::apply(const Plan& p, const QString& description)
{
    QList<quint64> ids;
    if ((p.created.isEmpty() && p.after.isEmpty()) || m_doc->isReadOnly())
        return ids;
    m_undo->beginMacro(description);
    if (!p.after.isEmpty()) {
        m_undo->push(new ConfigCommands::EditMappings(m_doc, p.before, p.after, description));
        for (const Mapping& m : p.after)
            ids << m.id;
    }
    if (!p.created.isEmpty()) {
        auto* cmd = new ConfigCommands::InsertMappings(m_doc, m_doc->mappingCount(), p.created, description);
        m_undo->push(cmd);
        ids += cmd->ids();
    }
    m_undo->endMacro();
    m_editor->selectMappings(ids);
    updateHealth();
    return ids;
}

QList<quint64> MapPage::bridgeRosTopics(const QList<TopicMime::Topic>& topics, const QString& mqttTarget)
{
    const MqttTopicTree* tree = m_parts.mqttTopics;
    // One ROS topic on an MQTT topic without levels below it: exactly that topic. Otherwise the
    // target is a level the new topics go under; no target: the prefix.
    const bool exact = topics.size() == 1 && !mqttTarget.isEmpty() && tree->topicData().info(mqttTarget)
        && !tree->hasChildren(mqttTarget);
    const QString prefix = mqttTarget.isEmpty() ? m_prefix->text().trimmed() : mqttTarget;
    Plan p;
    for (const TopicMime::Topic& t : topics) {
        const QString mqtt = exact ? mqttTarget : MappingFactory::mqttTopicFor(t.name, prefix);
        plan(p, m_doc->config(),
             MappingFactory::ros2mqtt(t.name, t.rosType, mqtt, factsOf(tree, mqtt), m_doc->layout()));
    }
    const int n = int(p.created.size() + p.after.size());
    return apply(p,
                 n == 1 ? tr("Bridge %1 to MQTT").arg(topics.first().name)
                        : tr("Bridge %1 ROS topics to MQTT").arg(n));
}

QList<quint64> MapPage::bridgeMqttTopics(const QList<TopicMime::Topic>& topics, const QString& rosTarget)
{
    const MqttTopicTree* tree = m_parts.mqttTopics;
    const bool onNamespace = rosTarget.endsWith(u'/');
    const bool exact = topics.size() == 1 && !rosTarget.isEmpty() && !onNamespace;
    const QString ns = onNamespace ? rosTarget : QString();
    Plan p;
    for (const TopicMime::Topic& t : topics) {
        const QString ros = exact ? rosTarget : MappingFactory::rosTopicFor(t.name, ns);
        plan(p, m_doc->config(),
             MappingFactory::mqtt2ros(t.name, factsOf(tree, t.name), ros, m_doc->layout()));
    }
    const int n = int(p.created.size() + p.after.size());
    return apply(p,
                 n == 1 ? tr("Bridge %1 to ROS").arg(topics.first().name)
                        : tr("Bridge %1 MQTT topics to ROS").arg(n));
}

bool MapPage::retarget(quint64 mappingId, const QMimeData* data)
{
    const int row = m_doc->rowOf(mappingId);
    if (row < 0)
        return false;
    const Mapping before = m_doc->mapping(row);
    Mapping after = before;
    const QList<TopicMime::Topic> ros = TopicMime::decode(data, TopicMime::rosType());
    const QList<TopicMime::Topic> mqtt = TopicMime::decode(data, TopicMime::mqttType());
    if (!ros.isEmpty())
        after.set(u"ros_topic"_s, ros.first().name);
    else if (!mqtt.isEmpty())
        after.set(u"mqtt_topic"_s, mqtt.first().name);
    else
        return false;
    if (after.sameContent(before))
        return false;
    m_undo->push(new ConfigCommands::EditMappings(m_doc, {before}, {after},
                                                  !ros.isEmpty()
                                                      ? tr("Retarget to %1").arg(ros.first().name)
                                                      : tr("Retarget to %1").arg(mqtt.first().name)));
    m_editor->selectMappings({mappingId});
    updateHealth();
    return true;
}

bool MapPage::dropOnMappings(const QMimeData* data, int row)
{
    if (row >= 0 && row < m_doc->mappingCount())
        return retarget(m_doc->mapping(row).id, data);
    const QList<TopicMime::Topic> ros = TopicMime::decode(data, TopicMime::rosType());
    if (!ros.isEmpty())
        return !bridgeRosTopics(ros, QString()).isEmpty();
    return !bridgeMqttTopics(TopicMime::decode(data, TopicMime::mqttType()), QString()).isEmpty();
}

void MapPage::bridgeSelectedRos()
{
    QModelIndexList rows = m_rosView->selectionModel()->selectedRows();
    QModelIndexList sourceRows;
    for (const QModelIndex& i : std::as_const(rows))
        sourceRows << m_rosBridged->mapToSource(m_rosFilter->mapToSource(i));
    // A selected namespace bridges every topic below it, as when it is dragged.
    std::unique_ptr<QMimeData> data(m_rosTree->mimeData(sourceRows));
    const QList<TopicMime::Topic> topics
        = data ? TopicMime::decode(data.get(), TopicMime::rosType()) : QList<TopicMime::Topic>();
    const QModelIndex target = m_mqttView->currentIndex();
    bridgeRosTopics(topics,
                    target.isValid() && m_mqttView->selectionModel()->isSelected(target)
                        ? target.data(MqttTopicTree::FullTopicRole).toString()
                        : QString());
}

void MapPage::bridgeSelectedMqtt()
{
    QList<TopicMime::Topic> topics;
    QSet<QString> seen;
    for (const QModelIndex& i : m_mqttView->selectionModel()->selectedRows()) {
        const QString path = i.data(MqttTopicTree::FullTopicRole).toString();
        const QStringList below = i.data(MqttTopicTree::IsTopicRole).toBool()
            ? QStringList {path}
            : m_parts.mqttTopics->topicData().store().topicsBelow(path, 1000);
        for (const QString& t : below) {
            if (!seen.contains(t)) {
                seen.insert(t);
                topics.append({t, QString()});
            }
        }
    }
    const QModelIndex target = m_rosView->currentIndex();
    bridgeMqttTopics(topics,
                     target.isValid() && m_rosView->selectionModel()->isSelected(target)
                         ? target.data(TopicTree::PathRole).toString()
                         : QString());
}

void MapPage::updateBridgedTopics()
{
    QHash<QString, QString> ros, mqtt;
    for (const Mapping& m : m_doc->config().mappings) {
        const QString what = MappingModel::directionText(m.direction) + u": "_s + m.sourceTopic() + u" → "_s
            + m.destinationTopic();
        ros.insert(m.rosTopic(), what);
        mqtt.insert(m.mqttTopic(), what);
    }
    m_rosBridged->setBridged(ros);
    m_mqttBridged->setBridged(mqtt);
}

MapPage::~MapPage()
{
    // m_mqttMonitored ends its subscriptions itself (when the sources are still there)
}

void MapPage::monitorMappedMqttTopics()
{
    QSet<QString> topics;
    const auto add = [&](const BridgeConfig& config) {
        for (const Mapping& m : config.mappings)
            topics.insert(m.mqttTopic());
    };
    add(m_doc->config());
    for (int i = 0; m_files && i < m_files->openCount(); ++i)
        if (i != m_files->currentIndex())
            add(m_files->configOf(i));
    m_mqttMonitored.holdExactly(topics);
}

bool MapPage::usesRos2() const
{
    return m_doc->config().layout == ConfigLayout::Ros2 && m_parts.graphs->ros2Running();
}

void MapPage::updateHealth()
{
    const qint64 now = wallClockNs();
    // A config in the ROS 2 layout maps against the ROS 2 graph when the Discover page shows one.
    const bool ros2 = usesRos2();
    TopicTableModel* topics = ros2 ? m_parts.ros2Topics : m_parts.rosTopics;
    if (m_rosTree->sourceModel() != topics) {
        m_rosTree->setSourceModel(topics);
        m_flows.clear(); // other topics, other counts
        updateBridgedTopics();
    }
    const QHash<QString, TopicFigures> monitored = (ros2 ? m_parts.sources.ros2 : m_parts.sources.ros1)->figures(now);
    monitorMappedMqttTopics();
    const QHash<QString, TopicFigures> mqtt = m_parts.sources.mqtt->figures(now);
    // Both ends' counts at this one instant: the rates shown compare the same interval.
    m_flows.sample(now, monitored, mqtt);
    MappingHealthEvaluator::Inputs in;
    in.graph = ros2 ? &m_parts.ros2Topics->graph() : &m_parts.rosTopics->graph();
    in.rosReachable = ros2 || m_parts.graphs->ros1Reachable(); // ROS 2 has no master to miss
    in.ros2 = ros2 ? &m_parts.graphs->ros2Graph() : nullptr;
    in.monitored = &monitored;
    in.mqtt = &mqtt;
    in.mqttConnected = m_parts.mqtt->state() == MqttConnection::State::Connected;
    in.nowNs = now;
    in.flows = &m_flows;
    const QHash<quint64, MappingHealth> shown = MappingHealthEvaluator::evaluate(m_doc->config(), in);
    m_editor->model()->setHealth(shown);
    // The traps only the running lab shows go to the Problems list (issue 45).
    DiscoveryLints::Options lint;
    lint.target = m_doc->validationOptions().target;
    lint.discoveryServer = qEnvironmentVariable("ROS_DISCOVERY_SERVER");
    m_doc->setDiscoveryProblems(DiscoveryLints::check(m_doc->config(), in, lint));
    if (!m_tabs)
        return;
    for (int i = 0; i < m_files->openCount(); ++i)
        m_tabs->setHealth(i, i == m_files->currentIndex() ? shown
                                                          : MappingHealthEvaluator::evaluate(m_files->configOf(i), in));
}

void MapPage::setFileController(ConfigFileController* files)
{
    m_files = files;
    m_tabs = new ConfigTabs(files, this);
    static_cast<QVBoxLayout*>(layout())->insertWidget(0, m_tabs);
    connect(m_doc, &ConfigDocument::modifiedChanged, m_tabs, &ConfigTabs::refresh);
    connect(m_doc, &ConfigDocument::filePathChanged, m_tabs, &ConfigTabs::refresh);
    connect(files, &ConfigFileController::openConfigsChanged, this, &MapPage::updateHealth);
}
