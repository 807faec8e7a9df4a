// SPDX-License-Identifier: MIT
#include "mainwindow.h"

#include "app/gui/pageparts.h"
#include "files/regularfile.h"
#include "yaml/yamllimits.h"
#include "config/configdocument.h"
#include "config/problemmodel.h"
#include "mqtt/mqttconnection.h"
#include "ros/rosnode.h"
#include "session/livesession.h"
#include "session/measuresession.h"
#include "watch/livewatch.h"
#include "watch/watchsession.h"
#include "widgets/common/problemspanel.h"
#include "widgets/common/theme.h"
#include "widgets/common/windowmemory.h"
#include "widgets/discover/discoverpage.h"
#include "widgets/experiment/experimentpage.h"
#include "widgets/links/linkspage.h"
#include "widgets/map/configeditor.h"
#include "widgets/map/configfilecontroller.h"
#include "widgets/map/mappage.h"
#include "widgets/map/recentfiles.h"
#include "widgets/measure/measurepage.h"
#include "widgets/measure/runbar.h"
#include "widgets/reports/reportspage.h"
#include "widgets/tools/probedialog.h"

#include <functional>
#include <QAbstractButton>
#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QDialog>
#include <QFile>
#include <QFileInfo>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMenuBar>
#include <QMessageBox>
#include <QScreen>
#include <QSettings>
#include <QShortcut>
#include <QStatusBar>
#include <QTableWidget>
#include <QTabWidget>
#include <QTextBrowser>
#include <QTimer>
#include <QUndoStack>
#include <QVBoxLayout>

using namespace Qt::StringLiterals;

namespace {
/// Shows the window's one dialog named `name` (Help's guide, its shortcuts), made the first time
/// with `content` filling it; a second call brings it to the front.
void showToolWindow(QWidget* window, const QString& name, const QString& title, QSize size,
                    const std::function<QWidget*(QDialog*)>& content)
{
    auto* dialog = window->findChild<QDialog*>(name);
    if (!dialog) {
        dialog = new QDialog(window);
        dialog->setObjectName(name);
        dialog->setWindowTitle(title);
        auto* layout = new QVBoxLayout(dialog);
        layout->addWidget(content(dialog));
        dialog->resize(size);
    }
    dialog->show();
    dialog->raise();
    dialog->activateWindow();
}
} // namespace

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent)
    , m_live(new LiveWatch(LiveWatch::Measuring::Yes, this))
    , m_session(m_live->live())
    , m_measure(m_live->measure())
    , m_document(new ConfigDocument(this))
    , m_undo(new QUndoStack(this))
    , m_recent(new RecentFiles(this))
    , m_files(new ConfigFileController(m_document, m_undo, m_recent, this))
    , m_pages(new QTabWidget(this))
    , m_discover(new DiscoverPage(PageParts::discover(m_session), m_pages))
    , m_map(new MapPage(PageParts::map(m_session), m_document, m_undo, m_pages))
    , m_measurePage(new MeasurePage(m_measure, m_pages))
    , m_reports(new ReportsPage(m_pages))
    , m_watch(m_live->watch())
    , m_links(new LinksPage(m_watch, m_pages))
    , m_experiments(new ExperimentPage(m_pages))
    , m_configEditor(m_map->editor())
    , m_problemStatus(new QLabel(this))
{
    setObjectName(u"mainWindow"_s);
    m_undo->setObjectName(u"undoStack"_s);
    setAcceptDrops(true); // files dropped anywhere open where they belong (mainwindowfiles.cpp)
    // The topics' figures are read by eye: four times a second, not at every drain (a view repaints
    // and re-measures its rows at every change of them).
    m_session->setFiguresInterval(kFiguresMs);
    m_pages->setDocumentMode(true);
    m_pages->addTab(m_discover, tr("Discover"));
    m_pages->addTab(m_map, tr("Map"));
    m_pages->addTab(m_measurePage, tr("Measure"));
    m_pages->addTab(m_reports, tr("Reports"));
    m_pages->addTab(m_links, tr("Links"));
    m_pages->addTab(m_experiments, tr("Experiments"));
    m_map->setFileController(m_files); // a tab per open config
    watchTheMapConfig();
    // A finished recording is ready to report on; every run keeps the bridge config it ran with.
    connect(m_measurePage->runBar(), &RunBar::runRecorded, m_reports,
            [this](const QString& path) { m_reports->addInputs({path}); });
    // Measurements dropped on the Reports page open there, the one way files open (mainwindowfiles.cpp).
    connect(m_reports, &ReportsPage::measurementsDropped, this,
            [this](const QStringList& paths) { openAndReport(paths, Measurements::Compare); });
    // A finished cell of an experiment opens on the Measure page, as any run.
    connect(m_experiments, &ExperimentPage::openRunRequested, this, [this](const QString& path) {
        const Status opened = m_measurePage->runBar()->openRun(path);
        if (opened)
            m_pages->setCurrentWidget(m_measurePage);
        else if (const QString error = opened.error().toString(); !error.isEmpty())
            QMessageBox::warning(this, tr("Open Run"), error);
    });
    m_measurePage->runBar()->setBridgeConfigProvider([this]() -> std::pair<QString, QByteArray> {
        const QString path = m_document->filePath();
        if (path.isEmpty())
            return {};
        const Result<QByteArray> bytes = RegularFile::readHead(path, YamlLimits::maxBytes + 1);
        if (!bytes)
            return {};
        return {path, *bytes};
    });
    setCentralWidget(m_pages);
    statusBar()->addPermanentWidget(m_problemStatus);
    createMenus();

    connect(m_document, &ConfigDocument::modifiedChanged, this, &MainWindow::updateTitle);
    connect(m_document, &ConfigDocument::filePathChanged, this, &MainWindow::updateTitle);
    // Opening a config shows it.
    connect(m_document, &ConfigDocument::resetDone, this, [this] { m_pages->setCurrentWidget(m_map); });
    connect(m_files, &ConfigFileController::statusMessage, this,
            [this](const QString& message) { statusBar()->showMessage(message, 8000); });
    connect(m_recent, &RecentFiles::changed, this, &MainWindow::updateRecentMenu);
    connect(m_configEditor->problems()->model(), &ProblemModel::countsChanged, this,
            &MainWindow::updateProblemStatus);
    connect(m_session->mqtt(), &MqttConnection::stateChanged, this, &MainWindow::updateProblemStatus);
    m_problemStatus->setObjectName(u"problemStatus"_s);
    updateProblemStatus();
    updateTitle();
    // 1280x800, or a smaller screen's room.
    const QRect screen = this->screen() ? this->screen()->availableGeometry() : QRect(0, 0, 1280, 800);
    resize(std::min(1280, screen.width()), std::min(800, screen.height()));
}

/// The status bar's word on problems: the config's errors and warnings, and a broker that is
/// down (it never says "no problems" while the broker cannot be reached).
void MainWindow::updateProblemStatus()
{
    const ProblemModel* problems = m_configEditor->problems()->model();
    // A new config's one error is that it has no mapping yet: said as what to do, not as "1 error".
    const bool onlyEmpty = problems->rowCount() == 1 && problems->problem(0).code == u"no-mappings"_s;
    QString text = onlyEmpty ? tr("no mappings yet: add one (Insert) or drag topics onto each other")
                             : ProblemModel::countText(problems->errorCount(), problems->warningCount());
    const MqttConnection* mqtt = m_session->mqtt();
    const bool down
        = mqtt->state() == MqttConnection::State::Reconnecting || mqtt->state() == MqttConnection::State::Failed;
    if (down) {
        const QString broker = MqttProfile::withoutCredentials(mqtt->profile().url);
        const QString config = problems->errorCount() + problems->warningCount() > 0 && !onlyEmpty
            ? u" · "_s + text
            : QString();
        text = tr("broker %1 unreachable").arg(broker) + config;
    }
    m_problemStatus->setText(text);
    m_problemStatus->setToolTip(down ? mqtt->stateDetail() : QString());
}

void MainWindow::rememberSession()
{
    m_remember = true;
    QSettings settings;
    restoreGeometry(settings.value(u"window/geometry"_s).toByteArray());
    restoreState(settings.value(u"window/state"_s).toByteArray());
    WindowMemory::restore(this, settings, u"window/views"_s);
    Theme::apply(settings.value(u"ui/theme"_s, u"system"_s).toString());
    // The master last entered by hand, unless the environment names one (--ros-master wins over
    // both, applied after this).
    const QString master = settings.value(u"session/rosMaster"_s).toString();
    if (!master.isEmpty() && qEnvironmentVariableIsEmpty("ROS_MASTER_URI"))
        m_discover->setRosMasterUri(master);
    connect(m_discover, &DiscoverPage::rosMasterChosen, this,
            [](const QString& uri) { QSettings().setValue(u"session/rosMaster"_s, uri); });
    // The ROS graphs shown and the ROS 2 domain, as last chosen (ROS_DOMAIN_ID wins for the domain).
    const int graphs = settings.value(u"session/rosGraphs"_s, 0).toInt();
    if (graphs > 0 && graphs <= int(DiscoverPage::RosGraphs::Both)) {
        Ros2Options o = Ros2Options::fromEnvironment();
        if (qEnvironmentVariableIsEmpty("ROS_DOMAIN_ID"))
            o.domain = qBound(0, settings.value(u"session/ros2Domain"_s, 0).toInt(), Ros2Options::kMaxDomain);
        o.localhostOnly = o.localhostOnly || settings.value(u"session/ros2LocalhostOnly"_s, false).toBool();
        m_discover->setRos2Options(o);
        m_discover->setRosGraphs(DiscoverPage::RosGraphs(graphs));
    }
    connect(m_discover, &DiscoverPage::rosGraphsChosen, this,
            [](DiscoverPage::RosGraphs graphs, const Ros2Options& o) {
                QSettings settings;
                settings.setValue(u"session/rosGraphs"_s, int(graphs));
                settings.setValue(u"session/ros2Domain"_s, o.domain);
                settings.setValue(u"session/ros2LocalhostOnly"_s, o.localhostOnly);
            });
}

void MainWindow::saveSession() const
{
    QSettings settings;
    settings.setValue(u"window/geometry"_s, saveGeometry());
    settings.setValue(u"window/state"_s, saveState());
    WindowMemory::save(this, settings, u"window/views"_s);
}

MainWindow::~MainWindow()
{
    // Pages first, while the window is still whole: an open cell editor commits on destruction
    // and the edit reaches this window's slots.
    delete m_pages;
    // The connection closes when the session goes, after this window's part of it is gone.
    disconnect(m_session->mqtt(), nullptr, this, nullptr);
}

/// The Links page lists every config open on the Map page, as they are edited (a second after the
/// last edit, not at every keystroke); it watches those the user checks there, nothing else.
void MainWindow::watchTheMapConfig()
{
    auto* debounce = new QTimer(this);
    debounce->setSingleShot(true);
    debounce->setInterval(1000);
    connect(debounce, &QTimer::timeout, this, [this] {
        QList<WatchSession::Config> configs;
        for (int i = 0; i < m_files->openCount(); ++i) {
            const QString path = m_files->pathOf(i);
            const BridgeConfig config = m_files->configOf(i);
            if (path.isEmpty() && config.mappings.isEmpty())
                continue; // a blank new config has no links
            configs.append({path.isEmpty() ? tr("untitled") : QFileInfo(path).completeBaseName(),
                            path.isEmpty() ? QString() : QFileInfo(path).absoluteFilePath(), config});
        }
        m_links->setMapConfigs(configs);
    });
    connect(m_document, &ConfigDocument::resetDone, debounce, qOverload<>(&QTimer::start));
    connect(m_document, &ConfigDocument::problemsChanged, debounce, qOverload<>(&QTimer::start));
    connect(m_files, &ConfigFileController::openConfigsChanged, debounce, qOverload<>(&QTimer::start));
}

void MainWindow::createMenus()
{
    QMenu* file = menuBar()->addMenu(tr("&File"));
    file->addAction(tr("&New"), QKeySequence::New, m_files, &ConfigFileController::newFile);
    file->addAction(tr("&Open…"), QKeySequence::Open, this, &MainWindow::chooseFiles);
    m_recentMenu = file->addMenu(tr("Open &Recent"));
    updateRecentMenu(m_recent->files());
    file->addSeparator();
    file->addAction(tr("&Save"), QKeySequence::Save, m_files, &ConfigFileController::save);
    file->addAction(tr("Save &As…"), QKeySequence::SaveAs, m_files, &ConfigFileController::saveAs);
    file->addAction(tr("&Close Config"), QKeySequence::Close, this,
                    [this] { m_files->closeConfig(m_files->currentIndex()); });
    QMenu* exportMenu = file->addMenu(tr("&Export As"));
    exportMenu->addAction(tr("mqtt_client, ROS &1…"), this,
                          [this] { m_files->exportAs(ConfigLayout::Ros1); });
    exportMenu->addAction(tr("mqtt_client, ROS &2…"), this,
                          [this] { m_files->exportAs(ConfigLayout::Ros2); });
    exportMenu->addAction(tr("mqtt_&bridge…"), this, [this] { m_files->exportAs(ConfigLayout::MqttBridge); });
    file->addAction(tr("Generate &Peer Config…"), m_files, &ConfigFileController::generatePeer);
    file->addSeparator();
    file->addAction(tr("&Quit"), QKeySequence::Quit, this, &QWidget::close);

    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    QAction* undo = m_undo->createUndoAction(this, tr("&Undo"));
    undo->setShortcut(QKeySequence::Undo);
    QAction* redo = m_undo->createRedoAction(this, tr("&Redo"));
    redo->setShortcut(QKeySequence::Redo);
    edit->addAction(undo);
    edit->addAction(redo);
    edit->addSeparator();
    edit->addAction(m_configEditor->addRos2MqttAction());
    edit->addAction(m_configEditor->addMqtt2RosAction());
    edit->addAction(m_configEditor->duplicateAction());
    edit->addAction(m_configEditor->deleteAction());
    edit->addSeparator();
    edit->addAction(m_map->bridgeToMqttAction());
    edit->addAction(m_map->bridgeToRosAction());
    edit->addSeparator();
    edit->addAction(tr("&Find Mapping"), QKeySequence::Find, this, [this] {
        m_configEditor->filterEdit()->setFocus(Qt::ShortcutFocusReason);
        m_configEditor->filterEdit()->selectAll();
    });

    QMenu* view = menuBar()->addMenu(tr("&View"));
    for (int i = 0; i < m_pages->count(); ++i) {
        QAction* a = view->addAction(m_pages->tabText(i), this, [this, i] { m_pages->setCurrentIndex(i); });
        a->setShortcut(QKeySequence(Qt::ALT | Qt::Key(Qt::Key_1 + i)));
    }
    view->addSeparator();
    m_themeMenu = view->addMenu(tr("&Theme"));
    auto* themes = new QActionGroup(m_themeMenu);
    const QStringList labels {tr("&System"), tr("&Light"), tr("&Dark")};
    for (int i = 0; i < Theme::names().size(); ++i) {
        const QString name = Theme::names().at(i);
        QAction* a = m_themeMenu->addAction(labels.value(i), this, [this, name] {
            Theme::apply(name);
            if (m_remember)
                QSettings().setValue(u"ui/theme"_s, name);
        });
        a->setCheckable(true);
        a->setData(name);
        themes->addAction(a);
    }
    connect(m_themeMenu, &QMenu::aboutToShow, this, [this] {
        for (QAction* a : m_themeMenu->actions())
            a->setChecked(a->data().toString() == Theme::current());
    });

    QMenu* tools = menuBar()->addMenu(tr("&Tools"));
    QAction* probe = tools->addAction(tr("Link &Probe…"), this, [this] {
        auto* dialog = findChild<ProbeDialog*>();
        if (!dialog) {
            dialog = new ProbeDialog(this);
            if (m_session->mqtt()->state() != MqttConnection::State::Disconnected)
                dialog->setProfile(m_session->mqtt()->profile()); // the Discover page's broker
        }
        dialog->show();
        dialog->raise();
        dialog->activateWindow();
    });
    probe->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_P));

    QMenu* help = menuBar()->addMenu(tr("&Help"));
    help->addAction(tr("&User Guide"), QKeySequence::HelpContents, this, &MainWindow::showUserGuide);
    help->addAction(tr("&Keyboard Shortcuts"), this, &MainWindow::showShortcuts);
    help->addSeparator();
    help->addAction(tr("&About Bridgescope"), this,
                    [this] { QMessageBox::about(this, tr("About Bridgescope"), aboutText()); });
    help->addAction(tr("About &Qt"), qApp, &QApplication::aboutQt);
}

QString MainWindow::aboutText()
{
    return tr("<h3>Bridgescope %1</h3><p>Discover ROS and MQTT topics, bridge them with mqtt_client, and "
              "measure the link.</p><p>Built with Qt %2 (running %3), Paho MQTT C++ %4, yaml-cpp %5 and "
              "roscpp %6.</p><p>MIT License.</p>")
        .arg(QStringLiteral(BRIDGESCOPE_VERSION), QStringLiteral(QT_VERSION_STR),
             QString::fromLatin1(qVersion()), MqttConnection::pahoVersion(),
             QStringLiteral(BRIDGESCOPE_YAMLCPP_VERSION), RosNode::roscppVersion());
}

/// The user guide, bundled with the program, in a window of its own beside the main one.
void MainWindow::showUserGuide()
{
    showToolWindow(this, u"userGuide"_s, tr("Bridgescope User Guide"), QSize(900, 700), [](QDialog* dialog) {
        auto* text = new QTextBrowser(dialog);
        text->setOpenExternalLinks(true);
        QFile guide(u":/docs/user-guide.md"_s);
        if (guide.open(QIODevice::ReadOnly))
            text->setMarkdown(QString::fromUtf8(guide.readAll()));
        else
            text->setPlainText(tr("The user guide is missing from this build."));
        return text;
    });
}

/// Every shortcut of the window: its menus' actions, and the pages' buttons and shortcuts.
QList<std::pair<QString, QString>> MainWindow::shortcuts() const
{
    QList<std::pair<QString, QString>> out;
    const auto clean = [](QString text) { return text.remove(u'&').remove(u'…').trimmed(); };
    std::function<void(const QMenu*, const QString&)> walk = [&](const QMenu* menu, const QString& path) {
        for (const QAction* a : menu->actions()) {
            if (a->menu())
                walk(a->menu(), path + clean(a->text()) + u" › "_s);
            else if (!a->shortcut().isEmpty())
                out.append({path + clean(a->text()), a->shortcut().toString(QKeySequence::NativeText)});
        }
    };
    for (const QAction* a : menuBar()->actions())
        if (a->menu())
            walk(a->menu(), clean(a->text()) + u" › "_s);
    for (const QAbstractButton* b : findChildren<QAbstractButton*>())
        if (!b->shortcut().isEmpty() && !b->text().isEmpty())
            out.append(
                {tr("Button: %1").arg(clean(b->text())), b->shortcut().toString(QKeySequence::NativeText)});
    for (const QShortcut* s : findChildren<QShortcut*>())
        if (!s->key().isEmpty())
            out.append({s->whatsThis().isEmpty() ? s->objectName() : s->whatsThis(),
                        s->key().toString(QKeySequence::NativeText)});
    return out;
}

void MainWindow::showShortcuts()
{
    showToolWindow(this, u"shortcuts"_s, tr("Keyboard Shortcuts"), QSize(560, 600), [this](QDialog* dialog) {
        auto* table = new QTableWidget(dialog);
        table->setObjectName(u"shortcutTable"_s);
        table->setColumnCount(2);
        table->setHorizontalHeaderLabels({tr("Command"), tr("Shortcut")});
        table->verticalHeader()->setVisible(false);
        table->setEditTriggers(QAbstractItemView::NoEditTriggers);
        const auto list = shortcuts();
        table->setRowCount(int(list.size()));
        for (int i = 0; i < int(list.size()); ++i) {
            table->setItem(i, 0, new QTableWidgetItem(list[i].first));
            table->setItem(i, 1, new QTableWidgetItem(list[i].second));
        }
        table->resizeColumnsToContents();
        table->horizontalHeader()->setStretchLastSection(true);
        return table;
    });
}

void MainWindow::updateRecentMenu(const QStringList& files)
{
    m_recentMenu->clear();
    for (const QString& path : files) {
        m_recentMenu->addAction(QFileInfo(path).fileName() + u"  —  "_s + QFileInfo(path).absolutePath(),
                                this, [this, path] {
                                    // Later: opening renews this menu, and so deletes this action.
                                    QMetaObject::invokeMethod(
                                        this, [this, path] { openAndReport({path}); }, Qt::QueuedConnection);
                                });
    }
    m_recentMenu->setEnabled(!files.isEmpty());
}

void MainWindow::updateTitle()
{
    const QString path = m_document->filePath();
    const QString name = path.isEmpty() ? tr("Untitled") : QFileInfo(path).fileName();
    setWindowTitle(name + u"[*] — Bridgescope"_s);
    setWindowModified(m_document->isModified());
}

void MainWindow::closeEvent(QCloseEvent* event)
{
    if (m_experiments->isRunning()
        && QMessageBox::question(
               this, tr("Experiment running"),
               tr("An experiment is running. Stop it and quit? Resume goes on with it later."))
            != QMessageBox::Yes) {
        event->ignore();
        return;
    }
    if (!m_files->maybeSaveAll()) {
        event->ignore();
        return;
    }
    if (m_remember)
        saveSession();
    event->accept();
}
