// SPDX-License-Identifier: MIT
#include "twohostlab.h"

#include <csignal>
#include <QAtomicInt>
#include <QDeadlineTimer>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QRandomGenerator>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QThread>
#include <sys/prctl.h>
#include <unistd.h>

using namespace Qt::Literals::StringLiterals;

namespace {

QAtomicInt s_labCount;

// The start time of a process in clock ticks since boot (field 22 of /proc/PID/stat), so a pid
// reused by another process does not keep a dead run's namespaces alive. Empty when it is gone.
QString processStart(qint64 pid)
{
    QFile stat(u"/proc/%1/stat"_s.arg(pid));
    if (!stat.open(QIODevice::ReadOnly))
        return {};
    const QByteArray text = stat.readAll();
    // The command name (field 2) may hold spaces and parentheses: count from the last ')'.
    const int close = text.lastIndexOf(')');
    if (close < 0)
        return {};
    const QList<QByteArray> fields = text.mid(close + 2).split(' ');
    return fields.size() > 19 ? QString::fromLatin1(fields.at(19)) : QString();
}

LabRun runProgram(const QString& program, const QStringList& args, int timeoutMs)
{
    LabRun result;
    QProcess p;
    p.start(program, args);
    if (!p.waitForStarted(5000)) {
        result.err = p.errorString();
        return result;
    }
    p.closeWriteChannel();
    result.finished = p.waitForFinished(timeoutMs);
    if (!result.finished) {
        p.kill();
        p.waitForFinished(2000);
    }
    result.exitCode = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1;
    result.out = QString::fromLocal8Bit(p.readAllStandardOutput());
    result.err = QString::fromLocal8Bit(p.readAllStandardError());
    return result;
}

LabRun runIp(const QStringList& args, int timeoutMs = 10000)
{
    return runProgram(u"ip"_s, args, timeoutMs);
}

QList<qint64> namespacePids(const QString& name)
{
    QList<qint64> pids;
    const LabRun r = runIp({u"netns"_s, u"pids"_s, name});
    for (const QString& word : r.out.split(QLatin1Char('\n'), Qt::SkipEmptyParts))
        pids.append(word.trimmed().toLongLong());
    return pids;
}

// Tears down what a lab leaves: the namespaces' processes, the namespaces and the folder. The same
// script runs in the guard (at the end of every lab, or when the test process dies) and for stale
// labs of dead runs; it waits until every process in the namespaces is gone before deleting them.
const QString s_teardownScript = uR"(
i=0
while [ $i -lt 200 ]; do
    left=
    for ns in "$1" "$2"; do
        p=$(ip netns pids "$ns" 2>/dev/null)
        if [ -n "$p" ]; then kill -KILL $p 2>/dev/null; left=1; fi
    done
    [ -z "$left" ] && break
    sleep 0.05
    i=$((i + 1))
done
ip netns del "$1" 2>/dev/null
ip netns del "$2" 2>/dev/null
[ -n "$3" ] && rm -rf -- "$3"
exit 0
)"_s;

} // namespace

TwoHostLab::TwoHostLab() = default;

TwoHostLab::~TwoHostLab()
{
    down();
}

bool TwoHostLab::fail(const QString& what)
{
    m_error = what;
    down();
    return false;
}

QString TwoHostLab::path(const QString& name) const
{
    return m_dir + u'/' + name;
}

bool TwoHostLab::canRun()
{
    if (::geteuid() != 0) {
        m_skipReason = u"needs root for network namespaces (ip netns), running as uid %1"_s.arg(::geteuid());
        return false;
    }
    for (const QString& program : {u"ip"_s, u"ssh"_s, u"ssh-keygen"_s, u"tc"_s}) {
        if (QStandardPaths::findExecutable(program).isEmpty()) {
            m_skipReason = u"%1 is not installed (scripts/setup.sh installs it)"_s.arg(program);
            return false;
        }
    }
    if (!QFileInfo(u"/usr/sbin/sshd"_s).isExecutable()) {
        m_skipReason = u"/usr/sbin/sshd is not installed (openssh-server; scripts/setup.sh installs it)"_s;
        return false;
    }
    const QString probe = u"bs-lab-probe-%1"_s.arg(::getpid());
    const LabRun add = runIp({u"netns"_s, u"add"_s, probe});
    if (add.exitCode != 0) {
        m_skipReason = u"ip netns add fails here: %1"_s.arg(add.err.trimmed());
        return false;
    }
    runIp({u"netns"_s, u"del"_s, probe});
    return true;
}

bool TwoHostLab::up()
{
    if (m_up)
        return true;
    m_skipReason.clear();
    m_error.clear();
    if (!canRun())
        return false;
    removeStale();

    const QString stem = u"bs-lab-%1-%2-%3"_s.arg(::getpid())
                             .arg(processStart(::getpid()))
                             .arg(s_labCount.fetchAndAddRelaxed(1));
    m_names[Vehicle] = stem + u"-v"_s;
    m_names[Cloud] = stem + u"-c"_s;
    // A private /30 per run: 10.R1.R2.(4k+1) and (4k+2).
    auto* rng = QRandomGenerator::global();
    const QString net = u"10.%1.%2."_s.arg(rng->bounded(256)).arg(rng->bounded(256));
    const int base = int(rng->bounded(64)) * 4;
    m_addresses[Vehicle] = net + QString::number(base + 1);
    m_addresses[Cloud] = net + QString::number(base + 2);
    m_silent = u"192.0.2.1"_s; // TEST-NET-1, routed to the cloud, which forwards nothing

    const QString tmp = QDir::tempPath() + u'/' + stem + u".XXXXXX"_s;
    QByteArray templ = QFile::encodeName(tmp);
    if (!::mkdtemp(templ.data()))
        return fail(u"cannot make a folder %1"_s.arg(tmp));
    m_dir = QFile::decodeName(templ);

    if (!startGuard() || !makeKeys() || !makeNetwork() || !startSshd(Vehicle) || !startSshd(Cloud))
        return false;

    // Both sshds answer over the veth, with the per-run key, before the lab counts as up.
    for (Side side : {Vehicle, Cloud}) {
        const QDeadlineTimer deadline(15000);
        LabRun r;
        do {
            r = runProgram(sshProgram(Vehicle), {u"root@"_s + address(side), u"true"_s}, 10000);
            if (r.exitCode == 0)
                break;
            QThread::msleep(50); // polling a server that is starting; not a test's synchronisation
        } while (!deadline.hasExpired());
        if (r.exitCode != 0)
            return fail(u"ssh into %1 failed: %2"_s.arg(address(side), r.err.trimmed()));
    }
    m_up = true;
    return true;
}

bool TwoHostLab::startGuard()
{
    m_guard = std::make_unique<QProcess>();
    m_guard->setProgram(u"/bin/sh"_s);
    // The script waits for the end of its stdin: down() closes it, and so does the test's death.
    m_guard->setArguments({u"-c"_s, u"cat >/dev/null\n"_s + s_teardownScript, u"bs-lab-guard"_s,
                           m_names[Vehicle], m_names[Cloud], m_dir});
    m_guard->setStandardOutputFile(QProcess::nullDevice());
    m_guard->setStandardErrorFile(QProcess::nullDevice());
    // Its own session: ctest killing the test's process group leaves the guard to clean up.
    m_guard->setChildProcessModifier([] { ::setsid(); });
    m_guard->start();
    if (!m_guard->waitForStarted(5000)) {
        m_guard.reset();
        return fail(u"cannot start the lab's guard process"_s);
    }
    return true;
}

bool TwoHostLab::makeKeys()
{
    QStringList hostLines;
    for (const QString& key : {u"client"_s, u"host-v"_s, u"host-c"_s, u"stranger"_s}) {
        const LabRun r = runProgram(u"ssh-keygen"_s,
                                    {u"-q"_s, u"-t"_s, u"ed25519"_s, u"-N"_s, QString(), u"-C"_s,
                                     u"bs-lab-"_s + key, u"-f"_s, path(key)},
                                    20000);
        if (r.exitCode != 0)
            return fail(u"ssh-keygen failed: %1"_s.arg(r.err.trimmed()));
    }
    if (!QFile::copy(path(u"client.pub"_s), path(u"authorized_keys"_s)))
        return fail(u"cannot write authorized_keys"_s);
    for (Side side : {Vehicle, Cloud}) {
        QFile pub(path(side == Vehicle ? u"host-v.pub"_s : u"host-c.pub"_s));
        if (!pub.open(QIODevice::ReadOnly))
            return fail(u"cannot read a host key"_s);
        const QStringList words = QString::fromLatin1(pub.readAll()).split(u' ');
        hostLines << u"%1,127.0.0.1 %2 %3"_s.arg(address(side), words.value(0), words.value(1));
    }
    QFile known(knownHosts());
    QFile config(path(u"ssh_config"_s));
    if (!known.open(QIODevice::WriteOnly) || !config.open(QIODevice::WriteOnly))
        return fail(u"cannot write the client's files"_s);
    known.write(hostLines.join(u'\n').toLatin1() + '\n');
    config.write(u"Host *\n"
                 "    IdentityFile %1\n"
                 "    IdentitiesOnly yes\n"
                 "    IdentityAgent none\n"
                 "    UserKnownHostsFile %2\n"
                 "    GlobalKnownHostsFile /dev/null\n"
                 "    StrictHostKeyChecking yes\n"
                 "    BatchMode yes\n"
                 "    LogLevel ERROR\n"_s.arg(clientKey(), knownHosts())
                     .toLocal8Bit());
    config.close();
    for (Side side : {Vehicle, Cloud}) {
        QFile wrapper(sshProgram(side));
        if (!wrapper.open(QIODevice::WriteOnly))
            return fail(u"cannot write the ssh wrapper"_s);
        wrapper.write(u"#!/bin/sh\nexec ip netns exec '%1' ssh -F '%2' \"$@\"\n"_s
                          .arg(netns(side), path(u"ssh_config"_s))
                          .toLocal8Bit());
        wrapper.setPermissions(QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner);
    }
    return true;
}

bool TwoHostLab::makeNetwork()
{
    for (Side side : {Vehicle, Cloud}) {
        const LabRun r = runIp({u"netns"_s, u"add"_s, netns(side)});
        if (r.exitCode != 0)
            return fail(u"ip netns add %1: %2"_s.arg(netns(side), r.err.trimmed()));
    }
    // The veth's ends are made inside the namespaces: no name in the machine's own namespace, so
    // parallel labs cannot collide.
    const QList<QStringList> steps = {
        {u"link"_s, u"add"_s, u"bs0"_s, u"netns"_s, netns(Vehicle), u"type"_s, u"veth"_s, u"peer"_s,
         u"name"_s, u"bs0"_s, u"netns"_s, netns(Cloud)},
        {u"-n"_s, netns(Vehicle), u"addr"_s, u"add"_s, address(Vehicle) + u"/30"_s, u"dev"_s, u"bs0"_s},
        {u"-n"_s, netns(Cloud), u"addr"_s, u"add"_s, address(Cloud) + u"/30"_s, u"dev"_s, u"bs0"_s},
        {u"-n"_s, netns(Vehicle), u"link"_s, u"set"_s, u"lo"_s, u"up"_s},
        {u"-n"_s, netns(Cloud), u"link"_s, u"set"_s, u"lo"_s, u"up"_s},
        {u"-n"_s, netns(Vehicle), u"link"_s, u"set"_s, u"bs0"_s, u"up"_s},
        {u"-n"_s, netns(Cloud), u"link"_s, u"set"_s, u"bs0"_s, u"up"_s},
        {u"-n"_s, netns(Vehicle), u"route"_s, u"add"_s, m_silent + u"/32"_s, u"via"_s, address(Cloud)},
    };
    for (const QStringList& step : steps) {
        const LabRun r = runIp(step);
        if (r.exitCode != 0)
            return fail(u"ip %1: %2"_s.arg(step.join(u' '), r.err.trimmed()));
    }
    return true;
}

bool TwoHostLab::startSshd(Side side)
{
    const QString tag = side == Vehicle ? u"v"_s : u"c"_s;
    QFile config(path(u"sshd_config-"_s + tag));
    if (!config.open(QIODevice::WriteOnly))
        return fail(u"cannot write sshd_config"_s);
    // StrictModes off: the keys live in a temporary folder, not in root's home.
    config.write(u"ListenAddress %1:22\n"
                 "ListenAddress 127.0.0.1:22\n"
                 "HostKey %2\n"
                 "PidFile %3\n"
                 "AuthorizedKeysFile %4\n"
                 "PubkeyAuthentication yes\n"
                 "PasswordAuthentication no\n"
                 "KbdInteractiveAuthentication no\n"
                 "PermitRootLogin prohibit-password\n"
                 "StrictModes no\n"
                 "UsePAM no\n"
                 "UseDNS no\n"
                 "LogLevel VERBOSE\n"_s
                     .arg(address(side), path(u"host-"_s + tag), path(u"sshd-"_s + tag + u".pid"_s),
                          path(u"authorized_keys"_s))
                     .toLocal8Bit());
    config.close();
    // sshd's privilege separation folder; Debian's service makes it, a bare sshd does not.
    QDir().mkpath(u"/run/sshd"_s);
    // sshd daemonizes into the namespace; the guard kills it with everything else there.
    const LabRun r = run(
        side, {u"/usr/sbin/sshd"_s, u"-f"_s, config.fileName(), u"-E"_s, path(u"sshd-"_s + tag + u".log"_s)});
    if (r.exitCode != 0)
        return fail(u"sshd in %1 did not start: %2"_s.arg(netns(side), r.err.trimmed()));
    return true;
}

void TwoHostLab::down()
{
    m_up = false;
    if (!m_guard)
        return;
    m_guard->closeWriteChannel();
    if (!m_guard->waitForFinished(30000))
        qWarning("two-host lab: the teardown of %s did not finish", qPrintable(m_names[Vehicle]));
    m_guard.reset();
}

QString TwoHostLab::netns(Side side) const
{
    return m_names[side];
}

QString TwoHostLab::address(Side side) const
{
    return m_addresses[side];
}

QString TwoHostLab::sshUrl(Side side) const
{
    return u"ssh://root@"_s + address(side);
}

QString TwoHostLab::clientKey() const
{
    return path(u"client"_s);
}

QString TwoHostLab::knownHosts() const
{
    return path(u"known_hosts"_s);
}

QString TwoHostLab::sshProgram(Side from) const
{
    return path(from == Vehicle ? u"ssh-from-v"_s : u"ssh-from-c"_s);
}

QString TwoHostLab::silentAddress() const
{
    return m_silent;
}

QStringList TwoHostLab::inNamespace(Side side, const QStringList& argv) const
{
    return QStringList {u"ip"_s, u"netns"_s, u"exec"_s, netns(side)} + argv;
}

LabRun TwoHostLab::run(Side side, const QStringList& argv, int timeoutMs) const
{
    const QStringList all = inNamespace(side, argv);
    return runProgram(all.first(), all.mid(1), timeoutMs);
}

std::unique_ptr<QProcess> TwoHostLab::startProcess(Side side, const QString& name, const QStringList& argv)
{
    const QStringList all = inNamespace(side, argv);
    auto process = std::make_unique<QProcess>();
    process->setStandardOutputFile(path(name + u".log"_s));
    process->setStandardErrorFile(path(name + u".log"_s), QIODevice::Append);
    process->setChildProcessModifier([] { ::prctl(PR_SET_PDEATHSIG, SIGTERM); });
    process->start(all.first(), all.mid(1));
    if (!process->waitForStarted(5000)) {
        m_error = u"cannot start %1 in %2: %3"_s.arg(argv.value(0), netns(side), process->errorString());
        return nullptr;
    }
    return process;
}

QString TwoHostLab::log(const QString& name) const
{
    QFile file(path(name + u".log"_s));
    return file.open(QIODevice::ReadOnly) ? QString::fromLocal8Bit(file.readAll()) : QString();
}

bool TwoHostLab::setRate(Side side, const QString& rate)
{
    const LabRun r = run(side,
                         {u"tc"_s, u"qdisc"_s, u"replace"_s, u"dev"_s, u"bs0"_s, u"root"_s, u"tbf"_s,
                          u"rate"_s, rate, u"burst"_s, u"32kbit"_s, u"latency"_s, u"400ms"_s});
    if (r.exitCode != 0) {
        m_error = u"tc tbf %1 on %2: %3"_s.arg(rate, netns(side), r.err.trimmed());
        return false;
    }
    return true;
}

QList<qint64> TwoHostLab::pids(Side side) const
{
    return namespacePids(netns(side));
}

qint64 TwoHostLab::sshdPid(Side side) const
{
    QFile file(path(side == Vehicle ? u"sshd-v.pid"_s : u"sshd-c.pid"_s));
    if (!file.open(QIODevice::ReadOnly))
        return 0;
    return file.readAll().trimmed().toLongLong();
}

QStringList TwoHostLab::labNamespaces()
{
    QStringList names;
    const LabRun r = runIp({u"netns"_s, u"list"_s});
    for (const QString& line : r.out.split(QLatin1Char('\n'), Qt::SkipEmptyParts)) {
        const QString name = line.section(QLatin1Char(' '), 0, 0);
        if (name.startsWith(u"bs-lab-"_s))
            names << name;
    }
    return names;
}

int TwoHostLab::removeStale()
{
    static const QRegularExpression labName(u"^bs-lab-(\\d+)-(\\d+)-(\\d+)-[vc]$"_s);
    int removed = 0;
    for (const QString& name : labNamespaces()) {
        const QRegularExpressionMatch m = labName.match(name);
        if (!m.hasMatch())
            continue;
        if (processStart(m.captured(1).toLongLong()) == m.captured(2))
            continue; // its run is still alive: never touch a parallel test's lab
        const QString stem = name.chopped(2);
        QDir tmp(QDir::tempPath());
        const QStringList dirs = tmp.entryList({stem + u".*"_s}, QDir::Dirs);
        runProgram(u"/bin/sh"_s,
                   {u"-c"_s, s_teardownScript, u"bs-lab-stale"_s, name, QString(),
                    dirs.isEmpty() ? QString() : tmp.filePath(dirs.first())},
                   30000);
        ++removed;
    }
    return removed;
}
