// SPDX-License-Identifier: MIT
#pragma once

#include <memory>
#include <QJsonArray>
#include <QProcess>
#include <QString>
#include <QTemporaryDir>

/// A real Prometheus server (Debian's /usr/bin/prometheus) on a free loopback port, with its own
/// data folder, for the tests of what `watch --metrics` serves: scrapes, federation, remote write
/// and the rules. It dies with the test process.
class PrometheusServer
{
public:
    static constexpr const char* kProgram = "/usr/bin/prometheus";
    /// Writes `configYaml` and starts the server with `extraArgs` (e.g. --enable-feature=agent);
    /// false with errorString() when it did not answer /-/ready within 30 s.
    bool start(const QString& configYaml, const QStringList& extraArgs = {});
    /// After stop(): the same server again, on the same port with the same data (a restart, as an
    /// operator's); false with errorString() as start().
    bool restart();
    void stop();
    bool isRunning() const { return m_process && m_process->state() == QProcess::Running; }
    ~PrometheusServer();
    quint16 port() const { return m_port; }
    QString address() const; ///< 127.0.0.1:PORT
    QString errorString() const { return m_error; }
    QString log() const;
    /// The `result` array of an instant query at now, empty on any error (said in the log).
    QJsonArray query(const QString& promql) const;
    /// The first result's value, NaN when there is none.
    double value(const QString& promql) const;
    /// GET of a path of the server's HTTP API.
    QByteArray get(const QString& pathAndQuery) const;

private:
    bool launch();

    QTemporaryDir m_dir;
    QStringList m_args;
    std::unique_ptr<QProcess> m_process;
    quint16 m_port = 0;
    QString m_error;
};
