// SPDX-License-Identifier: MIT
#include "testservers.h"

#include "base/loopbackports.h"

#include <csignal>
#include <QDir>
#include <QFile>
#include <QTcpSocket>
#include <sys/prctl.h>
#include <unistd.h>

using namespace Qt::StringLiterals;

TestServers::TestServers()
{
    m_dir.setAutoRemove(true);
}

TestServers::~TestServers()
{
    stopMosquitto();
    stopRosMaster();
}

quint16 TestServers::freePort()
{
    return LoopbackPorts::freePort();
}

bool TestServers::waitForPort(quint16 port, int timeoutMs)
{
    return LoopbackPorts::waitForListener(port, timeoutMs);
}

QByteArray TestServers::httpRequest(quint16 port, const QByteArray& request)
{
    QTcpSocket s;
    s.connectToHost(u"127.0.0.1"_s, port);
    if (!s.waitForConnected(3000))
        return {};
    s.write(request);
    QByteArray all;
    while (s.state() == QAbstractSocket::ConnectedState && s.waitForReadyRead(5000))
        all += s.readAll();
    return all + s.readAll();
}

QByteArray TestServers::httpGet(quint16 port, const QString& path)
{
    const QByteArray all = httpRequest(port, "GET " + path.toUtf8() + " HTTP/1.0\r\nHost: 127.0.0.1\r\n\r\n");
    const qsizetype body = all.indexOf("\r\n\r\n");
    return body < 0 ? QByteArray() : all.mid(body + 4);
}

double TestServers::metricSample(const QByteArray& metrics, const QString& name, const QStringList& labels)
{
    for (const QByteArray& raw : metrics.split('\n')) {
        const QString line = QString::fromUtf8(raw);
        if (!line.startsWith(name + u'{'))
            continue;
        bool all = true;
        for (const QString& l : labels)
            all = all && line.contains(l);
        if (all)
            return line.section(u' ', -1).toDouble();
    }
    return qQNaN();
}

std::unique_ptr<QProcess> TestServers::startProcess(const QString& program, const QStringList& args,
                                                    const QProcessEnvironment& env, const QString& logFile)
{
    auto process = std::make_unique<QProcess>();
    process->setProgram(program);
    process->setArguments(args);
    process->setProcessEnvironment(env);
    process->setStandardOutputFile(logFile);
    process->setStandardErrorFile(logFile, QIODevice::Append);
    // No orphans: the server dies with the test process, however that ends.
    process->setChildProcessModifier([] { ::prctl(PR_SET_PDEATHSIG, SIGTERM); });
    process->start();
    if (!process->waitForStarted(5000)) {
        m_error = u"cannot start %1: %2"_s.arg(program, process->errorString());
        return nullptr;
    }
    return process;
}

void TestServers::stopProcess(std::unique_ptr<QProcess>& process)
{
    if (!process)
        return;
    if (process->state() != QProcess::NotRunning) {
        process->terminate();
        if (!process->waitForFinished(5000)) {
            process->kill();
            process->waitForFinished(2000);
        }
    }
    process.reset();
}

bool TestServers::startMosquitto(const MosquittoOptions& options)
{
    for (int attempt = 0; attempt < 5; ++attempt) {
        if (startMosquittoOnPort(freePort(), options))
            return true;
    }
    return false;
}

bool TestServers::startMosquittoOnPort(quint16 port, const MosquittoOptions& options)
{
    stopMosquitto();
    if (port == 0) {
        m_error = u"no free port"_s;
        return false;
    }
    QString conf;
    conf += u"listener %1 127.0.0.1\n"_s.arg(port);
    conf += u"allow_anonymous %1\n"_s.arg(options.allowAnonymous ? u"true"_s : u"false"_s);
    if (!options.passwordFile.isEmpty())
        conf += u"password_file %1\n"_s.arg(options.passwordFile);
    if (!options.caFile.isEmpty()) {
        conf += u"cafile %1\ncertfile %2\nkeyfile %3\n"_s.arg(options.caFile, options.certFile,
                                                              options.keyFile);
        conf += u"require_certificate %1\n"_s.arg(options.requireCertificate ? u"true"_s : u"false"_s);
    }
    conf += u"persistence false\n"_s;
    conf += u"log_dest stdout\nlog_type error\nlog_type warning\nlog_type notice\n"_s;
    // Mosquitto drops root privileges to its own user unless told to stay; the test's files
    // (certificates, password file) belong to the user running the test.
    const QByteArray user = qgetenv("USER");
    if (::geteuid() == 0)
        conf += u"user root\n"_s;
    else if (!user.isEmpty())
        conf += u"user %1\n"_s.arg(QString::fromLocal8Bit(user));
    conf += options.extraConfig;
    const QString confPath = m_dir.filePath(u"mosquitto-%1.conf"_s.arg(port));
    QFile f(confPath);
    if (!f.open(QIODevice::WriteOnly) || f.write(conf.toUtf8()) < 0) {
        m_error = u"cannot write %1"_s.arg(confPath);
        return false;
    }
    f.close();
    m_mosquitto = startProcess(u"mosquitto"_s, {u"-c"_s, confPath}, QProcessEnvironment::systemEnvironment(),
                               m_dir.filePath(u"mosquitto.log"_s));
    if (!m_mosquitto)
        return false;
    if (!waitForPort(port, 10000) || m_mosquitto->state() != QProcess::Running) {
        m_error = u"mosquitto did not listen on %1: %2"_s.arg(port).arg(mosquittoLog());
        stopMosquitto();
        return false;
    }
    m_mosquittoPort = port;
    m_mosquittoTls = !options.caFile.isEmpty();
    return true;
}

void TestServers::stopMosquitto()
{
    stopProcess(m_mosquitto);
}

bool TestServers::startRosMaster()
{
    for (int attempt = 0; attempt < 5; ++attempt) {
        if (startRosMasterOnPort(freePort()))
            return true;
    }
    return false;
}

bool TestServers::startRosMasterOnPort(quint16 port)
{
    stopRosMaster();
    if (port == 0) {
        m_error = u"no free port"_s;
        return false;
    }
    m_masterPort = port;
    QProcessEnvironment env = rosEnvironment();
    m_master = startProcess(u"rosmaster"_s, {u"--core"_s, u"-p"_s, QString::number(port)}, env,
                            m_dir.filePath(u"rosmaster.log"_s));
    if (!m_master)
        return false;
    if (!waitForPort(port, 20000) || m_master->state() != QProcess::Running) {
        m_error = u"rosmaster did not listen on %1: %2"_s.arg(port).arg(rosMasterLog());
        stopRosMaster();
        return false;
    }
    return true;
}

void TestServers::stopRosMaster()
{
    stopProcess(m_master);
}

QString TestServers::brokerUrl() const
{
    return (m_mosquittoTls ? u"ssl://127.0.0.1:%1"_s : u"tcp://127.0.0.1:%1"_s).arg(m_mosquittoPort);
}

QString TestServers::rosMasterUri() const
{
    return u"http://127.0.0.1:%1/"_s.arg(m_masterPort);
}

bool TestServers::mosquittoRunning() const
{
    return m_mosquitto && m_mosquitto->state() == QProcess::Running;
}

bool TestServers::rosMasterRunning() const
{
    return m_master && m_master->state() == QProcess::Running;
}

qint64 TestServers::mosquittoPid() const
{
    return m_mosquitto ? m_mosquitto->processId() : 0;
}

qint64 TestServers::rosMasterPid() const
{
    return m_master ? m_master->processId() : 0;
}

QProcessEnvironment TestServers::rosEnvironment() const
{
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(u"ROS_MASTER_URI"_s, rosMasterUri());
    env.insert(u"ROS_IP"_s, u"127.0.0.1"_s);
    env.remove(u"ROS_HOSTNAME"_s);
    const QString home = m_dir.filePath(u"ros_home"_s);
    QDir().mkpath(home);
    env.insert(u"ROS_HOME"_s, home);
    env.insert(u"ROS_LOG_DIR"_s, home + u"/log"_s);
    return env;
}

static QString readLog(const QString& path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? QString::fromLocal8Bit(f.readAll()) : QString();
}

QString TestServers::mosquittoLog() const
{
    return readLog(m_dir.filePath(u"mosquitto.log"_s));
}

QString TestServers::rosMasterLog() const
{
    return readLog(m_dir.filePath(u"rosmaster.log"_s));
}

void TestServers::exportRosEnvironment() const
{
    const QProcessEnvironment env = rosEnvironment();
    for (const QString& key : {u"ROS_MASTER_URI"_s, u"ROS_IP"_s, u"ROS_HOME"_s, u"ROS_LOG_DIR"_s})
        qputenv(qPrintable(key), env.value(key).toLocal8Bit());
    qunsetenv("ROS_HOSTNAME");
}
