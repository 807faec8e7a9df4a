// SPDX-License-Identifier: MIT
#include "discoverpage.h"

#include "models/mqtttopicfilter.h"
#include "models/mqtttopictree.h"
#include "mqtt/passwordstore.h"
#include "session/graphstatus.h"
#include "topics/topictablemodel.h"
#include "widgets/common/columnfitter.h"
#include "widgets/common/livetext.h"
#include "widgets/common/rostopicview.h"
#include "widgets/common/viewsetup.h"
#include "widgets/discover/detailpane.h"
#include "widgets/discover/publishdialog.h"
#include "widgets/tools/mqttprofiledialog.h"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QGridLayout>
#include <QHeaderView>
#include <QItemSelectionModel>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <QSignalBlocker>
#include <QSortFilterProxyModel>
#include <QSpinBox>
#include <QSplitter>
#include <QStyle>
#include <QTabBar>
#include <QTableView>
#include <QTabWidget>
#include <QTimer>
#include <QToolButton>
#include <QTreeView>
#include <QVBoxLayout>
#include <utility>

using namespace Qt::StringLiterals;

namespace {
const auto kLastProfile = "lastMqttProfile";

QString bullet(const QString& colour, const QString& text)
{
    return u"<span style=\"color:%1\">●</span> %2"_s.arg(colour, text.toHtmlEscaped());
}

/// A graph's line in the colour of its level.
QString bullet(const GraphStatus::Line& line)
{
    const QString& text = line.text;
    switch (line.level) {
    case GraphStatus::Level::Ok:
        return bullet(u"#2e7d32"_s, text);
    case GraphStatus::Level::Troubled:
        return bullet(u"#e65100"_s, text);
    case GraphStatus::Level::Failed:
        return bullet(u"#b00020"_s, text);
    case GraphStatus::Level::Idle:
        break;
    }
    return bullet(u"#888"_s, text);
}
} // namespace

DiscoverPage::DiscoverPage(const Parts& parts, QWidget* parent)
    : QWidget(parent)
    , m_parts(parts)
    , m_passwords(new PasswordStore(this))
{
    QLayout* bar = createConnectionBar();
    QWidget* rosBox = createRosPane();
    QWidget* mqttBox = createMqttPane();
    m_detail = new DetailPane(parts.detail, this);

    // The two lists side by side over the whole width (names, types and values are what people
    // read), the selected topic's detail below them: at 1280 px a third column left the lists
    // `/b…/t…/…cloud/…` and four characters of a value. Until a topic is selected the detail is
    // a line; the first selection opens it (selectTopic()).
    auto* lists = new QSplitter(Qt::Horizontal, this);
    lists->setObjectName(u"discoverLists"_s);
    lists->addWidget(rosBox);
    lists->addWidget(mqttBox);
    ViewSetup::initialSizes(lists, {50, 50});
    m_split = new QSplitter(Qt::Vertical, this);
    m_split->setObjectName(u"discoverSplit"_s);
    m_split->addWidget(lists);
    m_split->addWidget(m_detail);
    m_detail->setMinimumHeight(fontMetrics().height() * 3); // its title and tabs, until opened
    m_split->setStretchFactor(0, 1);
    m_split->setStretchFactor(1, 0);
    ViewSetup::initialSizes(m_split, {90, 10});
    auto* v = new QVBoxLayout(this);
    v->setContentsMargins(4, 4, 4, 0);
    v->addLayout(bar);
    v->addWidget(m_split, 1);

    createMqttActions();
    connectSelection();
    connectSession();
    reloadProfiles(QSettings().value(QLatin1String(kLastProfile)).toString());
    updateRosStatus();
    updateMqttStatus();
}

/// Where the ROS master and the broker are, and how they are doing.
QLayout* DiscoverPage::createConnectionBar()
{
    auto* bar = new QGridLayout;
    m_masterUri = new QLineEdit(m_parts.controls->rosMasterUri(), this);
    m_masterUri->setObjectName(u"masterUri"_s);
    m_masterUri->setToolTip(tr("ROS master URI; Enter applies it"));
    m_rosState = new QLabel(this);
    m_rosState->setObjectName(u"rosState"_s);
    auto* masterLabel = new QLabel(tr("ROS &master:"), this);
    masterLabel->setBuddy(m_masterUri);
    bar->addWidget(masterLabel, 0, 0);
    bar->addWidget(m_masterUri, 0, 1);
    bar->addWidget(m_rosState, 0, 2, 1, 3);
    connect(m_masterUri, &QLineEdit::returnPressed, this, [this] {
        setRosMasterUri(m_masterUri->text().trimmed());
        emit rosMasterChosen(m_parts.controls->rosMasterUri());
    });

    m_profileBox = new QComboBox(this);
    m_profileBox->setObjectName(u"profiles"_s);
    m_profileBox->setMinimumContentsLength(24);
    auto* brokerLabel = new QLabel(tr("MQTT &broker:"), this);
    brokerLabel->setBuddy(m_profileBox);
    auto* edit = new QToolButton(this);
    edit->setText(tr("Edit…"));
    edit->setToolTip(tr("Edit the connection profile (URL, TLS, credentials, subscriptions)"));
    auto* add = new QToolButton(this);
    add->setText(tr("New…"));
    m_connect = new QPushButton(tr("&Connect"), this);
    m_connect->setObjectName(u"connectButton"_s);
    connect(edit, &QToolButton::clicked, this, [this] { editProfile(false); });
    connect(add, &QToolButton::clicked, this, [this] { editProfile(true); });
    connect(m_connect, &QPushButton::clicked, this, &DiscoverPage::toggleConnection);
    m_mqttState = new QLabel(this);
    m_mqttState->setObjectName(u"mqttState"_s);
    m_mqttState->setWordWrap(true);
    bar->addWidget(brokerLabel, 1, 0);
    bar->addWidget(m_profileBox, 1, 1);
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(edit);
    buttons->addWidget(add);
    buttons->addWidget(m_connect);
    bar->addLayout(buttons, 1, 2);
    bar->addWidget(m_mqttState, 1, 3);
    m_counters = new LiveText(this); // four times a second: a QLabel would lay out the window again
    m_counters->setObjectName(u"counters"_s);
    bar->addWidget(m_counters, 1, 4);

    // ROS 2: which graphs, the domain, this host only
    m_graphsBox = new QComboBox(this);
    m_graphsBox->setObjectName(u"rosGraphs"_s);
    m_graphsBox->addItems({tr("ROS 1"), tr("ROS 2"), tr("ROS 1 and ROS 2")});
    m_graphsBox->setToolTip(
        tr("The ROS graphs to show: ROS 1 through its master, ROS 2 through DDS discovery "
           "(no ROS 2 install needed), or both as two tabs"));
    auto* graphsLabel = new QLabel(tr("ROS &graph:"), this);
    graphsLabel->setBuddy(m_graphsBox);
    m_domain = new QSpinBox(this);
    m_domain->setObjectName(u"ros2Domain"_s);
    m_domain->setRange(0, Ros2Options::kMaxDomain);
    m_domain->setPrefix(tr("domain "));
    m_domain->setToolTip(tr("ROS 2 domain id (ROS_DOMAIN_ID); Enter joins it"));
    m_localhostOnly = new QCheckBox(tr("this &host only"), this);
    m_localhostOnly->setObjectName(u"ros2LocalhostOnly"_s);
    m_localhostOnly->setToolTip(
        tr("Discover ROS 2 participants on 127.0.0.1 only, as ROS_LOCALHOST_ONLY=1 does"));
    QString envError;
    const Ros2Options env = Ros2Options::fromEnvironment(&envError);
    m_domain->setValue(env.domain);
    m_localhostOnly->setChecked(env.localhostOnly);
    m_ros2State = new QLabel(this);
    m_ros2State->setObjectName(u"ros2State"_s);
    m_ros2State->setWordWrap(true);
    auto* ros2Row = new QHBoxLayout;
    ros2Row->addWidget(m_domain);
    ros2Row->addWidget(m_localhostOnly);
    bar->addWidget(graphsLabel, 2, 0);
    bar->addWidget(m_graphsBox, 2, 1);
    bar->addLayout(ros2Row, 2, 2);
    bar->addWidget(m_ros2State, 2, 3, 1, 2);
    connect(m_graphsBox, &QComboBox::activated, this, [this](int index) {
        setRosGraphs(RosGraphs(index));
        emit rosGraphsChosen(m_graphs, ros2Options());
    });
    auto rejoin = [this] {
        applyRos2();
        emit rosGraphsChosen(m_graphs, ros2Options());
    };
    connect(m_domain, &QSpinBox::editingFinished, this, [this, rejoin] {
        if (m_parts.controls->isRos2Running() && m_parts.graphs->ros2Options().domain != m_domain->value())
            rejoin();
    });
    connect(m_localhostOnly, &QCheckBox::toggled, this, rejoin);
    if (!envError.isEmpty())
        m_ros2State->setToolTip(envError);

    bar->setColumnStretch(3, 1);
    bar->setColumnStretch(4, 1); // the counters: their room does not follow their digits
    return bar;
}

QWidget* DiscoverPage::createRosPane()
{
    auto* rosBox = new RosTopicView(m_parts.rosTopics, tr("Filter ROS topics or types…"), this);
    m_rosFilter = rosBox->filterEdit();
    m_rosFilter->setObjectName(u"rosFilter"_s);
    m_rosProxy = rosBox->proxy();
    m_rosView = rosBox->table();
    m_rosView->setObjectName(u"rosTopics"_s);
    m_rosView->setSelectionMode(QAbstractItemView::SingleSelection);

    auto* ros2Box = new RosTopicView(m_parts.ros2Topics, tr("Filter ROS 2 topics or types…"), this);
    ros2Box->filterEdit()->setObjectName(u"ros2Filter"_s);
    m_ros2View = ros2Box->table();
    m_ros2View->setObjectName(u"ros2Topics"_s);
    m_ros2View->setSelectionMode(QAbstractItemView::SingleSelection);

    // A topic's rate, bandwidth, size and age come from monitoring it: until one is, those
    // columns are empty, and their room goes to the names.
    for (auto [box, model] : {std::pair(rosBox, m_parts.rosTopics), std::pair(ros2Box, m_parts.ros2Topics)}) {
        const auto update = [table = box->table(), model = model] {
            for (int c : {TopicTableModel::RateColumn, TopicTableModel::BandwidthColumn,
                          TopicTableModel::SizeColumn, TopicTableModel::AgeColumn})
                table->setColumnHidden(c, model->monitoredCount() == 0);
        };
        connect(model, &TopicTableModel::monitorRequested, box, update);
        // and after the window's memory brought back an older session's columns
        connect(model, &QAbstractItemModel::rowsInserted, box, update);
        connect(model, &QAbstractItemModel::modelReset, box, update);
        update();
    }

    m_rosTabs = new QTabWidget(this);
    m_rosTabs->setObjectName(u"rosTabs"_s);
    m_rosTabs->setDocumentMode(true);
    m_rosTabs->addTab(rosBox, tr("ROS &1"));
    m_rosTabs->addTab(ros2Box, tr("ROS &2"));
    m_rosTabs->setTabVisible(1, false);
    m_rosTabs->tabBar()->hide();
    return m_rosTabs;
}

void DiscoverPage::setRosGraphs(RosGraphs graphs)
{
    m_graphs = graphs;
    {
        const QSignalBlocker block(m_graphsBox);
        m_graphsBox->setCurrentIndex(int(graphs));
    }
    m_rosTabs->setTabVisible(0, graphs != RosGraphs::Ros2);
    m_rosTabs->setTabVisible(1, graphs != RosGraphs::Ros1);
    m_rosTabs->tabBar()->setVisible(graphs == RosGraphs::Both);
    m_rosTabs->setCurrentIndex(graphs == RosGraphs::Ros2 ? 1 : 0);
    applyRos2();
}

void DiscoverPage::setRos2Options(const Ros2Options& options)
{
    {
        const QSignalBlocker block(m_localhostOnly);
        m_domain->setValue(options.domain);
        m_localhostOnly->setChecked(options.localhostOnly);
    }
    applyRos2();
}

Ros2Options DiscoverPage::ros2Options() const
{
    Ros2Options o;
    o.domain = m_domain->value();
    o.localhostOnly = m_localhostOnly->isChecked();
    return o;
}

/// Joins the chosen domain when a ROS 2 graph is shown, leaves it when none is.
void DiscoverPage::applyRos2()
{
    m_ros2Error.clear();
    if (m_graphs == RosGraphs::Ros1) {
        m_parts.controls->stopRos2();
    } else {
        const Ros2Options o = ros2Options();
        const Ros2Options now = m_parts.graphs->ros2Options();
        if (!m_parts.controls->isRos2Running() || now.domain != o.domain || now.localhostOnly != o.localhostOnly)
            if (const Status joined = m_parts.controls->startRos2(o); !joined)
                m_ros2Error = joined.error().toString();
    }
    const bool ros2 = m_graphs != RosGraphs::Ros1;
    m_domain->setEnabled(ros2);
    m_localhostOnly->setEnabled(ros2);
    updateRos2Status();
    updateRosStatus();
}

void DiscoverPage::updateRos2Status()
{
    if (m_graphs == RosGraphs::Ros1) {
        m_ros2State->clear();
        return;
    }
    if (!m_ros2Error.isEmpty()) {
        m_ros2State->setText(bullet(u"#b00020"_s, m_ros2Error));
        return;
    }
    const GraphStatus::Line line = m_parts.graphs->ros2Line();
    m_ros2State->setText(bullet(line));
    if (line.level != GraphStatus::Level::Failed)
        m_ros2State->setToolTip(line.toolTip);
}

QWidget* DiscoverPage::createMqttPane()
{
    auto* mqttBox = new QWidget(this);
    auto* mv = new QVBoxLayout(mqttBox);
    mv->setContentsMargins(0, 0, 0, 0);
    auto* filterRow = new QHBoxLayout;
    m_mqttFilter = new QLineEdit(mqttBox);
    m_mqttFilter->setObjectName(u"mqttFilter"_s);
    m_mqttFilter->setPlaceholderText(tr("Filter MQTT topics…"));
    m_mqttFilter->setClearButtonEnabled(true);
    m_searchPayloads = new QCheckBox(tr("in &payloads too"), mqttBox);
    filterRow->addWidget(m_mqttFilter, 1);
    filterRow->addWidget(m_searchPayloads);
    auto* publish = new QToolButton(mqttBox);
    publish->setObjectName(u"publishTool"_s);
    filterRow->addWidget(publish);
    mv->addLayout(filterRow);
    m_mqttProxy = new MqttTopicFilter(this);
    m_mqttProxy->setSourceModel(m_parts.mqttTopics);
    connect(m_mqttFilter, &QLineEdit::textChanged, m_mqttProxy, &MqttTopicFilter::setText);
    connect(m_searchPayloads, &QCheckBox::toggled, m_mqttProxy, &MqttTopicFilter::setSearchPayloads);
    m_mqttView = new QTreeView(mqttBox);
    m_mqttView->setObjectName(u"mqttTopics"_s);
    m_mqttView->setModel(m_mqttProxy);
    ViewSetup::topicTree(m_mqttView, MqttTopicTree::TopicColumn);
    setUpMqttColumns();
    mv->addWidget(m_mqttView, 1);
    // New top-level levels open, so that the first look shows more than a handful of roots.
    connect(m_mqttProxy, &QAbstractItemModel::rowsInserted, this,
            [this](const QModelIndex& parent, int first, int last) {
                if (parent.isValid())
                    return;
                for (int r = first; r <= last; ++r)
                    m_mqttView->expand(m_mqttProxy->index(r, 0));
            });
    return mqttBox;
}

/// The figures a lab reads first (messages, rate, bytes, QoS, retained) beside the topics, so that
/// they are seen without scrolling sideways; then the last value (MQTT Explorer's habit), the
/// announced ROS type and the latency.
void DiscoverPage::setUpMqttColumns()
{
    QHeaderView* header = m_mqttView->header();
    header->setStretchLastSection(false); // the room left goes to the values (ColumnFitter)
    header->setSectionResizeMode(QHeaderView::Interactive);
    for (int c : {MqttTopicTree::SizeColumn, MqttTopicTree::LastColumn})
        m_mqttView->setColumnHidden(c, true);
    const QList<int> order {
        MqttTopicTree::TopicColumn, MqttTopicTree::MessagesColumn, MqttTopicTree::RateColumn,
        MqttTopicTree::BytesColumn, MqttTopicTree::QosColumn,      MqttTopicTree::RetainedColumn,
        MqttTopicTree::ValueColumn, MqttTopicTree::RosTypeColumn,  MqttTopicTree::LatencyColumn};
    for (int i = 0; i < order.size(); ++i)
        header->moveSection(header->visualIndex(order[i]), i);
    // As the rows need: the figures whole as they grow (whatever was restored), the topics'
    // levels, then the values get what is left, then the ROS types.
    auto* fitter = new ColumnFitter(m_mqttView);
    fitter->figures({MqttTopicTree::MessagesColumn, MqttTopicTree::RateColumn, MqttTopicTree::BytesColumn,
                     MqttTopicTree::QosColumn, MqttTopicTree::RetainedColumn, MqttTopicTree::LatencyColumn});
    fitter->fit(MqttTopicTree::TopicColumn, 0.4);
    fitter->values({MqttTopicTree::ValueColumn});
    m_mqttView->setColumnWidth(MqttTopicTree::RosTypeColumn, 170); // after the values: scrolled to
}

void DiscoverPage::selectTopic()
{
    // The first selection opens a detail left as a line (a first start, or a session that never
    // selected anything); a detail the user made tall stays so.
    if (std::exchange(m_detailOpened, true))
        return;
    const QList<int> sizes = m_split->sizes();
    const int total = sizes.value(0) + sizes.value(1);
    if (total > 0 && sizes.value(1) < total / 3)
        m_split->setSizes({total - total * 2 / 5, total * 2 / 5});
}

/// Publish and clear retained messages: a button, the tree's context menu and keys.
void DiscoverPage::createMqttActions()
{
    m_publishAction = new QAction(tr("&Publish…"), this);
    m_publishAction->setObjectName(u"publishAction"_s);
    m_publishAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_P));
    m_publishAction->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    m_publishAction->setToolTip(tr("Publish a message to the selected topic (Ctrl+P)"));
    connect(m_publishAction, &QAction::triggered, this, &DiscoverPage::openPublishDialog);
    addAction(m_publishAction);
    m_clearRetainedAction = new QAction(tr("&Clear Retained…"), this);
    m_clearRetainedAction->setShortcut(QKeySequence::Delete);
    m_clearRetainedAction->setShortcutContext(Qt::WidgetShortcut);
    m_clearRetainedAction->setToolTip(
        tr("Delete the retained message of the selected topic, or of every topic under a level (Del)"));
    connect(m_clearRetainedAction, &QAction::triggered, this, &DiscoverPage::clearRetained);
    m_mqttView->addAction(m_publishAction);
    m_mqttView->addAction(m_clearRetainedAction);
    m_mqttView->setContextMenuPolicy(Qt::ActionsContextMenu);
    findChild<QToolButton*>(u"publishTool"_s)->setDefaultAction(m_publishAction);
}

PublishDialog* DiscoverPage::openPublishDialog()
{
    const QString topic = m_mqttView->currentIndex().data(MqttTopicTree::FullTopicRole).toString();
    auto* dialog = new PublishDialog(m_parts.mqtt, m_parts.mqttTopics, topic, this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->show();
    return dialog;
}

int DiscoverPage::clearRetained()
{
    const QModelIndex current = m_mqttView->currentIndex();
    if (!current.isValid())
        return 0;
    const QString path = current.data(MqttTopicTree::FullTopicRole).toString();
    const QStringList topics = m_parts.mqttTopics->topicData().retainedBelow(path);
    if (topics.isEmpty()) {
        QMessageBox::information(this, tr("Clear Retained"),
                                 tr("No retained message is known at or under %1.").arg(path));
        return 0;
    }
    const bool one = topics.size() == 1 && topics.first() == path;
    QMessageBox ask(QMessageBox::Question, tr("Clear Retained"),
                    one ? tr("Clear the retained message of %1? The broker deletes it; new subscribers "
                             "get nothing until the next retained message.")
                              .arg(path)
                        : tr("Clear the retained messages of %n topics at or under %1? The broker "
                             "deletes them all.",
                             nullptr, int(topics.size()))
                              .arg(path),
                    QMessageBox::Yes | QMessageBox::Cancel, this);
    ask.setObjectName(u"clearRetainedQuestion"_s);
    ask.setDefaultButton(QMessageBox::Cancel);
    if (!one)
        ask.setDetailedText(topics.mid(0, 200).join(u'\n') + (topics.size() > 200 ? u"\n…"_s : QString()));
    if (ask.exec() != QMessageBox::Yes)
        return 0;
    int cleared = 0;
    QString why;
    for (const QString& t : topics)
        cleared += m_parts.mqtt->publish(t, QByteArray(), 0, true, &why) ? 1 : 0;
    if (cleared < topics.size())
        QMessageBox::warning(
            this, tr("Clear Retained"),
            tr("%1 of %n retained messages were not cleared: %2", nullptr, int(topics.size()))
                .arg(topics.size() - cleared)
                .arg(why));
    return cleared;
}

/// The detail pane shows the topic selected on either side.
void DiscoverPage::connectSelection()
{
    connect(m_rosView->selectionModel(), &QItemSelectionModel::currentRowChanged, this,
            [this](const QModelIndex& i) {
                if (i.isValid()) {
                    m_detail->showRosTopic(i.data(TopicTableModel::TopicRole).toString());
                    selectTopic();
                }
            });
    connect(m_ros2View->selectionModel(), &QItemSelectionModel::currentRowChanged, this,
            [this](const QModelIndex& i) {
                if (i.isValid()) {
                    m_detail->showRos2Topic(i.data(TopicTableModel::TopicRole).toString());
                    selectTopic();
                }
            });
    connect(m_mqttView->selectionModel(), &QItemSelectionModel::currentRowChanged, this,
            [this](const QModelIndex& i) {
                if (i.isValid()) {
                    m_detail->showMqttTopic(i.data(MqttTopicTree::FullTopicRole).toString());
                    selectTopic();
                }
            });
}

void DiscoverPage::connectSession()
{
    connect(m_parts.graphs, &GraphStatus::ros1Changed, this, &DiscoverPage::updateRosStatus);
    connect(m_parts.graphs, &GraphStatus::ros2Changed, this, &DiscoverPage::updateRos2Status);
    connect(m_parts.mqtt, &MqttConnection::stateChanged, this, &DiscoverPage::updateMqttStatus);
    // The detail pane follows its topic a few times a second, not at the drain rate.
    auto* refresh = new QTimer(this);
    connect(refresh, &QTimer::timeout, m_detail, &DetailPane::refresh);
    connect(refresh, &QTimer::timeout, this, &DiscoverPage::updateMqttStatus);
    refresh->start(250);
    connect(m_passwords, &PasswordStore::stored, this, [this](const QString&, bool ok, const QString& error) {
        if (!ok)
            m_mqttState->setToolTip(tr("The password was not kept: %1").arg(error));
    });
}

void DiscoverPage::reloadProfiles(const QString& select)
{
    m_profiles = ProfileStore::load();
    if (m_profiles.isEmpty())
        m_profiles << MqttProfile();
    m_profileBox->clear();
    for (const MqttProfile& p : std::as_const(m_profiles))
        m_profileBox->addItem(p.name == p.url ? p.url : u"%1 (%2)"_s.arg(p.name, p.url));
    int index = 0;
    for (int i = 0; i < m_profiles.size(); ++i) {
        if (m_profiles[i].name == select)
            index = i;
    }
    m_profileBox->setCurrentIndex(index);
}

void DiscoverPage::editProfile(bool asNew)
{
    const int current = m_profileBox->currentIndex();
    MqttProfile start = asNew || current < 0 ? MqttProfile() : m_profiles.value(current);
    if (asNew)
        start.name = tr("broker %1").arg(m_profiles.size() + 1);
    MqttProfileDialog dialog(start, this);
    if (dialog.exec() != QDialog::Accepted)
        return;
    const MqttProfile p = dialog.profile();
    QList<MqttProfile> saved = ProfileStore::load();
    bool replaced = false;
    for (MqttProfile& s : saved) {
        if (s.name == (asNew ? p.name : start.name)) {
            s = p;
            replaced = true;
        }
    }
    if (!replaced)
        saved << p;
    ProfileStore::save(saved);
    if (dialog.rememberPassword() && !p.password.isEmpty())
        m_passwords->store(u"mqtt/"_s + p.name, p.password);
    reloadProfiles(p.name);
    connectBroker(p);
}

void DiscoverPage::toggleConnection()
{
    const MqttConnection::State s = m_parts.mqtt->state();
    if (s == MqttConnection::State::Disconnected || s == MqttConnection::State::Failed) {
        MqttProfile p = m_profiles.value(m_profileBox->currentIndex());
        if (!p.username.isEmpty() && p.password.isEmpty()) {
            // The password comes from the keyring, if it is there.
            auto conn = std::make_shared<QMetaObject::Connection>();
            *conn = connect(
                m_passwords, &PasswordStore::fetched, this,
                [this, p, conn](const QString&, const QString& password, bool ok, const QString&) mutable {
                    disconnect(*conn);
                    if (ok)
                        p.password = password;
                    connectBroker(p);
                });
            m_passwords->fetch(u"mqtt/"_s + p.name);
            return;
        }
        connectBroker(p);
    } else {
        m_parts.controls->disconnectBroker();
    }
}

void DiscoverPage::connectBroker(const MqttProfile& profile)
{
    QSettings().setValue(QLatin1String(kLastProfile), profile.name);
    // A broker given on the command line is shown like a saved profile.
    int index = -1;
    for (int i = 0; i < m_profiles.size(); ++i) {
        if (m_profiles[i].name == profile.name)
            index = i;
    }
    if (index < 0) {
        m_profiles << profile;
        m_profileBox->addItem(profile.name == profile.url ? profile.url
                                                          : u"%1 (%2)"_s.arg(profile.name, profile.url));
        index = int(m_profiles.size()) - 1;
    } else {
        m_profiles[index] = profile;
    }
    m_profileBox->setCurrentIndex(index);
    m_parts.mqttTopics->clear();
    m_parts.controls->connectBroker(profile);
    updateMqttStatus();
}

void DiscoverPage::setRosMasterUri(const QString& uri)
{
    m_masterUri->setText(uri);
    m_parts.controls->setRosMasterUri(uri);
    m_rosState->setText(bullet(u"#888"_s, tr("asking %1…").arg(uri)));
}

void DiscoverPage::updateRosStatus()
{
    m_masterUri->setEnabled(m_graphs != RosGraphs::Ros2);
    if (m_graphs == RosGraphs::Ros2)
        m_rosState->setText(bullet(u"#888"_s, tr("not shown (ROS 2 only)")));
    else
        m_rosState->setText(bullet(m_parts.graphs->ros1Line()));
}

void DiscoverPage::updateMqttStatus()
{
    const MqttConnection* c = m_parts.mqtt;
    const MqttConnection::State s = c->state();
    QString colour = u"#888"_s;
    if (s == MqttConnection::State::Connected)
        colour = u"#2e7d32"_s;
    else if (s == MqttConnection::State::Reconnecting || s == MqttConnection::State::Connecting)
        colour = u"#e08e00"_s;
    else if (s == MqttConnection::State::Failed)
        colour = u"#b00020"_s;
    const QString detail = c->stateDetail();
    QString text = MqttConnection::stateText(s);
    if (s == MqttConnection::State::Connected)
        text += u' ' + c->profile().url;
    else if (!detail.isEmpty())
        text += u": "_s + detail;
    m_mqttState->setText(bullet(colour, text));
    const bool idle = s == MqttConnection::State::Disconnected || s == MqttConnection::State::Failed;
    m_connect->setText(idle ? tr("&Connect") : tr("Dis&connect"));
    const MqttTopicTree* t = m_parts.mqttTopics;
    QStringList parts {tr("%1 topics").arg(t->topicData().store().topicCount()),
                       tr("%1 messages").arg(c->received())};
    if (c->dropped())
        parts << tr("%1 dropped").arg(c->dropped());
    if (t->topicData().checks().malformedTypeAnnouncements() || t->topicData().checks().malformedPayloads())
        parts << tr("%1 malformed")
                     .arg(t->topicData().checks().malformedTypeAnnouncements()
                          + t->topicData().checks().malformedPayloads());
    if (const int unknown = t->topicData().checks().unknownTypeTopics())
        parts << tr("%n topic(s) of an unknown ROS 2 type", nullptr, unknown);
    if (const quint64 evicted = t->topicData().store().evictedPayloads())
        parts << tr("%1 payloads evicted from the history (budget %2 MiB)")
                     .arg(evicted)
                     .arg(t->topicData().store().historyBudget() / (1024 * 1024));
    if (const quint64 untracked = t->topicData().store().untrackedMessages())
        parts << tr("%1 messages on topics not tracked (budget %2 topics, %3 MiB of names)")
                     .arg(untracked)
                     .arg(t->topicData().store().topicBudget())
                     .arg(t->topicData().store().structureBudget() / (1024 * 1024));
    m_counters->setText(parts.join(u" · "_s));
}
