// SPDX-License-Identifier: MIT
// Issue 41, points 10 and 11: a server that accepts connections and never answers costs a command
// seconds, never the rest of its life, and a command that heard nothing on any graph says so and
// fails, on ROS 2 as on ROS 1. Every case runs the real program against a fake peer on 127.0.0.1.
#include "signalprocess.h"
#include "clirun.h"
#include "ros2peer.h"
#include "testservers.h"

#include <csignal>
#include <QElapsedTimer>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

using namespace Qt::StringLiterals;

namespace {
/// A ROS master that accepts every connection and then answers nothing ("never"), or answers
/// getPid and nothing else ("getpid": roscpp's own calls, which have no deadline, then hang).
const char kHungMaster[] = R"PY(
import re, socket, sys, threading
mode = sys.argv[1]
server = socket.socket()
server.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
server.bind(("127.0.0.1", 0))
server.listen(256)
print(server.getsockname()[1], flush=True)
held = []
def serve(c):
    held.append(c)  # never closed: the caller waits for an answer
    if mode != "getpid":
        return
    data = b""
    while b"\r\n\r\n" not in data:
        chunk = c.recv(65536)
        if not chunk:
            return
        data += chunk
    head, _, body = data.partition(b"\r\n\r\n")
    m = re.search(rb"(?i)content-length:\s*(\d+)", head)
    while m and len(body) < int(m.group(1)):
        chunk = c.recv(65536)
        if not chunk:
            return
        body += chunk
    if b"<methodName>getPid</methodName>" in body:
        answer = (b'<?xml version="1.0"?><methodResponse><params><param><value><array><data>'
                  b'<value><i4>1</i4></value><value><string></string></value><value><i4>4242</i4></value>'
                  b'</data></array></value></param></params></methodResponse>')
        c.sendall(b"HTTP/1.0 200 OK\r\nContent-Type: text/xml\r\nContent-Length: %d\r\n\r\n" % len(answer) + answer)
while True:
    c, _ = server.accept()
    threading.Thread(target=serve, args=(c,), daemon=True).start()
)PY";

/// The fake master as a child process; its URI once it listens.
class HungMaster
{
public:
    explicit HungMaster(const QString& mode)
    {
        m_process.start(u"python3"_s, {u"-c"_s, QString::fromLatin1(kHungMaster), mode});
        if (m_process.waitForReadyRead(10000))
            m_port = m_process.readLine().trimmed().toInt();
    }
    ~HungMaster()
    {
        m_process.kill();
        m_process.waitForFinished(5000);
    }
    bool listening() const { return m_port > 0; }
    QString uri() const { return u"http://127.0.0.1:%1/"_s.arg(m_port); }

private:
    QProcess m_process;
    int m_port = 0;
};

QString unreachableBroker()
{
    return u"tcp://127.0.0.1:%1"_s.arg(TestServers::freePort());
}

/// Starts bridgescope; the caller waits.
std::unique_ptr<QProcess> start(const QStringList& args)
{
    auto p = std::make_unique<QProcess>();
    p->start(QStringLiteral(BRIDGESCOPE_BINARY), args);
    return p;
}
} // namespace

class TestDeadlines : public QObject
{
    Q_OBJECT
private:
    QTemporaryDir m_dir;

    QString write(const QString& name, const QByteArray& text)
    {
        const QString path = m_dir.filePath(name);
        QFile f(path);
        if (!f.open(QIODevice::WriteOnly) || f.write(text) != text.size())
            return {};
        return path;
    }

    QStringList recordAgainst(const HungMaster& master, double seconds, const QString& run)
    {
        return {u"record"_s,
                u"--ros"_s,
                u"1"_s,
                u"--pipeline"_s,
                write(u"pipe.yaml"_s, "topics_in_order: [/lab/a, /lab/b]\nmetrics_window: 10\n"),
                u"--broker"_s,
                unreachableBroker(),
                u"--ros-master"_s,
                master.uri(),
                u"--seconds"_s,
                QString::number(seconds),
                u"-o"_s,
                m_dir.filePath(run)};
    }

private slots:
    void hungMasterEndsRecordAtItsSeconds_data()
    {
        QTest::addColumn<QString>("mode");
        QTest::newRow("never answers") << u"never"_s;
        QTest::newRow("answers getPid only") << u"getpid"_s;
    }

    // record --seconds 3 against a master that never answers: before, the ROS node's thread waited
    // in XmlRpcClient::execute for good and the command never ended. Now it ends after its seconds
    // and at most the teardown's bound (RosNode::kWaitMs, 5 s), failing, with what it missed.
    void hungMasterEndsRecordAtItsSeconds()
    {
        QFETCH(QString, mode);
        const HungMaster master(mode);
        QVERIFY(master.listening());
        const QString tag = QString::fromLatin1(QTest::currentDataTag()).replace(u' ', u'-');
        QElapsedTimer clock;
        clock.start();
        const CliRun::Result r = CliRun::bridgescope(recordAgainst(master, 3, tag + u".bsrun"_s), 25000);
        QVERIFY2(r.exit == 1,
                 qPrintable(u"exit %1 after %2 ms: %3"_s.arg(r.exit).arg(clock.elapsed()).arg(r.err)));
        QVERIFY2(clock.elapsed() < 15000, qPrintable(QString::number(clock.elapsed())));
        QVERIFY2(r.err.contains(u"nothing was recorded (neither the broker nor the master was reached)"_s),
                 qPrintable(r.err));
    }

    void sigtermEndsRecordAgainstAHungMaster_data() { hungMasterEndsRecordAtItsSeconds_data(); }

    // Ctrl+C and SIGTERM were ignored: the main thread waited on the blocked ROS thread.
    void sigtermEndsRecordAgainstAHungMaster()
    {
        QFETCH(QString, mode);
        const HungMaster master(mode);
        QVERIFY(master.listening());
        const QString tag = QString::fromLatin1(QTest::currentDataTag()).replace(u' ', u'-');
        const auto p = start(recordAgainst(master, 120, u"term-"_s + tag + u".bsrun"_s));
        QVERIFY(p->waitForStarted());
        QString err;
        QElapsedTimer clock;
        clock.start();
        while (!err.contains(u"2 s: "_s) && clock.elapsed() < 20000 && p->state() == QProcess::Running) {
            p->waitForReadyRead(200);
            err += QString::fromUtf8(p->readAllStandardError());
        }
        QVERIFY2(err.contains(u"2 s: "_s), qPrintable(err)); // recording, its progress said
        signalProcess(p->processId(), SIGTERM);
        clock.restart();
        QVERIFY2(p->waitForFinished(15000), qPrintable(err));
        QVERIFY2(clock.elapsed() < 10000, qPrintable(QString::number(clock.elapsed())));
        QCOMPARE(p->exitStatus(), QProcess::NormalExit);
        QCOMPARE(p->exitCode(), 1); // nothing recorded
    }

    // A ROS 1 experiment cell against a master that never answers fails at its timeout, and the
    // run ends (before: the cell's teardown waited for the ROS thread for good).
    void hungMasterFailsTheExperimentCell()
    {
        const HungMaster master(u"never"_s);
        QVERIFY(master.listening());
        const QString plan
            = write(u"hung.yaml"_s,
                    u"samples: 5\nwarmup: 0\ntimeout_s: 4\nservers: {broker: \"%1\", ros_master: \"%2\"}\n"_s
                        .arg(unreachableBroker(), master.uri())
                        .toUtf8());
        QElapsedTimer clock;
        clock.start();
        const CliRun::Result r
            = CliRun::bridgescope({u"experiment"_s, plan, u"-o"_s, m_dir.filePath(u"hung"_s)}, 60000);
        QVERIFY2(r.exit == 1,
                 qPrintable(u"exit %1 after %2 ms: %3"_s.arg(r.exit).arg(clock.elapsed()).arg(r.err)));
        bool failed = false;
        for (const QString& line : r.out.split(u'\n', Qt::SkipEmptyParts)) {
            const QJsonObject o = QJsonDocument::fromJson(line.toUtf8()).object();
            failed = failed
                || (o.value(u"event"_s).toString() == u"finished"_s
                    && o.value(u"state"_s).toString() == u"failed"_s);
        }
        QVERIFY2(failed, qPrintable(r.out));
    }

    // Issue 41, point 11: with the broker away and nobody on the ROS 2 domain, `watch --ros 2`
    // exited 0 as if it had watched something (ROS 1 in the same case exits 1). Somebody on the
    // domain is something heard; --allow-empty accepts nothing.
    void watchOnRos2HearingNothingFails()
    {
        const int domain = Ros2Peer::freeDomain(231, 232);
        const QStringList args {
            u"watch"_s,        u"--broker"_s,           unreachableBroker(),       u"--ros"_s,     u"2"_s,
            u"--ros-domain"_s, QString::number(domain), u"--ros-localhost-only"_s, u"--seconds"_s, u"3"_s};
        const CliRun::Result nothing = CliRun::bridgescope(args, 30000);
        QVERIFY2(nothing.exit == 1, qPrintable(nothing.err));
        QVERIFY2(nothing.err.contains(u"nothing was watched: the broker was not reached and nobody was heard "
                                      u"on ROS 2 domain %1"_s.arg(domain)),
                 qPrintable(nothing.err));
        QVERIFY2(!nothing.err.contains(u"master"_s), qPrintable(nothing.err));
        QCOMPARE(CliRun::bridgescope(args + QStringList {u"--allow-empty"_s}, 30000).exit, 0);

        Ros2Peer talker(domain,
                        {u"--node"_s, u"/lab/talker"_s, u"--pub"_s, u"/chatter:std_msgs/msg/String:10"_s});
        QVERIFY2(talker.waitFor(u"ready"_s), qPrintable(talker.errors()));
        const CliRun::Result heard = CliRun::bridgescope(args, 30000);
        QVERIFY2(heard.exit == 0, qPrintable(heard.err));
    }

    // `record --ros 2` said "neither the broker nor the master was reached": ROS 2 has no master.
    void recordOnRos2NamesWhatItWaitedFor()
    {
        const int domain = Ros2Peer::freeDomain(231, 232);
        const CliRun::Result r = CliRun::bridgescope(
            {u"record"_s, u"--ros"_s, u"2"_s, u"--ros-domain"_s, QString::number(domain),
             u"--ros-localhost-only"_s, u"--pipeline"_s,
             write(u"ros2.yaml"_s, "topics_in_order: [/lab/a, /lab/b]\n"), u"--broker"_s, unreachableBroker(),
             u"--seconds"_s, u"2"_s, u"-o"_s, m_dir.filePath(u"ros2.bsrun"_s)},
            30000);
        QVERIFY2(r.exit == 1, qPrintable(r.err));
        QVERIFY2(
            r.err.contains(u"nothing was recorded (the broker was not reached and nobody was heard on ROS 2 "
                           u"domain %1)"_s.arg(domain)),
            qPrintable(r.err));
        QVERIFY2(!r.err.contains(u"master"_s), qPrintable(r.err));
    }

    // `experiment --broker` demanded --ros-master for a `ros: 2` plan, which has no master.
    void experimentOnRos2TakesTheBrokerAlone()
    {
        const QString ros2 = write(u"ros2-plan.yaml"_s, "ros: 2\nsamples: 5\nfactors:\n  qos: [0, 1]\n");
        const QString broker = u"tcp://lab:pw@127.0.0.1:1883"_s;
        CliRun::Result r
            = CliRun::bridgescope({u"experiment"_s, ros2, u"--broker"_s, broker, u"--dry-run"_s});
        QVERIFY2(r.exit == 0, qPrintable(r.err));
        QVERIFY2(r.out.contains(u"002-qos-1"_s), qPrintable(r.out));
        r = CliRun::bridgescope({u"experiment"_s, ros2, u"--broker"_s, broker, u"--ros-master"_s,
                                 u"http://127.0.0.1:11311/"_s, u"--dry-run"_s});
        QCOMPARE(r.exit, 2);
        QVERIFY2(r.err.contains(u"--ros-master: the plan runs on ROS 2 (ros: 2), which has no master"_s),
                 qPrintable(r.err));
        // ROS 1 still takes them together
        const QString ros1 = write(u"ros1-plan.yaml"_s, "samples: 5\n");
        r = CliRun::bridgescope({u"experiment"_s, ros1, u"--broker"_s, broker, u"--dry-run"_s});
        QCOMPARE(r.exit, 2);
        QVERIFY2(r.err.contains(u"go together"_s), qPrintable(r.err));
    }
};

QTEST_GUILESS_MAIN(TestDeadlines)
#include "tst_deadlines.moc"
