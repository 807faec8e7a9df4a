// SPDX-License-Identifier: MIT
// Programs on another host over ssh (issue 43), against the two-namespace lab: they run on the far
// side, end when stopped or when the local ssh is killed, an unreachable host fails clearly within
// the connect timeout, and hostile words run nothing extra over there.
#include "remote/remotecommand.h"
#include "remote/remoteprocess.h"
#include "signalprocess.h"
#include "twohostlab.h"

#include <QCoreApplication>
#include <QDir>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

using namespace Qt::StringLiterals;

namespace {
// Whether a live process's command line holds `text` (the namespaces share this machine's pids;
// read from /proc: procps, pgrep's package, is not on every machine).
bool anyProcessMentions(const QString& text)
{
    const QByteArray needle = text.toLocal8Bit();
    const QStringList pids = QDir(u"/proc"_s).entryList({u"[0-9]*"_s}, QDir::Dirs);
    for (const QString& pid : pids) {
        QFile cmdline(u"/proc/"_s + pid + u"/cmdline"_s);
        if (pid.toLongLong() != QCoreApplication::applicationPid() && cmdline.open(QIODevice::ReadOnly)
            && cmdline.readAll().contains(needle))
            return true;
    }
    return false;
}
} // namespace

class TestRemoteProcess : public QObject
{
    Q_OBJECT

    TwoHostLab m_lab;

    SshOptions options(int connectTimeout = 5) const
    {
        SshOptions o;
        o.program = m_lab.sshProgram(TwoHostLab::Vehicle);
        o.identityFile = m_lab.clientKey();
        o.knownHostsFile = m_lab.knownHosts();
        o.connectTimeoutSeconds = connectTimeout;
        return o;
    }
    RemoteHost cloud(quint16 port = 22) const
    {
        RemoteHost host = *RemoteHost::parse(m_lab.sshUrl(TwoHostLab::Cloud));
        host.port = port;
        return host;
    }
    // Whether `pid` is a live process inside the cloud's namespace (asked over there).
    bool runsInCloud(qint64 pid) const
    {
        const LabRun r = m_lab.run(
            TwoHostLab::Cloud,
            {u"sh"_s, u"-c"_s, u"kill -0 \"$1\" 2>/dev/null"_s, u"check"_s, QString::number(pid)});
        return r.exitCode == 0 && m_lab.pids(TwoHostLab::Cloud).contains(pid);
    }

private slots:
    void initTestCase() { TWOHOSTLAB_UP_OR_SKIP(m_lab); }

    void runsAProgramOnTheFarHostAndStopsIt()
    {
        RemoteProcess remote(cloud(), options(), u"cloud"_s);
        QSignalSpy started(&remote, &RemoteProcess::started);
        QSignalSpy finished(&remote, &RemoteProcess::finished);
        QVERIFY2(remote.start({u"sleep"_s, u"1000"_s}), qPrintable(remote.errorString()));
        QTRY_COMPARE_WITH_TIMEOUT(started.size(), 1, 20000);
        const qint64 pid = remote.remotePid();
        QCOMPARE(started.first().first().toLongLong(), pid);
        QVERIFY(runsInCloud(pid));
        QVERIFY(!m_lab.pids(TwoHostLab::Vehicle).contains(pid));
        remote.stop();
        QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, 10000);
        QVERIFY(!runsInCloud(pid));
        QCOMPARE(remote.exitCode(), 128 + SIGTERM);
        QCOMPARE(remote.errorString(), QString()); // asked to stop: not a failure
    }

    void stopKillsAFarProgramThatIgnoresTerm()
    {
        RemoteProcess remote(cloud(), options(), u"cloud"_s);
        remote.setGracePeriod(1);
        QSignalSpy output(&remote, &RemoteProcess::standardOutputLine);
        QVERIFY(remote.start({u"sh"_s, u"-c"_s, u"trap '' TERM; echo ready; while :; do sleep 1; done"_s}));
        QTRY_VERIFY_WITH_TIMEOUT(remote.hasStarted() && !output.isEmpty(), 20000);
        QCOMPARE(output.first().first().toString(), u"ready"_s);
        const qint64 pid = remote.remotePid();
        remote.stop();
        QTRY_VERIFY_WITH_TIMEOUT(!remote.isRunning(), 10000);
        QVERIFY(!runsInCloud(pid));
        QCOMPARE(remote.exitCode(), 128 + SIGKILL);
    }

    void killingTheLocalSshEndsTheFarProgram()
    {
        RemoteProcess remote(cloud(), options(), u"cloud"_s);
        QSignalSpy output(&remote, &RemoteProcess::standardOutputLine);
        // A program with a child of its own, as bridgescope's demo starts its servers.
        QVERIFY(remote.start({u"sh"_s, u"-c"_s, u"sleep 1000 & echo $!; wait"_s}));
        QTRY_VERIFY_WITH_TIMEOUT(remote.hasStarted() && !output.isEmpty(), 20000);
        const qint64 pid = remote.remotePid();
        const qint64 child = output.first().first().toString().toLongLong();
        QVERIFY(runsInCloud(pid));
        QVERIFY(runsInCloud(child));
        // The controller's side dies without a word: SIGKILL to the local ssh.
        QVERIFY(signalProcess(remote.localPid(), SIGKILL));
        QTRY_VERIFY_WITH_TIMEOUT(!remote.isRunning(), 5000);
        QTRY_VERIFY_WITH_TIMEOUT(!runsInCloud(pid) && !runsInCloud(child), 10000);
    }

    void anUnreachableHostFailsClearly_data()
    {
        QTest::addColumn<QString>("address");
        QTest::addColumn<int>("port");
        QTest::addColumn<QString>("because");
        QTest::newRow("nothing listens") << QString() << 2 << u"Connection refused"_s;
        QTest::newRow("packets dropped") << u"silent"_s << 22 << u"Connection timed out"_s;
    }
    void anUnreachableHostFailsClearly()
    {
        QFETCH(QString, address);
        QFETCH(int, port);
        RemoteHost host = cloud(quint16(port));
        if (!address.isEmpty())
            host.host = m_lab.silentAddress();
        RemoteProcess remote(host, options(2), u"cloud"_s);
        QSignalSpy finished(&remote, &RemoteProcess::finished);
        QVERIFY(remote.start({u"sleep"_s, u"1000"_s}));
        // Within the connect timeout (2 s) and a margin, never hanging.
        QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, 8000);
        QCOMPARE(remote.exitCode(), 255);
        QVERIFY(!remote.hasStarted());
        QFETCH(QString, because);
        QCOMPARE(remote.errorString(),
                 u"cannot reach cloud (%1): ssh: connect to host %2 port %3: %4"_s.arg(host.url(), host.host)
                     .arg(port)
                     .arg(because));
    }

    void hostileWordsRunNothingExtraOnTheFarHost()
    {
        QTemporaryDir dir; // the namespaces share the file system: a file made over there shows here
        const QString touch = u"touch "_s + dir.filePath(u"injected"_s);
        const QStringList words
            = {u"a; "_s + touch,          u"$("_s + touch + u")"_s,        u"`"_s + touch + u"`"_s,
               u"x\n"_s + touch,          u"it's'; "_s + touch + u"; '"_s, u"\"; "_s + touch + u"; \""_s,
               u"| "_s + touch + u" &"_s, u"-oProxyCommand="_s + touch,    u"$HOME * ~"_s};
        RemoteProcess remote(cloud(), options(), u"cloud"_s);
        QSignalSpy finished(&remote, &RemoteProcess::finished);
        QVERIFY(remote.start(QStringList {u"printf"_s, u"[%s]\\n"_s} + words));
        QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, 20000);
        QCOMPARE(remote.exitCode(), 0);
        QString expected;
        for (const QString& word : words)
            expected += u'[' + word + u"]\n"_s;
        QCOMPARE(remote.lastOutputLines().join(u'\n') + u'\n', expected);
        QVERIFY2(!QFile::exists(dir.filePath(u"injected"_s)), "a word ran a command on the far host");
        // A word that starts with '-' as the program is not read as an option by ssh either.
        RemoteProcess dash(cloud(), options(), u"cloud"_s);
        QVERIFY(dash.start({u"-oProxyCommand="_s + touch}));
        QVERIFY(dash.waitForFinished(20000));
        QCOMPARE(dash.exitCode(), 127);
        QVERIFY(!QFile::exists(dir.filePath(u"injected"_s)));
    }

    // Short commands (checks before a cell, files a side needs): input in, output out, bounded.
    void aCommandRunsWithItsInputAndBoundedOutput()
    {
        const RemoteRun echo = RemoteCommand::run(cloud(), options(), u"cloud"_s, {u"cat"_s}, "one\ntwo\n");
        QVERIFY2(echo.ok(), qPrintable(echo.error));
        QCOMPARE(echo.output, QByteArray("one\ntwo\n"));
        const RemoteRun flood
            = RemoteCommand::run(cloud(), options(), u"cloud"_s,
                                 {u"head"_s, u"-c"_s, u"5000000"_s, u"/dev/zero"_s}, {}, 20000, 1000);
        QVERIFY(flood.ok());
        QCOMPARE(flood.output.size(), 1000);
        const RemoteRun failing = RemoteCommand::run(
            cloud(), options(), u"cloud"_s, {u"sh"_s, u"-c"_s, u"echo 'no such file' >&2; exit 4"_s});
        QCOMPARE(failing.exitCode, 4);
        QCOMPARE(failing.error, u"sh on cloud (%1) ended with status 4: no such file"_s.arg(cloud().url()));
        const RemoteRun refused = RemoteCommand::run(cloud(2), options(2), u"cloud"_s, {u"true"_s});
        QCOMPARE(refused.exitCode, 255);
        QCOMPARE(refused.error,
                 u"cannot reach cloud (%1): ssh: connect to host %2 port 2: Connection refused"_s.arg(
                     cloud(2).url(), cloud().host));
    }

    void aCommandPastItsDeadlineEndsOnBothSides()
    {
        QTemporaryDir dir;
        const QString mark = dir.filePath(u"still-running"_s);
        // Writes a file every second for a minute unless ended.
        const RemoteRun slow = RemoteCommand::run(
            cloud(), options(), u"cloud"_s,
            {u"sh"_s, u"-c"_s, u"for i in $(seq 60); do date > \"$1\"; sleep 1; done"_s, u"slow"_s, mark}, {},
            1000);
        QCOMPARE(slow.exitCode, -1);
        QCOMPARE(slow.error, u"cloud (%1) did not finish sh within 1 s"_s.arg(cloud().url()));
        // The far loop ends too (timeout -s KILL on the far side, a few seconds after): the file
        // stops changing.
        QTRY_VERIFY_WITH_TIMEOUT(!anyProcessMentions(mark), 10000);
    }

    void aFileIsWrittenOnTheFarHostUnderAnyName()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(u"new folder/$(touch injected)'; touch injected; '-x.yaml"_s);
        QByteArray bytes;
        for (int i = 0; i < 256 * 64; ++i)
            bytes.append(char(i % 256));
        const RemoteRun written = RemoteCommand::writeFile(cloud(), options(), u"cloud"_s, path, bytes);
        QVERIFY2(written.ok(), qPrintable(written.error));
        QFile file(path); // the namespaces share this machine's file system
        QVERIFY(file.open(QIODevice::ReadOnly));
        QCOMPARE(file.readAll(), bytes);
        QCOMPARE(file.permissions()
                     & (QFile::ReadGroup | QFile::ReadOther | QFile::WriteGroup | QFile::WriteOther),
                 QFile::Permissions());
        QVERIFY(!QFile::exists(dir.filePath(u"injected"_s)));
        QVERIFY(!QFile::exists(u"injected"_s));
    }

    void aFailingFarProgramSaysWhy()
    {
        RemoteProcess remote(cloud(), options(), u"cloud"_s);
        QVERIFY(remote.start({u"sh"_s, u"-c"_s, u"echo 'no broker at tcp://x' >&2; exit 3"_s}));
        QVERIFY(remote.waitForFinished(20000));
        QCOMPARE(remote.exitCode(), 3);
        QCOMPARE(remote.errorString(),
                 u"the program on cloud (%1) ended with status 3: no broker at tcp://x"_s.arg(cloud().url()));
        QCOMPARE(remote.lastErrorLines(), QStringList {u"no broker at tcp://x"_s});
    }
};

QTEST_GUILESS_MAIN(TestRemoteProcess)
#include "tst_remoteprocess.moc"
