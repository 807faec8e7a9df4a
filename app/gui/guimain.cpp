// SPDX-License-Identifier: MIT
#include "guimain.h"

#include "app/cli/clioutput.h"
#include "app/cli/rosoptions.h"
#include "app/gui/demostart.h"
#include "app/gui/mainwindow.h"
#include "base/logging.h"
#include "demo/demolab.h"
#include "fleet/prometheusclient.h"
#include "mqtt/mqttprofile.h"
#include "widgets/common/theme.h"
#include "widgets/discover/discoverpage.h"
#include "widgets/links/linkspage.h"
#include "widgets/map/configfilecontroller.h"
#include "widgets/measure/measurepage.h"

#include <optional>
#include <QApplication>
#include <QComboBox>
#include <QCommandLineParser>
#include <QIcon>
#include <QLibraryInfo>
#include <QMessageBox>
#include <QStatusBar>
#include <QTimer>
#include <QTranslator>

using namespace Qt::StringLiterals;
using CliOutput::ExitFailed;
using CliOutput::ExitUsage;

namespace {
class Gui
{
    Q_DECLARE_TR_FUNCTIONS(Gui)
};
} // namespace

void installTranslations(QCoreApplication& app)
{
    auto* ours = new QTranslator(&app);
    if (ours->load(QLocale(), u"bridgescope"_s, u"_"_s, u":/i18n"_s))
        app.installTranslator(ours);
    auto* qt = new QTranslator(&app);
    if (qt->load(QLocale(), u"qtbase"_s, u"_"_s, QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
        app.installTranslator(qt);
}

QString bridgescopeUsage()
{
    // One line per entry: a new option or command adds one string to translate, not a page.
    const QList<std::pair<QString, QString>> options = {
        {u"--broker URL"_s, Gui::tr("MQTT broker (tcp://host:1883, ssl://host:8883, mqtt://, mqtts://)")},
        {u"--ros-master URI"_s, Gui::tr("ROS master (default $ROS_MASTER_URI)")},
        {u"--ros 1|2|both"_s, Gui::tr("ROS graphs to show: ROS 1 (master), ROS 2 (DDS) or both")},
        {u"--ros-domain ID"_s, Gui::tr("ROS 2 domain (default $ROS_DOMAIN_ID, else 0)")},
        {u"--ros-localhost-only"_s, Gui::tr("ROS 2 discovery on this host only")},
        {u"--screenshot PNG"_s, Gui::tr("render the main window to PNG and exit")},
        {u"--after SECONDS"_s, Gui::tr("wait this long before the screenshot (default 1)")},
        {u"--remember"_s,
         Gui::tr("with --screenshot: start from the saved window and save it, as a user's start does")},
        {u"--pipeline PIPE.yaml"_s, Gui::tr("measure with this pipeline")},
        {u"--demo"_s, Gui::tr("start the embedded demo lab and show it")},
        {u"--page PAGE"_s, Gui::tr("open on a page: discover, map, measure, reports, links or experiments")},
        {u"--prometheus URL"_s,
         Gui::tr("the Links page shows every host's links from this Prometheus server")},
        {u"--theme THEME"_s, Gui::tr("colours: system (default), light or dark")},
        {u"--verbose"_s, Gui::tr("debug messages of every layer on stderr, also after a command")},
        {u"-h, --help"_s, Gui::tr("show this help")},
        {u"-v, --version"_s, Gui::tr("show the version")},
    };
    const QList<std::pair<QString, QString>> commands = {
        {u"config validate|convert|peer"_s, Gui::tr("check, convert and pair bridge configs")},
        {u"discover [--json] [--ros 2]"_s, Gui::tr("list ROS, ROS 2 and MQTT topics")},
        {u"bridge CONFIG.yaml"_s, Gui::tr("run a config as a reference bridge")},
        {u"probe [--sweep] [--echo]"_s, Gui::tr("round trips and throughput through the broker")},
        {u"clock serve|probe"_s, Gui::tr("answer clock probes; measure a far host's clock and its uncertainty")},
        {u"demo [--seconds N]"_s, Gui::tr("the demo lab without a window")},
        {u"record --pipeline P -o RUN"_s, Gui::tr("record a measurement run")},
        {u"report INPUT... [--format F]"_s, Gui::tr("latency reports of runs, CSV files and bags")},
        {u"watch CONFIG.yaml... [--metrics H:P]"_s,
         Gui::tr("watch every bridged link for hours: events, metrics")},
        {u"rules"_s, Gui::tr("print the Prometheus rules and alerts for watch --metrics")},
        {u"experiment PLAN.yaml -o DIR"_s, Gui::tr("run an experiment matrix unattended, a run per cell")},
    };
    QString text
        = Gui::tr("Usage: bridgescope [--broker URL] [--ros-master URI] [options] [FILE | EXPERIMENT-DIR]...")
        + u'\n' + Gui::tr("       bridgescope <command> [options]") + u"\n\n"_s
        + Gui::tr("Discover ROS and MQTT topics, bridge them with mqtt_client, and measure the link.")
        + u"\n\n"_s
        + Gui::tr("Files open where they belong: a bridge config on the Map page (more configs on Links), a "
                  "pipeline or one run, suite CSV or bag on Measure, several of those on Reports, an "
                  "experiment's folder on Experiments.")
        + u"\n\n"_s + Gui::tr("Options:") + u'\n';
    for (const auto& [name, what] : options)
        text += u"  "_s + name.leftJustified(20) + u' ' + what + u'\n';
    text += u'\n' + Gui::tr("Commands:") + u'\n';
    for (const auto& [name, what] : commands)
        text += u"  "_s + name.leftJustified(32) + u' ' + what + u'\n';
    return text + u'\n' + Gui::tr("Run 'bridgescope <command> --help' for the options of a command.");
}

namespace {
/// What the window's command line asks for.
struct GuiRequest
{
    QString screenshot; ///< empty: none
    double screenshotAfter = 1;
    bool session = false; ///< a screenshot run restores and saves the window as a user's start does
    QString brokerUrl; ///< as given, credentials included
    std::optional<MqttProfile> broker;
    QString masterUri; ///< empty: $ROS_MASTER_URI
    int rosGraphs = -1; ///< DiscoverPage::RosGraphs, -1: as last chosen
    int demoRos = 1; ///< the demo lab's ROS: 2 when only ROS 2 was chosen (--ros 2, the environment)
    int demoDomain = -1; ///< a ROS 2 demo lab's domain (--ros-domain), -1: a free one
    std::optional<Ros2Options> ros2;
    QString rosChoice; ///< which ROS graphs --ros or the environment chose and why; empty: none did
    QString pipeline;
    QString prometheus; ///< the fleet view's server (http or https, checked)
    int page = -1;
    bool demo = false;
    QString theme; ///< empty: the one last chosen (or the desktop's)
    QStringList files;
};

/// Parses and checks the command line before anything starts. -1 to go on, otherwise the exit status.
/// `notices`: also say which ROS graphs were chosen and why (not when only checking).
int parseGui(const QStringList& arguments, GuiRequest* request, bool notices = true)
{
    QCommandLineParser parser;
    // -demo is --demo, as Qt's own -platform
    parser.setSingleDashWordOptionMode(QCommandLineParser::ParseAsLongOptions);
    const QCommandLineOption screenshot(u"screenshot"_s, Gui::tr("Render the main window to PNG and exit."),
                                        u"PNG"_s);
    const QCommandLineOption after(u"after"_s, Gui::tr("Seconds to wait before the screenshot."),
                                   u"SECONDS"_s, u"1"_s);
    const QCommandLineOption remember(
        u"remember"_s, Gui::tr("With --screenshot: start from the saved window and save it on exit."));
    const QCommandLineOption broker(
        u"broker"_s, Gui::tr("MQTT broker to connect to (tcp://host:port, ssl://...)."), u"URL"_s);
    const QCommandLineOption master(u"ros-master"_s, Gui::tr("ROS master URI (default $ROS_MASTER_URI)."),
                                    u"URI"_s);
    const QCommandLineOption pipeline(
        u"pipeline"_s, Gui::tr("Measure with this pipeline (the suite's metrics-logger YAML)."),
        u"PIPE.yaml"_s);
    const QCommandLineOption page(
        u"page"_s, Gui::tr("Open on this page: discover, map, measure, reports, links or experiments."),
        u"PAGE"_s);
    const QCommandLineOption demo(u"demo"_s, Gui::tr("Start the embedded demo lab and show it."));
    const QCommandLineOption theme(u"theme"_s, Gui::tr("Colours: system (default), light or dark."),
                                   u"THEME"_s);
    const QCommandLineOption prometheus(
        u"prometheus"_s, Gui::tr("Show every host's links from this Prometheus server on the Links page."),
        u"URL"_s);
    parser.addOptions({screenshot, after, remember, broker, master, pipeline, page, demo, theme, prometheus});
    RosOptions ros;
    ros.addTo(parser);
    parser.addPositionalArgument(
        u"FILE"_s,
        Gui::tr("Bridge configs, pipelines, runs, suite CSVs, bags or experiment folders to open."),
        u"[FILE|DIR]..."_s);
    if (!parser.parse(arguments)) {
        CliOutput::err(CliOutput::parseError(parser, u"bridgescope"_s));
        return ExitUsage;
    }
    request->screenshot = parser.value(screenshot);
    request->session = request->screenshot.isEmpty() || parser.isSet(remember);
    bool ok = false;
    request->screenshotAfter = parser.value(after).toDouble(&ok);
    if (!ok || request->screenshotAfter < 0) {
        CliOutput::err(Gui::tr("--after takes a number of seconds"));
        return ExitUsage;
    }
    if (parser.isSet(broker)) {
        request->brokerUrl = parser.value(broker);
        request->broker = MqttProfile::fromUrl(request->brokerUrl);
        if (const Status valid = request->broker->validate(); !valid) {
            CliOutput::err(valid.error().toString());
            return ExitUsage;
        }
    }
    if (parser.isSet(page)) {
        const QStringList names {u"discover"_s, u"map"_s,   u"measure"_s,
                                 u"reports"_s,  u"links"_s, u"experiments"_s};
        request->page = int(names.indexOf(parser.value(page).toLower()));
        if (request->page < 0) {
            CliOutput::err(Gui::tr("--page takes one of: %1").arg(names.join(u", "_s)));
            return ExitUsage;
        }
    }
    request->prometheus = parser.value(prometheus);
    if (const auto url = PrometheusClient::checkUrl(request->prometheus); parser.isSet(prometheus) && !url) {
        CliOutput::err(url.error().toString());
        return ExitUsage;
    }
    request->theme = parser.value(theme);
    if (!request->theme.isEmpty() && !Theme::names().contains(request->theme)) {
        CliOutput::err(Gui::tr("--theme takes one of: %1").arg(Theme::names().join(u", "_s)));
        return ExitUsage;
    }
    if (const Status read = ros.read(parser); !read) {
        CliOutput::err(read.error().toString());
        return ExitUsage;
    }
    if (!ros.environmentWarning.isEmpty() && notices)
        CliOutput::err(ros.environmentWarning);
    request->demo = parser.isSet(demo);
    request->demoRos = ros.ros2 && !ros.ros1 ? 2 : 1;
    if (ros.graphsSet || ros.graphsFromEnvironment) {
        // A ROS 2 demo lab picks its own domain (the status bar says which).
        request->rosChoice = request->demo && request->demoRos == 2 && !ros.domainSet
            ? Gui::tr("ROS 2 (%1), the demo lab's domain").arg(ros.reason)
            : ros.choice();
        if (notices)
            CliOutput::err(request->rosChoice);
        request->rosGraphs = ros.ros1 && ros.ros2 ? 2 : (ros.ros2 ? 1 : 0);
    }
    if (ros.ros2OptionsSet)
        request->ros2 = ros.ros2Options;
    if (ros.domainSet)
        request->demoDomain = ros.ros2Options.domain;
    request->masterUri = parser.value(master);
    request->pipeline = parser.value(pipeline);
    request->files = parser.positionalArguments();
    return -1;
}

} // namespace

int checkGuiArguments(const QStringList& arguments)
{
    GuiRequest request;
    return parseGui(arguments, &request, false);
}

namespace {
/// Applies the servers, file, pipeline and page asked for; false after saying why not.
bool applyRequest(MainWindow& window, const GuiRequest& request)
{
    if (!request.masterUri.isEmpty())
        window.discoverPage()->setRosMasterUri(request.masterUri);
    if (request.ros2)
        window.discoverPage()->setRos2Options(*request.ros2);
    if (request.rosGraphs >= 0)
        window.discoverPage()->setRosGraphs(DiscoverPage::RosGraphs(request.rosGraphs));
    if (request.broker)
        window.discoverPage()->connectBroker(*request.broker);
    if (!request.rosChoice.isEmpty()) {
        window.discoverPage()->rosGraphsBox()->setToolTip(request.rosChoice);
        window.statusBar()->showMessage(request.rosChoice, 15000);
    }
    // What does not open is said, and the window opens with the rest (as a desktop's %F asks) and
    // a message box; a run for a screenshot ends instead (status 2), as a script wants.
    const bool automated = !request.screenshot.isEmpty();
    const QStringList errors
        = automated ? window.openPaths(request.files) : window.openAndReport(request.files);
    for (const QString& error : errors)
        CliOutput::err(error);
    if (automated && !errors.isEmpty())
        return false;
    if (!request.pipeline.isEmpty()) {
        if (const Status loaded = window.measurePage()->loadPipeline(request.pipeline); !loaded) {
            CliOutput::err(loaded.error().toString());
            return false;
        }
        window.pages()->setCurrentWidget(window.measurePage());
    }
    if (!request.prometheus.isEmpty())
        window.linksPage()->showFleet(request.prometheus);
    if (request.page >= 0)
        window.pages()->setCurrentIndex(request.page);
    return true;
}

/// Saves the window as PNG after `seconds` and ends the program (1 when the file was not written).
void scheduleScreenshot(MainWindow& window, const QString& png, double seconds, bool keep)
{
    QTimer::singleShot(int(seconds * 1000), &window, [&window, png, keep] {
        const bool saved = window.grab().save(png);
        if (!saved)
            CliOutput::err(Gui::tr("Cannot write the screenshot %1").arg(png));
        if (keep)
            window.saveSession(); // --remember: the next run starts from this one
        QCoreApplication::exit(saved ? 0 : 1);
    });
}
} // namespace

int runGui(int& argc, char** argv)
{
    QApplication app(argc, argv);
    QApplication::setWindowIcon(QIcon(u":/icons/bridgescope.svg"_s));
    // The installed desktop file's name (cmake/Packaging.cmake): Wayland shells find the icon by it.
    QGuiApplication::setDesktopFileName(u"io.github.bridgescope.Bridgescope"_s);
    installTranslations(app);
    GuiRequest request;
    if (const int status = parseGui(app.arguments(), &request); status >= 0)
        return status;
    // The demo lab outlives the window: its servers go last.
    std::unique_ptr<DemoLab> lab;
    MainWindow window;
    if (request.session)
        window.rememberSession(); // a screenshot shows the window as it starts the first time, unless --remember
    if (!request.theme.isEmpty())
        Theme::apply(request.theme);
    if (!request.demo && !applyRequest(window, request))
        return ExitUsage;
    window.show();
    // the first turn of the event loop: the window is up and answers (bench_startup reads it)
    QTimer::singleShot(0, &window, [] { qCDebug(lcSession) << "the window answers"; });
    if (request.demo) {
        // The window first, at once; the lab comes up behind it (a second or two).
        lab = std::make_unique<DemoLab>();
        CliOutput::err(Gui::tr("starting the demo lab…"));
        DemoLab::Options options;
        options.brokerUrl = request.brokerUrl; // given servers are used instead of private ones
        options.rosMasterUri = request.masterUri;
        options.ros = request.demoRos;
        options.rosDomain = request.demoDomain; // --ros-domain: this one instead of a free one
        const bool automated = !request.screenshot.isEmpty();
        DemoStart::start(window, *lab, options, [&window, &lab, &request, automated](const QString& error) {
            if (!error.isEmpty()) {
                CliOutput::err(Gui::tr("the demo lab did not start: %1").arg(error));
                if (automated)
                    QCoreApplication::exit(ExitFailed);
                else
                    QMessageBox::warning(&window, Gui::tr("Demo lab"),
                                         Gui::tr("The demo lab did not start: %1").arg(error));
                return;
            }
            DemoStart::show(window, *lab);
            GuiRequest rest = request;
            if (lab->ros() == 2)
                rest.ros2.reset(); // the lab's domain, on this host only, as show() joined it
            if (!applyRequest(window, rest))
                QCoreApplication::exit(ExitUsage);
        });
    }
    if (!request.screenshot.isEmpty())
        scheduleScreenshot(window, request.screenshot, request.screenshotAfter, request.session);
    return app.exec();
}
