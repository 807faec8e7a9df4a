// SPDX-License-Identifier: MIT
// Startup (issue 32): from launching `bridgescope --demo --page measure` to a window that answers
// (the first turn of its event loop) and to the first complete sample on the Measure page, against
// `bridgescope --version` (starting the process: the dynamic linker, Qt, the libraries) in the same
// run. Each is the median of BENCH_RUNS launches (default 5). The times are read from the window's
// own debug lines (bridgescope.session), as they are written.
//
//   scripts/bench.sh bench_startup
#include "benchutil.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QProcess>
#include <QTemporaryDir>

using namespace Qt::StringLiterals;

namespace {

struct Launch
{
    double answersMs = -1;
    double firstSampleMs = -1;
};

/// One launch of the demo window: when it said it answers, and its first complete sample.
Launch launchDemo(const QString& home)
{
    QProcess p;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(u"QT_QPA_PLATFORM"_s, u"offscreen"_s);
    env.insert(u"QT_LOGGING_RULES"_s, u"bridgescope.session.debug=true"_s);
    env.insert(u"QT_MESSAGE_PATTERN"_s, u"%{message}"_s);
    env.insert(u"HOME"_s, home);
    env.insert(u"XDG_CONFIG_HOME"_s, home + u"/.config"_s);
    p.setProcessEnvironment(env);
    QElapsedTimer clock;
    clock.start();
    p.start(QStringLiteral(BRIDGESCOPE_BINARY), {u"--demo"_s, u"--page"_s, u"measure"_s});
    Launch l;
    QByteArray pending;
    while (l.firstSampleMs < 0 && clock.elapsed() < 60000 && p.state() != QProcess::NotRunning) {
        p.waitForReadyRead(20);
        pending += p.readAllStandardError();
        qsizetype end;
        while ((end = pending.indexOf('\n')) >= 0) {
            const QByteArray line = pending.left(end);
            pending.remove(0, end + 1);
            const double ms = double(clock.nsecsElapsed()) / 1e6;
            if (l.answersMs < 0 && line.contains("the window answers"))
                l.answersMs = ms;
            if (line.contains("first complete sample"))
                l.firstSampleMs = ms;
        }
    }
    p.terminate(); // the window ends its lab on SIGTERM
    if (!p.waitForFinished(15000)) {
        p.kill();
        p.waitForFinished();
    }
    return l;
}

double versionMs()
{
    QElapsedTimer clock;
    clock.start();
    QProcess p;
    p.start(QStringLiteral(BRIDGESCOPE_BINARY), {u"--version"_s});
    p.waitForFinished(30000);
    return double(clock.nsecsElapsed()) / 1e6;
}

double median(std::vector<double> v)
{
    return Bench::percentile(std::move(v), 0.5);
}

} // namespace

int main(int argc, char** argv)
{
    QCoreApplication app(argc, argv);
    const int runs = Bench::envInt("BENCH_RUNS", 5);
    QTemporaryDir home;
    std::vector<double> version, answers, first;
    versionMs(); // the first start reads the libraries from disk; the others are what a user sees
    for (int i = 0; i < runs; ++i) {
        version.push_back(versionMs());
        const Launch l = launchDemo(home.path());
        if (l.answersMs < 0 || l.firstSampleMs < 0) {
            std::fprintf(stderr, "launch %d: the window did not say it answers, or no sample came in 60 s\n", i + 1);
            return 1;
        }
        answers.push_back(l.answersMs);
        first.push_back(l.firstSampleMs);
    }
    const double v = median(version), a = median(answers), f = median(first);
    std::printf("# bench_startup: medians of %d launches\n", runs);
    std::printf("| measure | ms | / --version |\n| --- | ---: | ---: |\n");
    std::printf("| bridgescope --version (process start, the peer) | %.1f | 1.00 |\n", v);
    std::printf("| --demo: the window answers | %.1f | %.2f |\n", a, a / v);
    std::printf("| --demo: first complete sample on Measure | %.1f | %.2f |\n", f, f / v);
    Bench::gate("startup_window_answers_vs_version", a / v);
    Bench::gate("startup_first_sample_vs_version", f / v);
    return 0;
}
