// SPDX-License-Identifier: MIT
// The test helper itself: real mosquitto and rosmaster on free loopback ports, reachable with the
// standard tools, and gone without a trace when stopped.
#include "base/loopbackports.h"
#include "testservers.h"

#include <csignal>
#include <QProcess>
#include <QTest>
#include <sys/types.h>

using namespace Qt::StringLiterals;

namespace {
QString run(const QString& program, const QStringList& args,
            const QProcessEnvironment& env = QProcessEnvironment::systemEnvironment(), int timeoutMs = 20000)
{
    QProcess p;
    p.setProcessEnvironment(env);
    p.start(program, args);
    if (!p.waitForFinished(timeoutMs)) {
        p.kill();
        p.waitForFinished();
        return u"<timeout>"_s;
    }
    return QString::fromLocal8Bit(p.readAllStandardOutput()).trimmed();
}

bool processAlive(qint64 pid)
{
    return pid > 0 && ::kill(pid_t(pid), 0) == 0;
}
} // namespace

class TestTestServers : public QObject
{
    Q_OBJECT
private slots:
    // The demo lab's broker and master once got the same port (the broker launched, not yet
    // listening): a port handed out is never handed out again, though nothing listens on it yet.
    void aTakenPortIsNotHandedOutAgain()
    {
        QList<quint16> taken;
        for (int i = 0; i < 200; ++i) {
            const quint16 port = LoopbackPorts::freePort(taken);
            QVERIFY(port != 0);
            QVERIFY2(!taken.contains(port), qPrintable(QString::number(port)));
            taken << port;
        }
    }

    void mosquittoCarriesMessagesOnItsOwnPort()
    {
        TestServers servers;
        QVERIFY2(servers.startMosquitto(), qPrintable(servers.errorString()));
        QVERIFY(servers.mosquittoPort() != 1883);
        QVERIFY(servers.brokerUrl().startsWith(u"tcp://127.0.0.1:"_s));
        const QString port = QString::number(servers.mosquittoPort());
        // A retained message is there for a subscriber that comes later.
        QCOMPARE(run(u"mosquitto_pub"_s,
                     {u"-h"_s, u"127.0.0.1"_s, u"-p"_s, port, u"-t"_s, u"test/hello"_s, u"-r"_s, u"-m"_s,
                      u"hello bridgescope"_s}),
                 QString());
        QCOMPARE(run(u"mosquitto_sub"_s,
                     {u"-h"_s, u"127.0.0.1"_s, u"-p"_s, port, u"-t"_s, u"test/#"_s, u"-C"_s, u"1"_s, u"-W"_s,
                      u"5"_s}),
                 u"hello bridgescope"_s);
    }

    void rosMasterAnswersRosTools()
    {
        TestServers servers;
        QVERIFY2(servers.startRosMaster(), qPrintable(servers.errorString()));
        QVERIFY(servers.rosMasterPort() != 11311);
        const QProcessEnvironment env = servers.rosEnvironment();
        QCOMPARE(env.value(u"ROS_MASTER_URI"_s), servers.rosMasterUri());
        run(u"rosparam"_s, {u"set"_s, u"/bridgescope_test"_s, u"42"_s}, env);
        QCOMPARE(run(u"rosparam"_s, {u"get"_s, u"/bridgescope_test"_s}, env), u"42"_s);
    }

    void instancesDoNotCollide()
    {
        TestServers a, b;
        QVERIFY(a.startMosquitto() && b.startMosquitto());
        QVERIFY(a.startRosMaster() && b.startRosMaster());
        QVERIFY(a.mosquittoPort() != b.mosquittoPort());
        QVERIFY(a.rosMasterPort() != b.rosMasterPort());
        run(u"rosparam"_s, {u"set"_s, u"/only_in_a"_s, u"1"_s}, a.rosEnvironment());
        QVERIFY(run(u"rosparam"_s, {u"list"_s}, b.rosEnvironment()).indexOf(u"only_in_a"_s) < 0);
    }

    void stoppingLeavesNothingBehind()
    {
        qint64 mosquittoPid = 0, masterPid = 0;
        quint16 mosquittoPort = 0, masterPort = 0;
        {
            TestServers servers;
            QVERIFY(servers.startMosquitto());
            QVERIFY(servers.startRosMaster());
            mosquittoPid = servers.mosquittoPid();
            masterPid = servers.rosMasterPid();
            mosquittoPort = servers.mosquittoPort();
            masterPort = servers.rosMasterPort();
            QVERIFY(processAlive(mosquittoPid) && processAlive(masterPid));
            // Restart on the same port (fault tests kill and restart servers).
            servers.stopMosquitto();
            QVERIFY(!TestServers::waitForPort(mosquittoPort, 300));
            QVERIFY(servers.startMosquittoOnPort(mosquittoPort));
            mosquittoPid = servers.mosquittoPid();
        }
        QVERIFY(!processAlive(mosquittoPid));
        QVERIFY(!processAlive(masterPid));
        QVERIFY(!TestServers::waitForPort(mosquittoPort, 300));
        QVERIFY(!TestServers::waitForPort(masterPort, 300));
    }
};

QTEST_GUILESS_MAIN(TestTestServers)
#include "tst_testservers.moc"
