// SPDX-License-Identifier: MIT
#pragma once

#include <memory>
#include <QCoreApplication>
#include <QString>
#include <QStringList>

class QProcess;

/// The embedded demo lab: everything the paper's experiment needs, on this machine, started by
/// Bridgescope and stopped with it.
///
/// A private mosquitto and rosmaster on free loopback ports (or the ones given), a vehicle and a cloud reference
/// bridge (`bridgescope bridge`) from generated paper-shaped configs, the vehicle node (a 0.18 MB
/// point cloud at 10 Hz) and the cloud's object detection (about 40 ms), the cloud's clock ahead
/// by `cloudOffsetMs`; stamps at every component. Every child gets SIGTERM when this process dies
/// (PR_SET_PDEATHSIG), so even a crash leaves no process behind.
class DemoLab
{
    Q_DECLARE_TR_FUNCTIONS(DemoLab)
public:
    struct Options
    {
        QString program; ///< the bridgescope binary (default: this program)
        int payloadBytes = 180'000;
        double rateHz = 10;
        double detectionMs = 40;
        double cloudOffsetMs = 35;
        QString brokerUrl; ///< a broker to use instead of a private mosquitto
        QString rosMasterUri; ///< a master to use instead of a private rosmaster
    };

    DemoLab();
    ~DemoLab(); ///< stops everything
    DemoLab(const DemoLab&) = delete;
    DemoLab& operator=(const DemoLab&) = delete;

    /// Starts the servers (waiting until they listen, a second or two) and the components.
    bool start(const Options& options, QString* error);
    void stop();
    bool isRunning() const;
    /// What stopped running meanwhile (empty while everything runs).
    QString failure() const;

    QString brokerUrl() const;
    QString rosMasterUri() const;
    QString vehicleConfigPath() const; ///< the vehicle bridge's config (for the Map page)
    QString cloudConfigPath() const;
    QString pipelinePath() const; ///< the paper's pipeline with hosts (for the Measure page)
    QString directory() const; ///< configs and logs
    QList<qint64> processIds() const;

    static QStringList pipelineTopics();

private:
    struct Private;
    std::unique_ptr<Private> d;
};
