// SPDX-License-Identifier: MIT
// The Measure page under load: ECDF chart updates with a million samples (against drawing the
// exact ECDF, every step a point), and the GUI event loop's lag while 10,000 stamp events a
// second arrive from a real rosmaster (against the same window idle).
//
//   scripts/bench.sh bench_measure     (BENCH_SECONDS, BENCH_EVENT_RATE override the load)
#include "app/gui/mainwindow.h"
#include "benchutil.h"
#include "latency/ecdf.h"
#include "latency/latencyengine.h"
#include "ros/rosstampsource.h"
#include "session/livesession.h"
#include "session/measuresession.h"
#include "syntheticrun.h"
#include "testservers.h"
#include "widgets/common/ecdfchart.h"
#include "widgets/discover/discoverpage.h"
#include "widgets/measure/measurepage.h"

#include <QApplication>
#include <QChart>
#include <QChartView>
#include <QElapsedTimer>
#include <QLineSeries>
#include <QProcess>
#include <QTabWidget>
#include <QTest>
#include <QTimer>
#include <QValueAxis>
#include <random>

using namespace Qt::StringLiterals;

namespace {

void chartUpdate()
{
    const int samples = 1'000'000;
    LatencyEngine engine(Pipeline({u"/vehicle/send"_s, u"/vehicle/done"_s}, 0)); // the whole run
    std::mt19937_64 rng(1);
    std::lognormal_distribution<double> latency(std::log(80.0), 0.1);
    qint64 t = 1'700'000'000LL * 1'000'000'000LL;
    const auto add = [&](int n) {
        for (int i = 0; i < n; ++i, t += 1'000'000)
            engine.addSample({t, t + qint64(latency(rng) * 1e6)});
    };
    QElapsedTimer fill;
    fill.start();
    add(samples);
    const double fillMs = double(fill.nsecsElapsed()) / 1e6;

    EcdfChart chart;
    chart.resize(1200, 700);
    chart.setSource(&engine.pipelineSeries());
    chart.setSeries({u"total"_s});
    chart.show();
    QTest::qWait(100);
    // 33 new samples per redraw: 1,000 samples a second at 30 redraws a second.
    std::vector<double> update;
    std::vector<double> render;
    for (int i = 0; i < 60; ++i) {
        add(33);
        QElapsedTimer u;
        u.start();
        chart.refresh();
        update.push_back(double(u.nsecsElapsed()) / 1e6);
        chart.views().first()->viewport()->repaint();
        render.push_back(double(u.nsecsElapsed()) / 1e6);
    }

    // Peer: the exact ECDF as a step line, every value a step (what plotting it naively costs).
    auto* peerChart = new QChart; // owned by the view
    QChartView peerView(peerChart);
    auto* series = new QLineSeries;
    peerChart->addSeries(series);
    auto* x = new QValueAxis;
    auto* y = new QValueAxis;
    peerChart->addAxis(x, Qt::AlignBottom);
    peerChart->addAxis(y, Qt::AlignLeft);
    series->attachAxis(x);
    series->attachAxis(y);
    const auto [lo, hi] = chart.range(u"total"_s);
    x->setRange(lo, hi);
    y->setRange(0, 1);
    peerView.resize(1200, 700);
    peerView.show();
    QTest::qWait(100);
    std::vector<double> peerUpdate;
    std::vector<double> peerRender;
    for (int i = 0; i < 5; ++i) {
        add(33);
        QElapsedTimer u;
        u.start();
        const LatencySeries& s = engine.series(engine.totalSeries());
        QList<QPointF> points;
        double previous = 0;
        for (const QPointF& step : Ecdf::steps(s)) {
            points.append(QPointF(step.x(), previous));
            points.append(step);
            previous = step.y();
        }
        series->replace(points);
        peerUpdate.push_back(double(u.nsecsElapsed()) / 1e6);
        peerView.viewport()->repaint();
        peerRender.push_back(double(u.nsecsElapsed()) / 1e6);
    }

    std::printf("chart: %d samples in the whole-run window (filled in %.0f ms), chart 1200x700\n\n", samples,
                fillMs);
    Bench::header("ms");
    Bench::row(u"peer: exact ECDF as a line, replace() (median of 5)"_s, Bench::percentile(peerUpdate, 0.5),
               u"%1 points"_s.arg(2 * engine.series(engine.totalSeries()).count()));
    Bench::row(u"peer: exact ECDF, replace() + repaint"_s, Bench::percentile(peerRender, 0.5));
    Bench::row(u"EcdfChart::refresh (reduce, one replace per curve), median"_s,
               Bench::percentile(update, 0.5),
               u"%1 points; %2x faster than the peer"_s.arg(chart.pointCount(u"total"_s))
                   .arg(Bench::percentile(peerUpdate, 0.5) / Bench::percentile(update, 0.5), 0, 'f', 0));
    Bench::row(u"EcdfChart::refresh, p90"_s, Bench::percentile(update, 0.9));
    Bench::row(u"refresh + repaint, median (goal < 16 ms)"_s, Bench::percentile(render, 0.5),
               u"%1x faster than the peer"_s.arg(
                   Bench::percentile(peerRender, 0.5) / Bench::percentile(render, 0.5), 0, 'f', 0));
    Bench::row(u"refresh + repaint, p90"_s, Bench::percentile(render, 0.9));
    std::printf("\n");
}

int guiLag()
{
    const int seconds = Bench::envInt("BENCH_SECONDS", 20);
    const int eventRate = Bench::envInt("BENCH_EVENT_RATE", 10000);
    TestServers servers;
    if (!servers.startRosMaster()) {
        std::fprintf(stderr, "cannot start rosmaster: %s\n", qPrintable(servers.errorString()));
        return 1;
    }
    servers.exportRosEnvironment();
    const SyntheticRun paper = SyntheticRun::paper(1, 0, 1);
    const int sampleRate = eventRate / int(paper.topics.size());
    const int samples = sampleRate * seconds;

    MainWindow window;
    window.resize(1500, 950);
    window.show();
    window.discoverPage()->setRosMasterUri(servers.rosMasterUri());
    window.pages()->setCurrentWidget(window.measurePage());
    Pipeline pipeline(paper.topics);
    const QStringList hosts = paper.hosts();
    for (int i = 0; i < paper.topics.size(); ++i)
        pipeline.setHost(paper.topics[i], hosts[i]);
    window.measure()->setPipeline(pipeline);
    window.measure()->setTimeoutNs(60'000'000'000LL);
    QTest::qWait(1500);

    // Peer: the same window with nothing arriving.
    QElapsedTimer idle;
    idle.start();
    const std::vector<double> idleLags = Bench::measureLag([&] { return idle.elapsed() < 5000; });

    QStringList args {u"--samples"_s,   QString::number(samples),
                      u"--rate"_s,      QString::number(sampleRate),
                      u"--jitter-us"_s, u"300"_s,
                      u"--seed"_s,      u"7"_s};
    const qint64 stageUs[] = {200, 300, 19000, 100, 3600, 43400, 100, 100, 19000, 100, 200};
    qint64 offset = 0;
    for (int i = 0; i < paper.topics.size(); ++i) {
        if (i > 0)
            offset += stageUs[i - 1];
        args << u"--stamp"_s
             << u"%1:%2"_s.arg(paper.topics[i]).arg(offset + (paper.remote[std::size_t(i)] ? 250'000 : 0));
    }
    QProcess publisher;
    publisher.setProcessEnvironment(servers.rosEnvironment());
    publisher.start(QStringLiteral(STAMP_PUBLISHER), args);
    // Measure from the first sample on.
    QElapsedTimer wait;
    wait.start();
    while (window.measure()->engine().samples() == 0 && wait.elapsed() < 30000)
        QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
    QElapsedTimer loaded;
    loaded.start();
    const std::vector<double> lags
        = Bench::measureLag([&] { return publisher.state() != QProcess::NotRunning; });
    const double loadSeconds = double(loaded.elapsed()) / 1000.0;
    QTest::qWait(1000);
    const LatencyEngine& e = window.measure()->engine();
    const quint64 received = window.measure()->rosSource()->received();

    std::printf("GUI lag: %d stamp events/s (%d samples/s of %lld stamps) for %d s from a rosmaster, Measure "
                "page open\n\n",
                eventRate, sampleRate, qlonglong(paper.topics.size()), seconds);
    Bench::header("value");
    Bench::row(u"stamp events published"_s, double(samples) * double(paper.topics.size()));
    Bench::row(u"stamp events received"_s, double(received),
               u"%1 events/s while loaded"_s.arg(double(received) / loadSeconds, 0, 'f', 0));
    Bench::row(u"complete samples"_s, double(e.samples()),
               u"dropped %1, in the buffer lost %2"_s.arg(e.counters().dropped())
                   .arg(window.measure()->rosSource()->dropped()));
    Bench::row(u"peer: idle window, event loop lag p50 (ms)"_s, Bench::percentile(idleLags, 0.5));
    Bench::row(u"peer: idle window, event loop lag p99 (ms)"_s, Bench::percentile(idleLags, 0.99));
    Bench::row(u"loaded, event loop lag p50 (ms)"_s, Bench::percentile(lags, 0.5));
    Bench::row(u"loaded, event loop lag p99 (ms)"_s, Bench::percentile(lags, 0.99), u"goal < 50 ms"_s);
    Bench::row(u"loaded, event loop lag max (ms)"_s,
               lags.empty() ? 0 : *std::max_element(lags.begin(), lags.end()));
    return 0;
}
} // namespace

int main(int argc, char** argv)
{
    qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    chartUpdate();
    return guiLag();
}
