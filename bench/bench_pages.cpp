// SPDX-License-Identifier: MIT
// The window's CPU per page on the demo lab, against mosquitto_sub in the same run (issue 32).
//
// This process is the window: MainWindow and the demo lab started as `bridgescope --demo` starts
// them (DemoStart), the lab's servers, bridges and nodes in their own processes. After a warm-up
// it shows each page in turn and measures its own CPU time (every thread: Paho's, roscpp's, the
// GUI's) over a few seconds, then the Measure page again with Pause on. Before the lab, the window
// connected to a broker and a master of its own where nothing is published: what it costs when
// nothing changes at all (budget 1 %, as paused). The peer is mosquitto_sub
// subscribed to every topic of the same broker, measured over the same spans: what receiving the
// lab's traffic costs a process that does nothing else with it. The ratio is the gate's figure;
// the budgets are absolute (5 % of a core with Measure shown, 3 % on any other page, 1 % paused).
//
//   scripts/bench.sh bench_pages      (BENCH_WARMUP_S default 20, BENCH_SECONDS default 30 a page)
#include "app/gui/demostart.h"
#include "app/gui/mainwindow.h"
#include "benchutil.h"
#include "demo/demolab.h"
#include "mqtt/mqttprofile.h"
#include "testservers.h"
#include "viewhelpers.h"
#include "widgets/discover/discoverpage.h"
#include "widgets/measure/measurepage.h"

#include <memory>
#include <QAction>
#include <QHash>
#include <QApplication>
#include <QEventLoop>
#include <QProcess>
#include <QTabWidget>
#include <QTimer>
#include <QUrl>

using namespace Qt::StringLiterals;

namespace {

/// Runs the event loop for `ms` without a timer of its own beyond one (QTest::qWait wakes every 10 ms).
void idle(int ms)
{
    QEventLoop loop;
    QTimer::singleShot(ms, &loop, &QEventLoop::quit);
    loop.exec();
}

/// BENCH_PAINTS=1: counts the paint events of every widget, to say which ones a page repaints.
class PaintCounter : public QObject
{
public:
    QHash<QString, int> counts;

protected:
    bool eventFilter(QObject* watched, QEvent* event) override
    {
        if (event->type() == QEvent::Paint) {
            // the widget and its ancestors up to the first with a name: "QLabel < DetailPane < discoverPage"
            QStringList path;
            for (const QObject* o = watched; o; o = o->parent()) {
                path << (o->objectName().isEmpty() ? QString::fromLatin1(o->metaObject()->className())
                                                   : o->objectName());
                if (!o->objectName().isEmpty() || path.size() >= 5)
                    break;
            }
            ++counts[path.join(u" < "_s)];
        }
        return false;
    }
};

void printPaints(PaintCounter* counter, int seconds)
{
    if (!counter)
        return;
    QList<std::pair<int, QString>> top;
    for (auto it = counter->counts.cbegin(); it != counter->counts.cend(); ++it)
        top.append({it.value(), it.key()});
    std::sort(top.begin(), top.end(), std::greater<>());
    for (qsizetype i = 0; i < std::min<qsizetype>(top.size(), 8); ++i)
        std::printf("    paints/s %6.1f  %s\n", double(top[i].first) / seconds, qPrintable(top[i].second));
    counter->counts.clear();
}

struct Span
{
    double ownPercent = 0; ///< this process's CPU, % of one core
    double peerPercent = 0; ///< mosquitto_sub's
};

Span measure(qint64 peerPid, int seconds)
{
    const double own0 = Bench::cpuSeconds();
    const double peer0 = Bench::processCpuSeconds(peerPid);
    QElapsedTimer clock;
    clock.start();
    idle(seconds * 1000);
    const double wall = double(clock.nsecsElapsed()) / 1e9;
    return {100 * (Bench::cpuSeconds() - own0) / wall, 100 * (Bench::processCpuSeconds(peerPid) - peer0) / wall};
}

} // namespace

int main(int argc, char** argv)
{
    qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    const int warmup = Bench::envInt("BENCH_WARMUP_S", 20);
    const int seconds = Bench::envInt("BENCH_SECONDS", 30);

    MainWindow window;
    window.resize(1280, 800);
    window.show();
    window.pages()->setCurrentWidget(window.measurePage());
    // Nothing arriving: the window on a broker and a master of its own, quiet.
    double quietPercent = -1;
    {
        TestServers quiet;
        if (!quiet.startMosquitto() || !quiet.startRosMaster()) {
            std::fprintf(stderr, "cannot start the quiet servers: %s\n", qPrintable(quiet.errorString()));
            return 1;
        }
        window.discoverPage()->setRosMasterUri(quiet.rosMasterUri());
        window.discoverPage()->connectBroker(MqttProfile::fromUrl(quiet.brokerUrl()));
        idle(5000);
        const double own0 = Bench::cpuSeconds();
        QElapsedTimer span;
        span.start();
        idle(std::max(5, seconds / 2) * 1000);
        quietPercent = 100 * (Bench::cpuSeconds() - own0) / (double(span.nsecsElapsed()) / 1e9);
    }
    DemoLab lab;
    QString failed;
    bool started = false;
    DemoLab::Options options;
    options.program = QStringLiteral(BRIDGESCOPE_BINARY); // its bridges and nodes: `bridgescope bridge` ...
    DemoStart::start(window, lab, options, [&](const QString& error) {
        failed = error;
        started = error.isEmpty();
        if (started)
            DemoStart::show(window, lab);
    });
    QElapsedTimer clock;
    clock.start();
    while (!started && failed.isEmpty() && clock.elapsed() < 60000)
        idle(100);
    if (!started) {
        std::fprintf(stderr, "the demo lab did not start: %s\n", qPrintable(failed));
        return 1;
    }
    const QUrl broker(lab.brokerUrl());
    QProcess peer;
    peer.setStandardOutputFile(QProcess::nullDevice());
    peer.start(u"mosquitto_sub"_s, {u"-h"_s, broker.host(), u"-p"_s, QString::number(broker.port()), u"-t"_s,
                                    u"#"_s, u"-v"_s});
    if (!peer.waitForStarted()) {
        std::fprintf(stderr, "mosquitto_sub did not start\n");
        return 1;
    }
    idle(warmup * 1000);

    std::printf("# bench_pages: the window on the demo lab, %d s a page after %d s of warm-up\n", seconds, warmup);
    std::printf("| page | window CPU %% of a core | mosquitto_sub %% | ratio | budget %% |\n| --- | ---: | ---: | ---: | ---: |\n");
    const auto report = [](const QString& name, const Span& s, double budget) {
        // The gate's figure is the window's own CPU, "pages_<page>_cpu_percent": the peer's is a few
        // clock ticks (10 ms each) in a short run, too coarse to divide by.
        QByteArray gate = "pages_" + name.toLower().toUtf8() + "_cpu_percent";
        gate.replace(' ', '_').replace(',', "");
        Bench::gate(gate.constData(), s.ownPercent);
        std::printf("| %s | %.2f | %.2f | %.2f | %.0f |\n", qPrintable(name), s.ownPercent, s.peerPercent,
                    s.peerPercent > 0 ? s.ownPercent / s.peerPercent : 0.0, budget);
        std::fflush(stdout);
    };
    std::unique_ptr<PaintCounter> paints;
    if (qEnvironmentVariableIntValue("BENCH_PAINTS")) {
        paints = std::make_unique<PaintCounter>();
        app.installEventFilter(paints.get());
    }
    QTabWidget* pages = window.pages();
    for (int i = 0; i < pages->count(); ++i) {
        pages->setCurrentIndex(i);
        idle(2000); // the switch itself (layout, a first refresh) is not the steady state
        const bool measure = pages->widget(i) == window.measurePage();
        if (paints)
            paints->counts.clear();
        report(pages->tabText(i).remove(u'&'), ::measure(peer.processId(), seconds), measure ? 5 : 3);
        printPaints(paints.get(), seconds);
    }
    pages->setCurrentWidget(window.measurePage());
    ViewHelpers::named<QAction>(*window.measurePage(), u"pauseAction"_s)->setChecked(true);
    idle(2000);
    if (paints)
        paints->counts.clear();
    report(u"Measure, paused"_s, ::measure(peer.processId(), seconds), 1);
    printPaints(paints.get(), seconds);
    Bench::gate("pages_nothing_arriving_cpu_percent", quietPercent);
    std::printf("| Measure, nothing arriving (a quiet broker and master) | %.2f | – | – | 1 |\n", quietPercent);
    std::printf("window resident memory: %lld MiB\n", Bench::statusKb("VmRSS:") / 1024);
    peer.terminate();
    peer.waitForFinished(3000);
    return 0;
}
