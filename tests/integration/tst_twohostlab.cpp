// SPDX-License-Identifier: MIT
// The two-host test lab itself (issue 43): two network namespaces joined by a veth pair, an sshd in
// each that takes only the run's own key, and nothing left behind when the lab ends, also when the
// test process is killed.
#include "signalprocess.h"
#include "twohostlab.h"

#include <csignal>
#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QProcess>
#include <QTest>
#include <QTextStream>

using namespace Qt::StringLiterals;

namespace {
// A process that still runs and is the program `comm` (a reused pid is not ours; a zombie waiting
// for init to reap it runs no more).
bool processIs(qint64 pid, const QString& comm)
{
    QFile file(u"/proc/%1/stat"_s.arg(pid));
    if (pid <= 0 || !file.open(QIODevice::ReadOnly))
        return false;
    const QByteArray stat = file.readAll();
    const qsizetype open = stat.indexOf('('), close = stat.lastIndexOf(')');
    return open > 0 && close > open && stat.mid(open + 1, close - open - 1) == comm.toLatin1()
        && stat.mid(close + 2, 1) != "Z";
}

const char* const s_childVariable = "TWOHOSTLAB_CHILD";

// The child mode of this executable: builds a lab, prints its names and folder, and waits to be killed.
int runChild()
{
    TwoHostLab lab;
    QTextStream out(stdout);
    if (!lab.up()) {
        out << "failed " << lab.skipReason() << lab.errorString() << Qt::endl;
        return 1;
    }
    out << lab.netns(TwoHostLab::Vehicle) << ' ' << lab.netns(TwoHostLab::Cloud) << ' '
        << QFileInfo(lab.clientKey()).absolutePath() << ' ' << lab.sshdPid(TwoHostLab::Vehicle) << ' '
        << lab.sshdPid(TwoHostLab::Cloud) << Qt::endl;
    return QCoreApplication::exec();
}
} // namespace

class TestTwoHostLab : public QObject
{
    Q_OBJECT
private slots:
    void eachSideReachesTheOtherOverTheVeth()
    {
        TwoHostLab lab;
        TWOHOSTLAB_UP_OR_SKIP(lab);
        QVERIFY(lab.address(TwoHostLab::Vehicle) != lab.address(TwoHostLab::Cloud));
        for (auto [from, to] : {std::pair {TwoHostLab::Vehicle, TwoHostLab::Cloud},
                                std::pair {TwoHostLab::Cloud, TwoHostLab::Vehicle}}) {
            // A raw TCP connection from one namespace to the other's address gets its sshd's banner.
            const LabRun banner = lab.run(
                from,
                {u"bash"_s, u"-c"_s, u"exec 3<>/dev/tcp/%1/22 && head -c 8 <&3"_s.arg(lab.address(to))});
            QCOMPARE(banner.out, u"SSH-2.0-"_s);
            // ssh lands in the other namespace: its veth holds the other's address.
            const LabRun r
                = lab.run(from,
                          {u"ssh"_s, u"-F"_s, QFileInfo(lab.clientKey()).absolutePath() + u"/ssh_config"_s,
                           u"root@"_s + lab.address(to), u"ip -o -4 addr show dev bs0"_s});
            QVERIFY2(r.exitCode == 0, qPrintable(r.err));
            QVERIFY2(r.out.contains(u" inet "_s + lab.address(to) + u"/30"_s), qPrintable(r.out));
        }
        // The lab's wrapper does the same from the vehicle's side.
        QProcess ssh;
        ssh.start(lab.sshProgram(),
                  {u"root@"_s + lab.address(TwoHostLab::Cloud), u"cat /proc/sys/kernel/hostname; echo ok"_s});
        QVERIFY(ssh.waitForFinished(20000));
        QVERIFY(ssh.readAllStandardOutput().endsWith("ok\n"));
    }

    void sshdListensOnlyOnItsVethAndLo()
    {
        TwoHostLab lab;
        TWOHOSTLAB_UP_OR_SKIP(lab);
        for (TwoHostLab::Side side : {TwoHostLab::Vehicle, TwoHostLab::Cloud}) {
            const LabRun r = lab.run(side, {u"ss"_s, u"-Hltn"_s});
            QStringList listening;
            for (const QString& line : r.out.split(u'\n', Qt::SkipEmptyParts))
                listening << line.simplified().section(u' ', 3, 3);
            listening.sort();
            QCOMPARE(listening, QStringList({lab.address(side) + u":22"_s, u"127.0.0.1:22"_s}));
        }
    }

    void batchModeWorksWithTheRunsKeyOnly()
    {
        TwoHostLab lab;
        TWOHOSTLAB_UP_OR_SKIP(lab);
        const QString dir = QFileInfo(lab.clientKey()).absolutePath();
        const QStringList common = {u"ssh"_s,
                                    u"-F"_s,
                                    u"/dev/null"_s,
                                    u"-o"_s,
                                    u"BatchMode=yes"_s,
                                    u"-o"_s,
                                    u"IdentitiesOnly=yes"_s,
                                    u"-o"_s,
                                    u"IdentityAgent=none"_s,
                                    u"-o"_s,
                                    u"UserKnownHostsFile="_s + lab.knownHosts(),
                                    u"-o"_s,
                                    u"StrictHostKeyChecking=yes"_s};
        for (TwoHostLab::Side side : {TwoHostLab::Vehicle, TwoHostLab::Cloud}) {
            const QString target = u"root@"_s + lab.address(side);
            const LabRun good = lab.run(
                TwoHostLab::Vehicle, common + QStringList {u"-i"_s, lab.clientKey(), target, u"echo in"_s});
            QCOMPARE(good.exitCode, 0);
            QCOMPARE(good.out, u"in\n"_s);
            // Another key, no key, a password: refused, and only public keys are offered.
            const LabRun stranger
                = lab.run(TwoHostLab::Vehicle,
                          common + QStringList {u"-i"_s, dir + u"/stranger"_s, target, u"echo in"_s});
            QCOMPARE(stranger.exitCode, 255);
            QVERIFY2(stranger.err.contains(u"Permission denied (publickey)"_s), qPrintable(stranger.err));
            const LabRun none
                = lab.run(TwoHostLab::Vehicle,
                          common + QStringList {u"-o"_s, u"IdentityFile=/dev/null"_s, target, u"echo in"_s});
            QCOMPARE(none.exitCode, 255);
            const LabRun password = lab.run(
                TwoHostLab::Vehicle,
                common
                    + QStringList {u"-o"_s, u"PreferredAuthentications=password,keyboard-interactive"_s,
                                   target, u"echo in"_s});
            QCOMPARE(password.exitCode, 255);
            QVERIFY2(password.err.contains(u"Permission denied (publickey)"_s), qPrintable(password.err));
        }
    }

    // The broker on one side, reached from the other over the veth (issue 43, point 4).
    void aBrokerOnOneSideServesTheOther()
    {
        TwoHostLab lab;
        TWOHOSTLAB_UP_OR_SKIP(lab);
        const QString conf = QFileInfo(lab.clientKey()).absolutePath() + u"/mosquitto.conf"_s;
        QFile file(conf);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(
            u"listener 1883 %1\nallow_anonymous true\n"_s.arg(lab.address(TwoHostLab::Cloud)).toLatin1());
        file.close();
        const auto broker
            = lab.startProcess(TwoHostLab::Cloud, u"mosquitto"_s, {u"mosquitto"_s, u"-c"_s, conf});
        QVERIFY2(broker, qPrintable(lab.errorString()));
        const QStringList common = {u"-h"_s, lab.address(TwoHostLab::Cloud), u"-t"_s, u"lab/hello"_s};
        // Retained, so the subscriber that comes later gets it; retried while the broker starts.
        QTRY_VERIFY2_WITH_TIMEOUT(lab.run(TwoHostLab::Vehicle,
                                          QStringList {u"mosquitto_pub"_s} + common
                                              + QStringList {u"-r"_s, u"-m"_s, u"over the veth"_s})
                                          .exitCode
                                      == 0,
                                  qPrintable(lab.log(u"mosquitto"_s)), 10000);
        const LabRun sub = lab.run(TwoHostLab::Vehicle,
                                   QStringList {u"mosquitto_sub"_s} + common
                                       + QStringList {u"-C"_s, u"1"_s, u"-W"_s, u"5"_s});
        QCOMPARE(sub.out, u"over the veth\n"_s);
        // Only over the veth: the vehicle's own loopback has no broker.
        QVERIFY(lab.run(TwoHostLab::Vehicle,
                        {u"mosquitto_pub"_s, u"-h"_s, u"127.0.0.1"_s, u"-t"_s, u"x"_s, u"-m"_s, u"x"_s})
                    .exitCode
                != 0);
    }

    void rateLimitsTheVeth()
    {
        TwoHostLab lab;
        TWOHOSTLAB_UP_OR_SKIP(lab);
        QVERIFY2(lab.setRate(TwoHostLab::Vehicle, u"8mbit"_s), qPrintable(lab.errorString()));
        const LabRun r = lab.run(TwoHostLab::Vehicle, {u"tc"_s, u"qdisc"_s, u"show"_s, u"dev"_s, u"bs0"_s});
        QVERIFY2(r.out.contains(u"tbf"_s) && r.out.contains(u"rate 8Mbit"_s), qPrintable(r.out));
    }

    void teardownLeavesNoNamespaceNoSshdNoFolder()
    {
        QString names[2];
        qint64 sshd[2] = {};
        QString dir;
        {
            TwoHostLab lab;
            TWOHOSTLAB_UP_OR_SKIP(lab);
            for (TwoHostLab::Side side : {TwoHostLab::Vehicle, TwoHostLab::Cloud}) {
                names[side] = lab.netns(side);
                sshd[side] = lab.sshdPid(side);
                QVERIFY(processIs(sshd[side], u"sshd"_s));
            }
            dir = QFileInfo(lab.clientKey()).absolutePath();
            QVERIFY(TwoHostLab::labNamespaces().contains(names[0]));
            // A session still running on the cloud's side when the lab ends.
            QProcess session;
            session.start(lab.sshProgram(),
                          {u"root@"_s + lab.address(TwoHostLab::Cloud), u"echo started; exec sleep 1000"_s});
            QByteArray out;
            QTRY_VERIFY2_WITH_TIMEOUT((out += session.readAllStandardOutput()).contains("started"),
                                      session.readAllStandardError().constData(), 20000);
            lab.down();
            QVERIFY(session.waitForFinished(10000));
        }
        const QStringList left = TwoHostLab::labNamespaces();
        QVERIFY2(!left.contains(names[0]) && !left.contains(names[1]), qPrintable(left.join(u' ')));
        QTRY_VERIFY_WITH_TIMEOUT(!processIs(sshd[0], u"sshd"_s) && !processIs(sshd[1], u"sshd"_s), 5000);
        QVERIFY(!QFileInfo::exists(dir));
    }

    void teardownAlsoWhenTheTestProcessIsKilled()
    {
        if (::geteuid() != 0)
            QSKIP("two-host lab unavailable: needs root for network namespaces (ip netns)");
        QProcess child;
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert(QString::fromLatin1(s_childVariable), u"1"_s);
        child.setProcessEnvironment(env);
        child.start(QCoreApplication::applicationFilePath(), {});
        QTRY_VERIFY_WITH_TIMEOUT(child.canReadLine() || child.state() == QProcess::NotRunning, 30000);
        const QStringList words = QString::fromLocal8Bit(child.readLine()).trimmed().split(u' ');
        if (words.value(0) == u"failed"_s)
            QSKIP(qPrintable(words.join(u' ')));
        QCOMPARE(words.size(), 5);
        QVERIFY(TwoHostLab::labNamespaces().contains(words[0]));
        QVERIFY(processIs(words[3].toLongLong(), u"sshd"_s));
        QVERIFY(signalProcess(child.processId(), SIGKILL));
        QVERIFY(child.waitForFinished(5000));
        QTRY_VERIFY_WITH_TIMEOUT(!TwoHostLab::labNamespaces().contains(words[0])
                                     && !TwoHostLab::labNamespaces().contains(words[1]),
                                 20000);
        QTRY_VERIFY_WITH_TIMEOUT(!processIs(words[3].toLongLong(), u"sshd"_s)
                                     && !processIs(words[4].toLongLong(), u"sshd"_s),
                                 10000);
        QTRY_VERIFY_WITH_TIMEOUT(!QFileInfo::exists(words[2]), 10000);
    }

    void staleLabsOfDeadRunsAreRemoved()
    {
        if (::geteuid() != 0)
            QSKIP("two-host lab unavailable: needs root for network namespaces (ip netns)");
        // A lab whose run (pid 1's start time is not "1") is gone, with a process left inside.
        const QString stale = u"bs-lab-1-1-%1-v"_s.arg(QCoreApplication::applicationPid());
        QProcess add;
        add.start(u"ip"_s, {u"netns"_s, u"add"_s, stale});
        QVERIFY(add.waitForFinished(10000));
        if (add.exitCode() != 0)
            QSKIP("two-host lab unavailable: ip netns add fails here");
        QProcess sleeper;
        sleeper.start(u"ip"_s, {u"netns"_s, u"exec"_s, stale, u"sleep"_s, u"1000"_s});
        QVERIFY(sleeper.waitForStarted());
        QTRY_VERIFY_WITH_TIMEOUT(processIs(sleeper.processId(), u"sleep"_s), 5000);
        QVERIFY(TwoHostLab::removeStale() >= 1);
        QVERIFY(!TwoHostLab::labNamespaces().contains(stale));
        QVERIFY(sleeper.waitForFinished(5000));
    }
};

int main(int argc, char** argv)
{
    if (qEnvironmentVariableIsSet(s_childVariable)) {
        QCoreApplication app(argc, argv);
        return runChild();
    }
    QCoreApplication app(argc, argv);
    TestTwoHostLab test;
    QTEST_SET_MAIN_SOURCE_PATH
    return QTest::qExec(&test, argc, argv);
}

#include "tst_twohostlab.moc"
