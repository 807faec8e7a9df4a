// SPDX-License-Identifier: MIT
#pragma once

#include <memory>
#include <QProcess>
#include <QProcessEnvironment>
#include <QString>
#include <QTemporaryDir>

/// How the test broker is configured.
struct TestMosquittoOptions
{
    bool allowAnonymous = true;
    QString passwordFile; ///< mosquitto_passwd file; set allowAnonymous = false with it
    // TLS listener (in addition to nothing: the listener is TLS only when caFile is set)
    QString caFile;
    QString certFile;
    QString keyFile;
    bool requireCertificate = false;
    QString extraConfig; ///< appended to the generated mosquitto.conf
};

/// Starts a real mosquitto and a real rosmaster on free loopback ports for one test, and stops
/// them again (also when the test process dies: they get a parent-death signal).
class TestServers
{
public:
    using MosquittoOptions = TestMosquittoOptions;

    TestServers();
    ~TestServers();
    TestServers(const TestServers&) = delete;
    TestServers& operator=(const TestServers&) = delete;

    bool startMosquitto(const MosquittoOptions& options = {});
    bool startMosquittoOnPort(quint16 port, const MosquittoOptions& options = {});
    void stopMosquitto();
    bool startRosMaster();
    bool startRosMasterOnPort(quint16 port);
    void stopRosMaster();

    quint16 mosquittoPort() const { return m_mosquittoPort; }
    QString brokerUrl() const; ///< tcp://127.0.0.1:PORT (ssl:// for a TLS listener)
    quint16 rosMasterPort() const { return m_masterPort; }
    QString rosMasterUri() const; ///< http://127.0.0.1:PORT/
    bool mosquittoRunning() const;
    bool rosMasterRunning() const;
    qint64 mosquittoPid() const;
    qint64 rosMasterPid() const;

    /// Environment for ROS tools and nodes talking to this master (ROS_MASTER_URI, ROS_IP,
    /// ROS_HOME and ROS_LOG_DIR in the test's temporary directory).
    QProcessEnvironment rosEnvironment() const;
    /// Sets that environment in this process too (roscpp here reads it).
    void exportRosEnvironment() const;
    /// A directory that lives as long as this object.
    QString tempPath() const { return m_dir.path(); }
    QString errorString() const { return m_error; }
    QString mosquittoLog() const;
    QString rosMasterLog() const;

    /// A TCP port on 127.0.0.1 that nothing listens on right now.
    static quint16 freePort();
    /// Waits until something accepts connections on 127.0.0.1:port.
    static bool waitForPort(quint16 port, int timeoutMs);
    /// Sends `request` to 127.0.0.1:port and reads until the server closes; the whole answer.
    static QByteArray httpRequest(quint16 port, const QByteArray& request);
    /// GET http://127.0.0.1:port/path (HTTP/1.0); the body, or empty.
    static QByteArray httpGet(quint16 port, const QString& path);
    /// One sample of the Prometheus text format, by metric name and labels it must have; NaN if none.
    static double metricSample(const QByteArray& metrics, const QString& name, const QStringList& labels);

private:
    std::unique_ptr<QProcess> startProcess(const QString& program, const QStringList& args,
                                           const QProcessEnvironment& env, const QString& logFile);
    static void stopProcess(std::unique_ptr<QProcess>& process);

    QTemporaryDir m_dir;
    std::unique_ptr<QProcess> m_mosquitto;
    std::unique_ptr<QProcess> m_master;
    quint16 m_mosquittoPort = 0;
    quint16 m_masterPort = 0;
    bool m_mosquittoTls = false;
    QString m_error;
};
