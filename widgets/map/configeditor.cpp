// SPDX-License-Identifier: MIT
#include "configeditor.h"

#include "config/configdocument.h"
#include "config/mappingmodel.h"
#include "widgets/common/columnfitter.h"
#include "widgets/common/namedelegate.h"
#include "widgets/common/problemspanel.h"
#include "widgets/common/severityiconproxy.h"
#include "widgets/common/viewsetup.h"
#include "widgets/map/mappingfilterproxy.h"
#include "widgets/map/mappinginspector.h"
#include "widgets/map/settingsinspector.h"
#include "widgets/map/undocommands.h"
#include "widgets/map/yamlpreview.h"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QItemSelectionModel>
#include <QLabel>
#include <QLineEdit>
#include <QSet>
#include <QSplitter>
#include <QTableView>
#include <QTabWidget>
#include <QToolButton>
#include <QUndoStack>
#include <QVBoxLayout>

using namespace Qt::StringLiterals;

ConfigEditor::ConfigEditor(ConfigDocument* document, QUndoStack* undoStack, QWidget* parent)
    : QWidget(parent)
    , m_doc(document)
    , m_undo(undoStack)
    , m_model(new MappingModel(document, this))
    , m_icons(new SeverityIconProxy(MappingModel::SeverityRole, this))
    , m_filter(new MappingFilterProxy(this))
{
    // Edits in the table go through the undo stack like every other edit.
    m_model->setEditHandler([this](const Mapping& before, const Mapping& after) {
        m_undo->push(new ConfigCommands::EditMappings(m_doc, {before}, {after}, tr("Edit topic")));
    });
    m_icons->setSourceModel(m_model);
    m_icons->setHealthColumn(MappingModel::HealthColumn, MappingModel::HealthStateRole);
    m_filter->setObjectName(u"mappingFilterProxy"_s);
    m_filter->setSourceModel(m_icons);
    createActions();

    // The mapping table takes the page's width, so that its topics show whole; the inspector of
    // the selected mappings and the problems sit below it, side by side.
    // Made in reading order, which is the keyboard's.
    QWidget* mappings = createMappingPane();
    QWidget* inspector = createInspectorTabs();
    m_problems = new ProblemsPanel(document, this);
    auto* bottom = new QSplitter(Qt::Horizontal, this);
    bottom->setObjectName(u"inspectorSplit"_s);
    bottom->addWidget(inspector);
    bottom->addWidget(m_problems);
    bottom->setStretchFactor(0, 2);
    bottom->setStretchFactor(1, 1);
    ViewSetup::initialSizes(bottom, {600, 300});
    m_split = bottom;
    auto* outer = new QSplitter(Qt::Vertical, this);
    outer->setObjectName(u"editorSplit"_s);
    outer->addWidget(mappings);
    outer->addWidget(bottom);
    outer->setStretchFactor(0, 3);
    outer->setStretchFactor(1, 2);
    outer->setChildrenCollapsible(false);
    ViewSetup::initialSizes(outer, {360, 280});
    auto* v = new QVBoxLayout(this);
    v->setContentsMargins(0, 0, 0, 0);
    v->addWidget(outer);

    connect(m_table->selectionModel(), &QItemSelectionModel::selectionChanged, this, [this] {
        m_inspector->setMappings(selectedIds());
        updateActions();
    });
    // A freshly opened file shows its first mapping, so the inspector is never empty for nothing.
    connect(m_doc, &ConfigDocument::resetDone, this, [this] {
        if (m_doc->mappingCount() > 0)
            selectMappings({m_doc->mapping(0).id});
        showReadOnly();
    });
    connect(m_problems, &ProblemsPanel::mappingProblemActivated, this, &ConfigEditor::showMappingProblem);
    connect(m_problems, &ProblemsPanel::settingsProblemActivated, this, &ConfigEditor::showSettingsProblem);
    updateActions();
}

void ConfigEditor::createActions()
{
    m_addOut = new QAction(tr("Add ROS → MQTT Mapping"), this);
    m_addOut->setShortcut(QKeySequence(Qt::Key_Insert));
    m_addOut->setToolTip(tr("Bridge a ROS topic to MQTT (Insert)"));
    m_addOut->setIconText(tr("+ ROS → MQTT"));
    m_addIn = new QAction(tr("Add MQTT → ROS Mapping"), this);
    m_addIn->setShortcut(QKeySequence(Qt::SHIFT | Qt::Key_Insert));
    m_addIn->setToolTip(tr("Bridge an MQTT topic to ROS (Shift+Insert)"));
    m_addIn->setIconText(tr("+ MQTT → ROS"));
    m_delete = new QAction(tr("Delete Mappings"), this);
    m_delete->setShortcut(QKeySequence::Delete);
    m_delete->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    m_delete->setIconText(tr("Delete"));
    m_duplicate = new QAction(tr("Duplicate Mappings"), this);
    m_duplicate->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_D));
    connect(m_addOut, &QAction::triggered, this, [this] { addMapping(Direction::Ros2Mqtt); });
    connect(m_addIn, &QAction::triggered, this, [this] { addMapping(Direction::Mqtt2Ros); });
    connect(m_delete, &QAction::triggered, this, &ConfigEditor::deleteSelected);
    connect(m_duplicate, &QAction::triggered, this, &ConfigEditor::duplicateSelected);
}

/// The filter bar above the mapping table, the add and delete buttons below it.
QWidget* ConfigEditor::createMappingPane()
{
    auto* pane = new QWidget(this);
    auto* lv = new QVBoxLayout(pane);
    lv->setContentsMargins(0, 0, 0, 0);
    auto* bar = new QHBoxLayout;
    m_filterEdit = new QLineEdit(pane);
    m_filterEdit->setObjectName(u"mappingFilter"_s);
    m_filterEdit->setPlaceholderText(tr("Filter mappings (topic or option)…"));
    m_filterEdit->setClearButtonEnabled(true);
    m_filterEdit->setMinimumWidth(150);
    m_directionFilter = new QComboBox(pane);
    m_directionFilter->addItem(tr("Both directions"), int(MappingFilterProxy::AllDirections));
    m_directionFilter->addItem(MappingModel::directionText(Direction::Ros2Mqtt), int(Direction::Ros2Mqtt));
    m_directionFilter->addItem(MappingModel::directionText(Direction::Mqtt2Ros), int(Direction::Mqtt2Ros));
    m_onlyProblems = new QCheckBox(tr("With problems"), pane);
    connect(m_filterEdit, &QLineEdit::textChanged, m_filter, &MappingFilterProxy::setText);
    connect(m_directionFilter, &QComboBox::currentIndexChanged, this,
            [this] { m_filter->setDirection(m_directionFilter->currentData().toInt()); });
    connect(m_onlyProblems, &QCheckBox::toggled, m_filter, &MappingFilterProxy::setOnlyProblems);
    bar->addWidget(m_filterEdit, 1);
    bar->addWidget(m_directionFilter);
    bar->addWidget(m_onlyProblems);
    lv->addLayout(bar);
    m_table = new QTableView(pane);
    setUpTable();
    lv->addWidget(m_table, 1);
    // Adding and deleting below the table, so that the bars above leave the inspector its room.
    auto* actions = new QHBoxLayout;
    for (QAction* a : {m_addOut, m_addIn, m_delete}) {
        auto* b = new QToolButton(pane);
        b->setDefaultAction(a);
        b->setToolButtonStyle(Qt::ToolButtonTextOnly);
        actions->addWidget(b);
    }
    actions->addStretch(1);
    lv->addLayout(actions);
    return pane;
}

void ConfigEditor::setUpTable()
{
    m_table->setObjectName(u"mappingTable"_s);
    m_table->setModel(m_filter);
    // One line per mapping; long names give up their namespaces first (NameDelegate).
    ViewSetup::records(m_table);
    NameDelegate::install(m_table, MappingModel::RosTopicColumn);
    NameDelegate::install(m_table, MappingModel::MqttTopicColumn);
    m_table->setSortingEnabled(true);
    m_table->sortByColumn(-1, Qt::AscendingOrder); // file order until the user sorts
    m_table->setSelectionMode(QAbstractItemView::ExtendedSelection);
    m_table->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed);
    m_table->verticalHeader()->setDefaultSectionSize(m_table->fontMetrics().height() + 8);
    QHeaderView* header = m_table->horizontalHeader();
    header->setStretchLastSection(false);
    header->setSectionResizeMode(QHeaderView::Interactive);
    header->setSectionResizeMode(MappingModel::DirectionColumn, QHeaderView::ResizeToContents);
    // Health (both rates and the latency, `10.0 → 9.9 Hz · 1.6 ms`) and the options (`stamped,
    // QoS 0, suite stamps`: issue 40 read `st…ps`) are measured and never cut; the topics share
    // what they leave, never less than their last segments.
    auto* fitter = new ColumnFitter(m_table);
    fitter->figures({MappingModel::HealthColumn, MappingModel::OptionsColumn});
    fitter->fill({MappingModel::RosTopicColumn, MappingModel::MqttTopicColumn});
    m_table->addAction(m_delete);
    m_table->setContextMenuPolicy(Qt::ActionsContextMenu);
    m_table->addAction(m_duplicate);
}

/// The mapping and settings inspectors and the YAML preview.
QWidget* ConfigEditor::createInspectorTabs()
{
    m_tabs = new QTabWidget(this);
    m_tabs->setObjectName(u"inspectorTabs"_s);
    m_inspector = new MappingInspector(m_doc, m_undo, m_tabs);
    m_settings = new SettingsInspector(m_doc, m_undo, m_tabs);
    m_preview = new YamlPreview(m_doc, m_tabs);
    m_tabs->addTab(m_inspector, tr("&Mapping"));
    m_tabs->addTab(m_settings, tr("&Broker && client"));
    m_tabs->addTab(m_preview, tr("&YAML"));
    return m_tabs;
}

void ConfigEditor::setInspectorWidth(int width)
{
    const int total = std::max(m_split->width(), width + 200);
    m_split->setSizes({width, total - width});
}

void ConfigEditor::showReadOnly()
{
    // Nothing of a file open read-only can be edited: its text and error are on the YAML tab.
    const bool readOnly = m_doc->isReadOnly();
    m_inspector->setEnabled(!readOnly);
    m_settings->setEnabled(!readOnly);
    m_table->setEnabled(!readOnly);
    m_addOut->setEnabled(!readOnly);
    m_addIn->setEnabled(!readOnly);
    if (readOnly)
        m_tabs->setCurrentWidget(m_preview);
    updateActions();
}

QList<quint64> ConfigEditor::selectedIds() const
{
    QList<quint64> ids;
    const QModelIndexList rows = m_table->selectionModel()->selectedRows();
    for (const QModelIndex& index : rows)
        ids << index.data(MappingModel::MappingIdRole).value<quint64>();
    return ids;
}

void ConfigEditor::selectMappings(const QList<quint64>& ids)
{
    QItemSelection selection;
    for (quint64 id : ids) {
        QModelIndex index = viewIndex(id);
        if (!index.isValid()) { // hidden by the filter: show everything again
            m_filterEdit->clear();
            m_directionFilter->setCurrentIndex(0);
            m_onlyProblems->setChecked(false);
            index = viewIndex(id);
        }
        if (index.isValid())
            selection.select(index, index);
    }
    m_table->selectionModel()->select(selection,
                                      QItemSelectionModel::ClearAndSelect | QItemSelectionModel::Rows);
    if (!selection.isEmpty()) {
        m_table->selectionModel()->setCurrentIndex(selection.indexes().first(),
                                                   QItemSelectionModel::NoUpdate);
        m_table->scrollTo(selection.indexes().first());
    }
}

QModelIndex ConfigEditor::viewIndex(quint64 id) const
{
    return m_filter->mapFromSource(m_icons->mapFromSource(m_model->indexOfMapping(id)));
}

void ConfigEditor::addMapping(Direction direction)
{
    if (m_doc->isReadOnly())
        return;
    // Propose free names, so that a new mapping never collides with an existing one.
    QSet<QString> used;
    for (const Mapping& m : m_doc->config().mappings)
        used << m.rosTopic() << m.mqttTopic();
    int n = 1;
    while (used.contains(u"/new_topic_%1"_s.arg(n)) || used.contains(u"new_topic_%1"_s.arg(n)))
        ++n;
    const Mapping m = Mapping::create(direction, u"/new_topic_%1"_s.arg(n), u"new_topic_%1"_s.arg(n));
    m_undo->push(new ConfigCommands::InsertMappings(
        m_doc, m_doc->mappingCount(), {m},
        direction == Direction::Ros2Mqtt ? tr("Add ROS → MQTT mapping") : tr("Add MQTT → ROS mapping")));
    selectMappings({m.id});
    m_tabs->setCurrentWidget(m_inspector);
    m_inspector->focusField(direction == Direction::Ros2Mqtt ? u"ros_topic"_s : u"mqtt_topic"_s);
}

void ConfigEditor::deleteSelected()
{
    const QList<quint64> ids = selectedIds();
    if (ids.isEmpty())
        return;
    m_undo->push(new ConfigCommands::RemoveMappings(
        m_doc, ids, ids.size() == 1 ? tr("Delete mapping") : tr("Delete %1 mappings").arg(ids.size())));
}

void ConfigEditor::duplicateSelected()
{
    QList<Mapping> copies;
    int row = 0;
    for (quint64 id : selectedIds()) {
        Mapping copy = m_doc->mapping(m_doc->rowOf(id));
        row = std::max(row, m_doc->rowOf(id) + 1);
        copy.id = 0;
        copy.block.source = SourceMap();
        copies << copy;
    }
    if (copies.isEmpty())
        return;
    auto* cmd = new ConfigCommands::InsertMappings(
        m_doc, row, copies,
        copies.size() == 1 ? tr("Duplicate mapping") : tr("Duplicate %1 mappings").arg(copies.size()));
    m_undo->push(cmd);
    selectMappings(cmd->ids());
}

void ConfigEditor::showMappingProblem(quint64 id, const QString& field)
{
    selectMappings({id});
    m_tabs->setCurrentWidget(m_inspector);
    m_inspector->focusField(field);
}

void ConfigEditor::showSettingsProblem(OptionScope scope, const QString& field)
{
    m_tabs->setCurrentWidget(m_settings);
    m_settings->focusField(scope, field);
}

void ConfigEditor::updateActions()
{
    const bool any = m_table->selectionModel()->hasSelection() && !m_doc->isReadOnly();
    m_delete->setEnabled(any);
    m_duplicate->setEnabled(any);
}
