// SPDX-License-Identifier: MIT
#include "demostart.h"

#include "app/cli/clioutput.h"
#include "app/gui/mainwindow.h"
#include "yaml/secrets.h"
#include "models/latencystatsmodel.h"
#include "latency/seriesid.h"
#include "mqtt/mqttprofile.h"
#include "session/measuresession.h"
#include "widgets/discover/discoverpage.h"
#include "widgets/links/linkspage.h"
#include "widgets/map/configfilecontroller.h"
#include "widgets/measure/measurepage.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QStatusBar>
#include <QTabWidget>
#include <QTimer>

using namespace Qt::StringLiterals;

namespace {
class Gui
{
    Q_DECLARE_TR_FUNCTIONS(Gui)
};
} // namespace

namespace DemoStart {

void start(MainWindow& window, DemoLab& lab, const DemoLab::Options& options,
           const std::function<void(const QString& error)>& done)
{
    auto* progress = new QWidget(&window);
    auto* layout = new QHBoxLayout(progress);
    layout->setContentsMargins(0, 0, 0, 0);
    auto* what = new QLabel(options.ros == 2 ? Gui::tr("Starting the demo lab: mosquitto…")
                                             : Gui::tr("Starting the demo lab: mosquitto and rosmaster…"),
                            progress);
    auto* bar = new QProgressBar(progress);
    bar->setRange(0, 0); // busy: how long the servers take is unknown
    bar->setMaximumWidth(120);
    layout->addWidget(what);
    layout->addWidget(bar);
    window.statusBar()->addPermanentWidget(progress);
    window.setWindowTitle(Gui::tr("Bridgescope — demo lab (starting)"));
    window.pages()->setCurrentWidget(window.measurePage());
    const auto finish = [&window, progress, done](const QString& error) {
        progress->deleteLater();
        if (!error.isEmpty())
            window.statusBar()->showMessage(Gui::tr("The demo lab did not start: %1").arg(error));
        done(error);
    };
    if (const Status launched = lab.launchServers(options); !launched) {
        QTimer::singleShot(0, &window, [finish, error = launched.error().toString()] { finish(error); });
        return;
    }
    auto* poll = new QTimer(&window);
    auto* since = new QElapsedTimer;
    since->start();
    QObject::connect(poll, &QTimer::timeout, &window, [&lab, poll, since, what, finish] {
        QString why;
        DemoLab::Poll state = lab.pollServers(&why);
        if (state == DemoLab::Poll::Waiting && since->elapsed() > 20000) {
            lab.stop();
            why = Gui::tr("the servers did not listen within 20 s");
            state = DemoLab::Poll::Failed;
        }
        if (state == DemoLab::Poll::Waiting)
            return;
        poll->deleteLater();
        delete since;
        if (state == DemoLab::Poll::Ready) {
            what->setText(Gui::tr("Starting the demo lab: bridges and nodes…"));
            if (const Status started = lab.startComponents(); !started) {
                finish(started.error().toString());
                return;
            }
        }
        finish(why);
    });
    poll->start(50);
}

void show(MainWindow& window, const DemoLab& lab)
{
    if (lab.ros() == 2) { // the window's ROS 2 participant joins the lab's domain, on this host
        window.discoverPage()->setRos2Options({lab.rosDomain(), true});
        window.discoverPage()->setRosGraphs(DiscoverPage::RosGraphs::Ros2);
    } else { // the lab's graph, whatever the last session showed (a ROS 2 list stayed empty)
        window.discoverPage()->setRosGraphs(DiscoverPage::RosGraphs::Ros1);
        window.discoverPage()->setRosMasterUri(lab.rosMasterUri());
    }
    window.discoverPage()->connectBroker(MqttProfile::fromUrl(lab.brokerUrl()));
    // Both ends on Map, a tab each, the vehicle's shown. The Links page watches both from the
    // start: the lab is the demo's own, started for this window, so watching changes no one's lab.
    window.linksPage()->watchWhenListed(lab.vehicleConfigPath());
    window.linksPage()->watchWhenListed(lab.cloudConfigPath());
    window.files()->openFile(lab.vehicleConfigPath());
    window.files()->openFile(lab.cloudConfigPath());
    window.files()->activate(0);
    // Where the lab's servers are (random ports), so that discover, watch or mosquitto_sub can be
    // pointed at it: on stderr, as `bridgescope demo` says it, and in the status bar.
    const QString broker = Secrets::urlWithoutCredentials(lab.brokerUrl());
    const QString where = lab.ros() == 2
        ? Gui::tr("demo lab (ROS 2, domain %1): broker %2").arg(lab.rosDomain()).arg(broker)
        : Gui::tr("demo lab: broker %1, ROS master %2").arg(broker, lab.rosMasterUri());
    CliOutput::err(where);
    auto* servers = new QLabel(where, &window);
    servers->setObjectName(u"demoServers"_s);
    servers->setTextInteractionFlags(Qt::TextSelectableByMouse);
    servers->setToolTip(Gui::tr("Point bridgescope discover, watch or mosquitto_sub at these; configs in %1")
                            .arg(lab.directory()));
    window.statusBar()->addPermanentWidget(servers); // not hidden by passing messages
    if (const Status loaded = window.measurePage()->loadPipeline(lab.pipelinePath()); !loaded)
        CliOutput::err(loaded.error().toString());
    window.pages()->setCurrentWidget(window.measurePage());
    // The paper's Fig. 5 view: detection, one-way communication and the total.
    window.measure()->statsModel()->setChecked(SeriesId::ofStage(5).toString(), true);
    window.measure()->statsModel()->setChecked(SeriesId::ofKind(SeriesKind::OneWay).toString(), true);
    window.setWindowTitle(Gui::tr("Bridgescope — demo lab"));
    auto* watch = new QTimer(&window);
    QObject::connect(watch, &QTimer::timeout, &window, [&window, &lab, watch] {
        if (lab.isRunning())
            return;
        watch->stop();
        window.statusBar()->showMessage(Gui::tr("The demo lab stopped: %1").arg(lab.failure()));
    });
    watch->start(2000);
    // Ctrl+C or SIGTERM close the window properly, so that the lab stops and cleans up.
    CliOutput::whenStopRequested(&window, [] { QCoreApplication::quit(); });
}

} // namespace DemoStart
