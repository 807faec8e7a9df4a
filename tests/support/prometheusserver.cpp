// SPDX-License-Identifier: MIT
#include "prometheusserver.h"

#include "testservers.h"

#include <csignal>
#include <QDeadlineTimer>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTest>
#include <QUrl>
#include <QUrlQuery>
#include <sys/prctl.h>

using namespace Qt::StringLiterals;

bool PrometheusServer::start(const QString& configYaml, const QStringList& extraArgs)
{
    if (!QFile::exists(QString::fromLatin1(kProgram))) {
        m_error = u"%1 is missing (Debian's prometheus package; scripts/setup.sh installs it)"_s.arg(
            QString::fromLatin1(kProgram));
        return false;
    }
    QFile config(m_dir.filePath(u"prometheus.yml"_s));
    if (!config.open(QIODevice::WriteOnly) || config.write(configYaml.toUtf8()) < 0) {
        m_error = u"cannot write %1"_s.arg(config.fileName());
        return false;
    }
    config.close();
    m_port = TestServers::freePort();
    QStringList args {u"--config.file="_s + config.fileName(),
                      u"--web.listen-address=127.0.0.1:%1"_s.arg(m_port), u"--web.enable-lifecycle"_s};
    if (!extraArgs.contains(u"--enable-feature=agent"_s))
        args << u"--storage.tsdb.path="_s + m_dir.filePath(u"data"_s);
    else
        args << u"--storage.agent.path="_s + m_dir.filePath(u"agent"_s);
    m_args = args + extraArgs;
    return launch();
}

bool PrometheusServer::restart()
{
    stop();
    return launch();
}

bool PrometheusServer::launch()
{
    m_process = std::make_unique<QProcess>();
    m_process->setProgram(QString::fromLatin1(kProgram));
    m_process->setArguments(m_args);
    m_process->setStandardOutputFile(m_dir.filePath(u"log"_s), QIODevice::Append); // a restart adds
    m_process->setStandardErrorFile(m_dir.filePath(u"log"_s), QIODevice::Append);
    m_process->setChildProcessModifier([] { ::prctl(PR_SET_PDEATHSIG, SIGTERM); });
    m_process->start();
    if (!m_process->waitForStarted(5000)) {
        m_error = u"prometheus did not start: "_s + m_process->errorString();
        return false;
    }
    const QDeadlineTimer deadline(30000);
    while (!deadline.hasExpired()) {
        if (TestServers::httpGet(m_port, u"/-/ready"_s).contains("Ready"))
            return true;
        if (m_process->state() != QProcess::Running)
            break;
        QTest::qWait(100); // polls the child's start, not a condition of the code under test
    }
    m_error = u"prometheus did not get ready:\n"_s + log();
    return false;
}

void PrometheusServer::stop()
{
    if (!m_process)
        return;
    m_process->terminate();
    if (!m_process->waitForFinished(15000))
        m_process->kill();
    m_process->waitForFinished(5000);
    m_process.reset();
}

PrometheusServer::~PrometheusServer()
{
    stop();
}

QString PrometheusServer::address() const
{
    return u"127.0.0.1:%1"_s.arg(m_port);
}

QString PrometheusServer::log() const
{
    QFile f(m_dir.filePath(u"log"_s));
    return f.open(QIODevice::ReadOnly) ? QString::fromUtf8(f.readAll().right(20000)) : QString();
}

QByteArray PrometheusServer::get(const QString& pathAndQuery) const
{
    return TestServers::httpGet(m_port, pathAndQuery);
}

QJsonArray PrometheusServer::query(const QString& promql) const
{
    QUrlQuery q;
    q.addQueryItem(u"query"_s, promql);
    const QByteArray body = get(u"/api/v1/query?"_s + q.toString(QUrl::FullyEncoded));
    const QJsonObject answer = QJsonDocument::fromJson(body).object();
    if (answer.value(u"status"_s).toString() != u"success"_s)
        qWarning("query %s: %s", qPrintable(promql), body.left(500).constData());
    return answer.value(u"data"_s).toObject().value(u"result"_s).toArray();
}

double PrometheusServer::value(const QString& promql) const
{
    const QJsonArray result = query(promql);
    return result.isEmpty()
        ? qQNaN()
        : result.first().toObject().value(u"value"_s).toArray().at(1).toString().toDouble();
}
