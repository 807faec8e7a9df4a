// SPDX-License-Identifier: MIT
#pragma once

#include "base/result.h"
#include "remote/remotehost.h"
#include "remote/sshcommand.h"
#include "ros2/ros2types.h"

#include <memory>
#include <optional>
#include <QCoreApplication>
#include <QString>
#include <QStringList>

class QProcess;

/// The embedded demo lab: everything the paper's experiment needs, on this machine, started by
/// Bridgescope and stopped with it.
///
/// A private mosquitto and rosmaster on free loopback ports (or the ones given), a vehicle and a cloud
/// reference bridge (`bridgescope bridge`) from generated paper-shaped configs, the vehicle node (a 0.18 MB
/// point cloud at 10 Hz) and the cloud's object detection (about 40 ms), the cloud's clock ahead
/// by `cloudOffsetMs`; stamps at every component. Every child gets SIGTERM when this process dies
/// (PR_SET_PDEATHSIG), so even a crash leaves no process behind.
///
/// A side may run on another host (Options::vehicleHost, cloudHost): its bridge, its node and its
/// clock service start there over OpenSSH (RemoteProcess: they end with their ssh session, also
/// when this process is killed), its config goes to a private folder there, and the servers here
/// listen also on the address that host reaches this one by (its SSH_CONNECTION).
class DemoLab
{
    Q_DECLARE_TR_FUNCTIONS(DemoLab)
public:
    /// A side on another host, reached over OpenSSH (keys or an agent, BatchMode), with a broker
    /// without credentials or TLS: nothing secret has to travel to that host. With ROS 2 the
    /// lab's domain spans both hosts (DDS discovery on every interface).
    struct FarHost
    {
        RemoteHost host;
        QString program; ///< bridgescope on that host; empty: this program's path
        SshOptions ssh = SshOptions::fromEnvironment();
    };

    struct Options
    {
        QString program; ///< the bridgescope binary (default: this program)
        int payloadBytes = 180'000;
        double rateHz = 10;
        double detectionMs = 40;
        double cloudOffsetMs = 35;
        QString brokerUrl; ///< a broker to use instead of a private mosquitto
        QString rosMasterUri; ///< a master to use instead of a private rosmaster
        // What an experiment varies (the demo keeps the defaults).
        int qos = 0; ///< of every mapping
        int queueSize = 1; ///< advanced.ros.queue_size of every mapping
        bool announceEveryMessage = false; ///< reference bridges announce the type before every message
        /// A folder with ca.crt, server.crt and server.key: the private mosquitto listens with TLS
        /// and the bridges verify it with ca.crt.
        QString tlsDirectory;
        /// Empty: the reference bridges. Otherwise a shell command per bridge, with {config}, {name},
        /// {broker_host}, {broker_port}, {ros_master} and {ros_domain} replaced (shell-quoted); with
        /// ROS 2 {config} is a ROS 2 params file whose node is {name}.
        QString bridgeCommand;
        /// 1: a rosmaster, ROS 1 nodes and bridges. 2: DDS nodes and ROS 2 bridges on a private
        /// domain on 127.0.0.1 (ROS_LOCALHOST_ONLY=1), no master.
        int ros = 1;
        /// With ROS 2: the domain; -1, a free one (see freeDomain()).
        int rosDomain = -1;
        std::optional<FarHost> vehicleHost; ///< the vehicle side's host; none: this one
        std::optional<FarHost> cloudHost; ///< the cloud side's host; none: this one
    };

    DemoLab();
    ~DemoLab(); ///< stops everything
    DemoLab(const DemoLab&) = delete;
    DemoLab& operator=(const DemoLab&) = delete;

    /// Starts the servers (waiting until they listen, a second or two) and the components.
    Status start(const Options& options);
    /// The same in two steps, for an experiment that puts a relay between a bridge and the broker.
    Status startServers(const Options& options);
    /// The port a side's bridge ("vehicle", "cloud") connects to instead of the broker's (a relay
    /// on 127.0.0.1 in front of it); before startComponents().
    void setBridgePort(const QString& side, quint16 port);
    Status startComponents();
    /// startServers() without waiting, for a window that shows progress meanwhile: launches the
    /// servers; then pollServers() until they listen (each poll a loopback connect per server).
    Status launchServers(const Options& options);
    enum class Poll { Waiting, Ready, Failed };
    /// Whether the launched servers listen now; Failed (with `error`) when one stopped.
    Poll pollServers(QString* error);
    void stop();
    bool isRunning() const;
    /// What stopped running meanwhile (empty while everything runs).
    QString failure() const;

    /// The address a side's host reaches this one by (the lab's servers and relays listen there):
    /// 127.0.0.1 for a side on this host. Known once the servers are launched.
    QString listenAddress(const QString& side) const;
    /// Whether a side runs on another host.
    bool isFar(const QString& side) const;
    /// With ROS 2: whether the lab's domain stays on this host's loopback (no side elsewhere);
    /// with a far side, the domain spans the hosts and whoever measures it joins it on every
    /// interface.
    bool isLocalhostOnly() const;
    /// How whoever measures joins the lab's ROS 2 domain: its id, on this host only, or (with a far
    /// side) on every interface with the far hosts as static peers.
    Ros2Options ros2Options() const;

    QString brokerUrl() const; ///< ssl:// with TLS
    /// The broker URL a side's bridge is given (through a pipe, never its command line): the
    /// broker's, with the relay's host and port when a relay is in between.
    QString bridgeBrokerUrl(const QString& side) const;
    QString caFile() const; ///< the CA that signed the broker's certificate (TLS), else empty
    QString rosMasterUri() const; ///< empty with ROS 2
    int ros() const; ///< 1 or 2, as started
    int rosDomain() const; ///< with ROS 2 the lab's domain, else -1
    QString vehicleConfigPath() const; ///< the vehicle bridge's config (for the Map page)
    QString cloudConfigPath() const;
    QString pipelinePath() const; ///< the paper's pipeline with hosts (for the Measure page)
    QString directory() const; ///< configs and logs
    QList<qint64> processIds() const;

    static QStringList pipelineTopics();
    /// A ROS 2 domain from `first` to `last` that no participant on this host uses now (the first
    /// participant's discovery port, 7410 + 250 × domain, is free on 127.0.0.1), tried from a
    /// different one each call so that labs one after the other get fresh domains; -1 when none.
    static int freeDomain(int first = 161, int last = 232);

private:
    struct Private;
    std::unique_ptr<Private> d;
};
