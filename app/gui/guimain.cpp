// SPDX-License-Identifier: MIT
#include "guimain.h"

#include "app/cli/clioutput.h"
#include "app/gui/mainwindow.h"
#include "demo/demolab.h"
#include "experiment/experimentreport.h"
#include "latency/latencystatsmodel.h"
#include "latency/seriesid.h"
#include "mqtt/mqttprofile.h"
#include "session/measuresession.h"
#include "widgets/discover/discoverpage.h"
#include "widgets/experiment/experimentpage.h"
#include "widgets/links/linkspage.h"
#include "widgets/map/configfilecontroller.h"
#include "widgets/measure/measurepage.h"
#include "widgets/measure/runbar.h"

#include <optional>
#include <QApplication>
#include <QCommandLineParser>
#include <QIcon>
#include <QLibraryInfo>
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
        {u"--screenshot PNG"_s, Gui::tr("render the main window to PNG and exit")},
        {u"--after SECONDS"_s, Gui::tr("wait this long before the screenshot (default 1)")},
        {u"--pipeline PIPE.yaml"_s, Gui::tr("measure with this pipeline")},
        {u"--demo"_s, Gui::tr("start the embedded demo lab and show it")},
        {u"--page PAGE"_s, Gui::tr("open on a page: discover, map, measure, reports, links or experiments")},
        {u"--verbose"_s, Gui::tr("debug messages of every layer on stderr, also after a command")},
        {u"-h, --help"_s, Gui::tr("show this help")},
        {u"-v, --version"_s, Gui::tr("show the version")},
    };
    const QList<std::pair<QString, QString>> commands = {
        {u"config validate|convert|peer"_s, Gui::tr("check, convert and pair bridge configs")},
        {u"discover [--json]"_s, Gui::tr("list ROS and MQTT topics")},
        {u"bridge CONFIG.yaml"_s, Gui::tr("run a config as a reference bridge")},
        {u"probe [--sweep] [--echo]"_s, Gui::tr("round trips and throughput through the broker")},
        {u"demo [--seconds N]"_s, Gui::tr("the demo lab without a window")},
        {u"record --pipeline P -o RUN"_s, Gui::tr("record a measurement run")},
        {u"report INPUT... [--format F]"_s, Gui::tr("latency reports of runs, CSV files and bags")},
        {u"watch CONFIG.yaml... [--metrics H:P]"_s,
         Gui::tr("watch every bridged link for hours: events, metrics")},
        {u"experiment PLAN.yaml -o DIR"_s, Gui::tr("run an experiment matrix unattended, a run per cell")},
    };
    QString text
        = Gui::tr(
              "Usage: bridgescope [--broker URL] [--ros-master URI] [options] [FILE.yaml | EXPERIMENT-DIR]")
        + u'\n' + Gui::tr("       bridgescope <command> [options]") + u"\n\n"_s
        + Gui::tr("Discover ROS and MQTT topics, bridge them with mqtt_client, and measure the link.")
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
    QString brokerUrl; ///< as given, credentials included
    std::optional<MqttProfile> broker;
    QString masterUri; ///< empty: $ROS_MASTER_URI
    QString pipeline;
    int page = -1;
    bool demo = false;
    QStringList files;
};

/// Parses and checks the command line before anything starts. -1 to go on, otherwise the exit status.
int parseGui(const QStringList& arguments, GuiRequest* request)
{
    QCommandLineParser parser;
    const QCommandLineOption screenshot(u"screenshot"_s, Gui::tr("Render the main window to PNG and exit."),
                                        u"PNG"_s);
    const QCommandLineOption after(u"after"_s, Gui::tr("Seconds to wait before the screenshot."),
                                   u"SECONDS"_s, u"1"_s);
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
    parser.addOptions({screenshot, after, broker, master, pipeline, page, demo});
    parser.addPositionalArgument(u"FILE"_s, Gui::tr("Bridge config to open, or an experiment's folder."),
                                 u"[FILE.yaml|DIR]"_s);
    if (!parser.parse(arguments)) {
        CliOutput::err(parser.errorText());
        CliOutput::err(bridgescopeUsage());
        return ExitUsage;
    }
    request->screenshot = parser.value(screenshot);
    bool ok = false;
    request->screenshotAfter = parser.value(after).toDouble(&ok);
    if (!ok || request->screenshotAfter < 0) {
        CliOutput::err(Gui::tr("--after takes a number of seconds"));
        return ExitUsage;
    }
    if (parser.isSet(broker)) {
        request->brokerUrl = parser.value(broker);
        request->broker = MqttProfile::fromUrl(request->brokerUrl);
        QString error;
        if (!request->broker->validate(&error)) {
            CliOutput::err(error);
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
    request->masterUri = parser.value(master);
    request->pipeline = parser.value(pipeline);
    request->demo = parser.isSet(demo);
    request->files = parser.positionalArguments();
    return -1;
}

/// Shows the running demo lab: its servers, its vehicle config, the Measure page with the paper's
/// Fig. 5 series; says so when the lab stops, and quits on Ctrl+C so that the lab cleans up.
void showDemo(MainWindow& window, const DemoLab& lab)
{
    window.discoverPage()->setRosMasterUri(lab.rosMasterUri());
    window.discoverPage()->connectBroker(MqttProfile::fromUrl(lab.brokerUrl()));
    window.files()->openFile(lab.vehicleConfigPath());
    QString error;
    if (!window.linksPage()->addConfigFiles({lab.cloudConfigPath()}, &error)) // both bridges' links
        CliOutput::err(error);
    if (!window.measurePage()->loadPipeline(lab.pipelinePath(), &error))
        CliOutput::err(error);
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

/// Applies the servers, file, pipeline and page asked for; false after saying why not.
bool applyRequest(MainWindow& window, const GuiRequest& request)
{
    if (!request.masterUri.isEmpty())
        window.discoverPage()->setRosMasterUri(request.masterUri);
    if (request.broker)
        window.discoverPage()->connectBroker(*request.broker);
    if (!request.files.isEmpty() && ExperimentReport::isExperiment(request.files.first())) {
        QString error;
        if (!window.experimentPage()->openFolder(request.files.first(), &error)) {
            CliOutput::err(error);
            return false;
        }
        window.pages()->setCurrentWidget(window.experimentPage());
    } else if (!request.files.isEmpty() && request.files.first().endsWith(u".bsrun"_s, Qt::CaseInsensitive)) {
        // A run file (the desktop file's application/x-bridgescope-run) opens on the Measure page.
        QString error;
        if (!window.measurePage()->runBar()->openRun(request.files.first(), &error)) {
            if (!error.isEmpty()) // empty: cancelled
                CliOutput::err(error);
            return false;
        }
        window.pages()->setCurrentWidget(window.measurePage());
    } else if (!request.files.isEmpty()) {
        window.files()->openFile(request.files.first());
    }
    if (!request.pipeline.isEmpty()) {
        QString error;
        if (!window.measurePage()->loadPipeline(request.pipeline, &error)) {
            CliOutput::err(error);
            return false;
        }
        window.pages()->setCurrentWidget(window.measurePage());
    }
    if (request.page >= 0)
        window.pages()->setCurrentIndex(request.page);
    return true;
}

/// Saves the window as PNG after `seconds` and ends the program (1 when the file was not written).
void scheduleScreenshot(MainWindow& window, const QString& png, double seconds)
{
    QTimer::singleShot(int(seconds * 1000), &window, [&window, png] {
        const bool saved = window.grab().save(png);
        if (!saved)
            CliOutput::err(Gui::tr("Cannot write the screenshot %1").arg(png));
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
    if (request.demo) {
        lab = std::make_unique<DemoLab>();
        CliOutput::err(Gui::tr("starting the demo lab…"));
        DemoLab::Options options;
        options.brokerUrl = request.brokerUrl; // given servers are used instead of private ones
        options.rosMasterUri = request.masterUri;
        QString error;
        if (!lab->start(options, &error)) {
            CliOutput::err(Gui::tr("the demo lab did not start: %1").arg(error));
            return ExitFailed;
        }
    }
    MainWindow window;
    if (request.screenshot.isEmpty())
        window.rememberSession(); // a screenshot shows the window as it starts the first time
    if (lab)
        showDemo(window, *lab);
    if (!applyRequest(window, request))
        return ExitUsage;
    window.show();
    if (!request.screenshot.isEmpty())
        scheduleScreenshot(window, request.screenshot, request.screenshotAfter);
    return app.exec();
}
