// SPDX-License-Identifier: MIT
// Issue 43, points 3 and 4: an experiment plan whose cloud side is another host. The controller
// (`bridgescope experiment`) runs inside the vehicle's namespace of the two-host lab and starts the
// cloud's bridge, object detection and clock service inside the cloud's namespace over ssh; the way
// there (vehicle towards the broker) is 10 ms longer than the way back (`there_extra_ms`). Checked:
// the cloud's programs ran in the cloud's namespace and nothing of them is left (processes, their
// folder there); the report equals numpy on the run's raw stamps; half the round trip misattributes
// 5 ms and the one-way figures corrected by the measured clocks do not. Skipped, with the reason
// printed, where the machine cannot make namespaces.
#include "demo/demolab.h"
#include "pythonref.h"
#include "signalprocess.h"
#include "twohostlab.h"

#include <csignal>
#include <QDir>
#include <QFile>
#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QSet>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

using namespace Qt::StringLiterals;

namespace {
/// The command lines of the processes inside a namespace, each as its words joined by spaces.
QStringList commandLines(const QList<qint64>& pids)
{
    QStringList lines;
    for (const qint64 pid : pids) {
        QFile f(u"/proc/%1/cmdline"_s.arg(pid));
        if (f.open(QIODevice::ReadOnly))
            lines << QString::fromLocal8Bit(f.readAll()).replace(QChar(0), u' ').trimmed();
    }
    return lines;
}

QSet<QString> labFolders()
{
    const QStringList names = QDir(u"/tmp"_s).entryList({u"bridgescope-lab-*"_s}, QDir::Dirs);
    return QSet<QString>(names.begin(), names.end());
}

struct Ran
{
    int exit = -1;
    QString out;
    QString err;
};

Ran bridgescope(const QStringList& args)
{
    QProcess p;
    p.start(QStringLiteral(BRIDGESCOPE_BINARY), args);
    Ran r;
    if (p.waitForFinished(120000))
        r.exit = p.exitCode();
    r.out = QString::fromUtf8(p.readAllStandardOutput());
    r.err = QString::fromUtf8(p.readAllStandardError());
    return r;
}
const auto same = PythonRef::sameStats;
} // namespace

class TestTwoHostExperiment : public QObject
{
    Q_OBJECT
    TwoHostLab m_lab;
    QTemporaryDir m_dir;

    /// Starts bridgescope with `args` inside the vehicle's namespace, its ssh the lab's.
    bool startInVehicle(QProcess& p, const QStringList& args)
    {
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert(u"BRIDGESCOPE_SSH"_s, m_lab.sshProgram(TwoHostLab::Vehicle));
        p.setProcessEnvironment(env);
        const QStringList argv
            = m_lab.inNamespace(TwoHostLab::Vehicle, QStringList {QStringLiteral(BRIDGESCOPE_BINARY)} + args);
        p.start(argv.first(), argv.mid(1));
        return p.waitForStarted(5000);
    }

private slots:
    void initTestCase() { TWOHOSTLAB_UP_OR_SKIP(m_lab); }

    void aPlanRunsItsCloudOnTheCloudsHost_data()
    {
        QTest::addColumn<int>("ros");
        QTest::newRow("ROS 1") << 1;
        QTest::newRow("ROS 2") << 2;
    }
    void aPlanRunsItsCloudOnTheCloudsHost()
    {
        QFETCH(int, ros);
        const QString planPath = m_dir.filePath(u"two-hosts.yaml"_s);
        QFile plan(planPath);
        QVERIFY(plan.open(QIODevice::WriteOnly));
        plan.write(u"name: two hosts\nros: %2\nsamples: 150\nwarmup: 10\n"
                   "defaults: {payload: 2000, rate_hz: 20, detection_ms: 5, link: {there_extra_ms: 10}}\n"
                   "hosts: {cloud: %1}\n"_s.arg(m_lab.sshUrl(TwoHostLab::Cloud))
                       .arg(ros)
                       .toUtf8());
        plan.close();
        const QSet<QString> foldersBefore = labFolders();
        const QString out = m_dir.filePath(u"out-ros%1"_s.arg(ros));

        QProcess controller;
        QVERIFY(startInVehicle(controller, {u"experiment"_s, planPath, u"-o"_s, out}));
        // The cloud's side runs in the cloud's namespace while the cell records.
        bool bridge = false, detection = false, clock = false;
        QVERIFY(QTest::qWaitFor(
            [&] {
                for (const QString& line : commandLines(m_lab.pids(TwoHostLab::Cloud))) {
                    bridge = bridge || (line.contains(u" bridge "_s) && line.contains(u"cloud.yaml"_s));
                    detection = detection || line.contains(u"demo-node cloud"_s);
                    clock = clock || line.contains(u"clock serve --name cloud"_s);
                }
                return controller.state() == QProcess::NotRunning;
            },
            240000));
        const QString err = QString::fromUtf8(controller.readAllStandardError());
        QVERIFY2(
            controller.exitCode() == 0,
            qPrintable(QString(err + QString::fromUtf8(controller.readAllStandardOutput())).right(3000)));
        QVERIFY2(bridge && detection && clock,
                 qPrintable(u"bridge %1, detection %2, clock %3"_s.arg(bridge).arg(detection).arg(clock)));
        // Nothing of the cloud's side is left there: its programs ended with their ssh sessions
        // and its folder is gone.
        QTRY_VERIFY_WITH_TIMEOUT(
            !commandLines(m_lab.pids(TwoHostLab::Cloud)).join(u'\n').contains(u"bridgescope"_s), 10000);
        QCOMPARE(labFolders(), foldersBefore);

        const QStringList runs = QDir(out + u"/runs"_s).entryList({u"*.bsrun"_s}, QDir::Files);
        QCOMPARE(runs.size(), 1);
        const QString run = out + u"/runs/"_s + runs.first();

        // The report equals numpy on the run's raw stamps.
        const QString csv = m_dir.filePath(u"stamps-ros%1.csv"_s.arg(ros));
        const Ran written = bridgescope({u"report"_s, run, u"--format"_s, u"csv"_s, u"-o"_s, csv});
        QVERIFY2(written.exit == 0, qPrintable(written.err));
        const Ran json = bridgescope({u"report"_s, run, u"--format"_s, u"json"_s});
        QVERIFY2(json.exit == 0, qPrintable(json.err));
        const QJsonObject ours = QJsonDocument::fromJson(json.out.toUtf8()).object();
        QStringList hosts;
        for (const QString& t : DemoLab::pipelineTopics())
            hosts << (t.contains(u"_cloud/"_s) || t.contains(u"object_detection"_s) ? u"cloud"_s
                                                                                    : u"vehicle"_s);
        const QJsonObject ref
            = PythonRef::run(u"latency_reference.py"_s, {csv, u"--hosts"_s, hosts.join(u',')}).object();
        QVERIFY(!ref.isEmpty());
        QVERIFY2(ours.value(u"samples"_s).toInt() >= 150, qPrintable(json.out.left(400)));
        const QJsonArray stages = ours.value(u"stages"_s).toArray();
        QCOMPARE(stages.size(), 11);
        for (int s = 0; s < 11; ++s)
            QVERIFY2(
                same(stages[s].toObject().value(u"stats"_s).toObject(), ref.value(u"stages"_s)[s].toObject()),
                qPrintable(QString::number(s)));
        QVERIFY(same(ours.value(u"total"_s).toObject(), ref.value(u"total"_s).toObject()));
        const QJsonObject comm = ours.value(u"communication"_s).toObject();
        QVERIFY(same(comm.value(u"round_trip"_s).toObject(),
                     ref.value(u"communication"_s)[u"round_trip"_s].toObject()));
        QVERIFY(same(comm.value(u"one_way"_s).toObject(),
                     ref.value(u"communication"_s)[u"one_way"_s].toObject()));

        // The two crossings corrected by the measured clocks: there about 10 ms longer than back,
        // which half the round trip cannot see; the asymmetry says half of it.
        QList<QJsonObject> corrected;
        for (const QJsonValue& s : stages)
            if (s.toObject().contains(u"corrected"_s))
                corrected << s.toObject().value(u"corrected"_s).toObject();
        QCOMPARE(corrected.size(), 2);
        const double there = corrected[0].value(u"median_ms"_s).toDouble();
        const double back = corrected[1].value(u"median_ms"_s).toDouble();
        const double u = std::max(corrected[0].value(u"uncertainty_ms"_s).toDouble(),
                                  corrected[1].value(u"uncertainty_ms"_s).toDouble());
        const double half = comm.value(u"one_way"_s)[u"median_ms"_s].toDouble();
        qInfo("ROS %d across namespaces: corrected there %.2f ms, back %.2f ms (± %.2f ms), half the round "
              "trip %.2f ms",
              ros, there, back, u, half);
        QVERIFY2(u > 0 && u < 5, qPrintable(QString::number(u)));
        QVERIFY2(std::abs(there - back - 10) < 2 + 2 * u, qPrintable(u"%1 − %2"_s.arg(there).arg(back)));
        QVERIFY2(std::abs(half - back - 5) < 2 + u, qPrintable(u"half %1, back %2"_s.arg(half).arg(back)));
    }

    // Killed with SIGKILL (no clean-up of its own) while its cloud runs, the controller leaves
    // nothing on the cloud's host: the programs end with their ssh sessions, the folder with its.
    void aKilledControllerLeavesNothingOnTheFarHost()
    {
        const QSet<QString> foldersBefore = labFolders();
        QProcess demo;
        QVERIFY(startInVehicle(
            demo, {u"demo"_s, u"--cloud-host"_s, m_lab.sshUrl(TwoHostLab::Cloud), u"--size"_s, u"2000"_s}));
        QTRY_VERIFY_WITH_TIMEOUT(
            commandLines(m_lab.pids(TwoHostLab::Cloud)).join(u'\n').contains(u"clock serve --name cloud"_s),
            60000);
        QVERIFY(labFolders() != foldersBefore);
        signalProcess(demo.processId(), SIGKILL);
        QVERIFY(demo.waitForFinished(10000));
        QTRY_VERIFY_WITH_TIMEOUT(
            !commandLines(m_lab.pids(TwoHostLab::Cloud)).join(u'\n').contains(u"bridgescope"_s), 15000);
        QTRY_COMPARE_WITH_TIMEOUT(labFolders(), foldersBefore, 10000);
    }

    // `bridgescope demo --cloud-host`: the demo's cloud (its clock 35 ms ahead) in the cloud's
    // namespace; the clocks measured between the hosts hold the 35 ms within their interval.
    void theDemoRunsItsCloudOnAnotherHost()
    {
        QProcess demo;
        QVERIFY(startInVehicle(demo,
                               {u"demo"_s, u"--cloud-host"_s, m_lab.sshUrl(TwoHostLab::Cloud), u"--seconds"_s,
                                u"15"_s, u"--size"_s, u"20000"_s, u"--format"_s, u"json"_s}));
        bool detection = false;
        QVERIFY(QTest::qWaitFor(
            [&] {
                detection = detection
                    || commandLines(m_lab.pids(TwoHostLab::Cloud)).join(u'\n').contains(u"demo-node cloud"_s);
                return demo.state() == QProcess::NotRunning;
            },
            120000));
        const QString err = QString::fromUtf8(demo.readAllStandardError());
        QVERIFY2(demo.exitCode() == 0, qPrintable(err));
        QVERIFY2(detection, qPrintable(err));
        QVERIFY2(err.contains(u"the cloud's side runs on %1, reaching this host at %2"_s.arg(
                     m_lab.sshUrl(TwoHostLab::Cloud), m_lab.address(TwoHostLab::Vehicle))),
                 qPrintable(err));
        const QJsonObject report = QJsonDocument::fromJson(demo.readAllStandardOutput()).object();
        const QJsonObject clocks = report.value(u"clocks"_s).toObject();
        QVERIFY2(!clocks.isEmpty(), QJsonDocument(report).toJson().left(2000).constData());
        const QJsonObject cloud = clocks.begin()->toObject();
        const double offset = cloud.value(u"offset_ms"_s).toDouble();
        const double u = cloud.value(u"uncertainty_ms"_s).toDouble();
        qInfo("demo across namespaces: %s %.2f ms ± %.2f ms", qPrintable(clocks.begin().key()), offset, u);
        QVERIFY2(std::abs(offset - 35) <= u && u < 5, qPrintable(u"%1 ± %2"_s.arg(offset).arg(u)));
        QTRY_VERIFY_WITH_TIMEOUT(
            !commandLines(m_lab.pids(TwoHostLab::Cloud)).join(u'\n').contains(u"bridgescope"_s), 10000);
    }

    // The window joins a demo whose cloud is the cloud's namespace (its clock 35 ms ahead) and
    // renders Measure: the picture docs/two-hosts.md shows (kept where BRIDGESCOPE_SCREENSHOT_DIR
    // says). The window must come up, join the lab's servers and render the page.
    void theWindowWatchesTheTwoHostDemo()
    {
        QProcess demo;
        QVERIFY(startInVehicle(
            demo, {u"demo"_s, u"--cloud-host"_s, m_lab.sshUrl(TwoHostLab::Cloud), u"--seconds"_s, u"90"_s}));
        QString err;
        const QRegularExpression servers(u"broker (\\S+), ROS master (\\S+), configs in (\\S+)"_s);
        QRegularExpressionMatch m;
        QVERIFY(QTest::qWaitFor(
            [&] {
                err += QString::fromUtf8(demo.readAllStandardError());
                m = servers.match(err);
                return m.hasMatch() || demo.state() == QProcess::NotRunning;
            },
            60000));
        QVERIFY2(m.hasMatch(), qPrintable(err));
        const QString dir = qEnvironmentVariable("BRIDGESCOPE_SCREENSHOT_DIR", m_dir.path());
        const QString png = QDir(dir).filePath(u"measure-two-hosts.png"_s);
        QFile::remove(png);
        QTemporaryDir home;
        QProcess window;
        QProcessEnvironment wenv = QProcessEnvironment::systemEnvironment();
        wenv.insert(u"HOME"_s, home.path());
        wenv.insert(u"XDG_CONFIG_HOME"_s, home.filePath(u"config"_s));
        wenv.insert(u"QT_QPA_PLATFORM"_s, u"offscreen"_s);
        // For the docs, on a 1280x800 X screen when one can be made; offscreen otherwise.
        const QString xvfb = QStandardPaths::findExecutable(u"xvfb-run"_s);
        const QStringList screen = qEnvironmentVariableIsSet("BRIDGESCOPE_SCREENSHOT_DIR") && !xvfb.isEmpty()
            ? QStringList {xvfb, u"-a"_s, u"-s"_s, u"-screen 0 1280x800x24"_s}
            : QStringList {};
        if (!screen.isEmpty())
            wenv.remove(u"QT_QPA_PLATFORM"_s);
        window.setProcessEnvironment(wenv);
        const QStringList wargv = m_lab.inNamespace(
            TwoHostLab::Vehicle,
            screen
                + QStringList {QStringLiteral(BRIDGESCOPE_BINARY), u"--broker"_s, m.captured(1),
                               u"--ros-master"_s, m.captured(2), u"--pipeline"_s,
                               QDir(m.captured(3)).filePath(u"pipeline.yaml"_s), u"--page"_s, u"measure"_s,
                               u"--screenshot"_s, png, u"--after"_s, u"25"_s});
        window.start(wargv.first(), wargv.mid(1));
        QVERIFY(window.waitForFinished(90000));
        QVERIFY2(window.exitCode() == 0, window.readAllStandardError().constData());
        const QImage shot(png);
        QVERIFY2(!shot.isNull(), qPrintable(png));
        // Offscreen the window takes its minimum width; on a 1280x800 X screen (docs) all of it.
        QCOMPARE(shot.height(), 800);
        QVERIFY2(shot.width() >= 1000 && shot.width() <= 1280, qPrintable(QString::number(shot.width())));
        signalProcess(demo.processId(), SIGTERM);
        QVERIFY(demo.waitForFinished(30000));
    }
};

QTEST_GUILESS_MAIN(TestTwoHostExperiment)
#include "tst_twohostexperiment.moc"
