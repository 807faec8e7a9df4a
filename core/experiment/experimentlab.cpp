// SPDX-License-Identifier: MIT
#include "experimentlab.h"

#include "yaml/secrets.h"
#include "experiment/linkrelay.h"
#include "latency/pipeline.h"
#include "mqtt/mqttprofile.h"
#include "session/liveparts.h"
#include "session/livesession.h"
#include "session/measuresession.h"

#include <QDir>
#include <QUrl>

using namespace Qt::StringLiterals;

ExperimentLab::ExperimentLab() = default;
ExperimentLab::~ExperimentLab() = default;

Status ExperimentLab::start(const ExperimentPlan& plan, const CellSettings& s, int seed,
                            const QString& directory, const QString& program)
{
    clock.start();
    DemoLab::Options o;
    o.program = program;
    o.payloadBytes = s.payloadBytes;
    o.rateHz = s.rateHz;
    o.detectionMs = s.detectionMs;
    o.cloudOffsetMs = 0; // one machine, one clock: the crossing stages are the one-way latencies
    o.brokerUrl = plan.brokerUrl;
    o.rosMasterUri = plan.rosMasterUri;
    o.qos = s.qos;
    o.queueSize = s.queueSize;
    o.announceEveryMessage = s.announceEveryMessage;
    o.tlsDirectory = s.tls ? QDir(directory).filePath(u"tls"_s) : QString();
    o.bridgeCommand = s.bridge.command;
    o.ros = plan.ros; // ROS 2: the lab picks a fresh free domain for each cell
    // A side the plan puts on a host of its own starts there over ssh, with the bridgescope the
    // plan names for it (else this one's path: the same installation on every host).
    const QString localProgram = program.isEmpty() ? QCoreApplication::applicationFilePath() : program;
    for (auto [role, host] : {std::pair {u"vehicle"_s, &o.vehicleHost}, std::pair {u"cloud"_s, &o.cloudHost}})
        if (const std::optional<PlanHost>& side = plan.hosts.side(role))
            *host = DemoLab::FarHost {side->host, plan.hosts.programFor(role, localProgram),
                                      SshOptions::fromEnvironment()};
    if (Status servers = lab.startServers(o); !servers)
        return servers;
    if (!s.link.isNone()) {
        // host and port without the user info: a password may hold what QUrl refuses
        const QUrl broker(Secrets::urlWithoutCredentials(lab.brokerUrl()));
        const quint16 port = quint16(broker.port(1883));
        for (auto [relay, n] : {std::pair {&vehicleRelay, 1u}, std::pair {&cloudRelay, 2u}}) {
            LinkProfile profile = s.link;
            if (relay == &cloudRelay)
                profile.thereExtraMs = 0; // the way there leaves the vehicle: only its relay adds it
            // A bridge on another host reaches its relay by this host's address on their link.
            const QString side = relay == &vehicleRelay ? u"vehicle"_s : u"cloud"_s;
            Result<std::unique_ptr<LinkRelay>> started = LinkRelay::start(
                profile, broker.host(), port, 2u * quint32(seed) + n, lab.listenAddress(side));
            if (!started)
                return started.error();
            *relay = std::move(started).value();
        }
        lab.setBridgePort(u"vehicle"_s, vehicleRelay->port());
        lab.setBridgePort(u"cloud"_s, cloudRelay->port());
    }
    if (Status components = lab.startComponents(); !components)
        return components;
    Result<Pipeline> pipeline
        = Pipeline::readFile(plan.pipelinePath.isEmpty() ? lab.pipelinePath() : plan.pipelinePath);
    if (!pipeline)
        return pipeline.error();
    // Every component of a cell on this machine stamps with its clock; with hosts, two clocks
    // (the hosts' clock services measure them).
    pipeline->setOneClock(!plan.hosts.any());
    live = std::make_unique<LiveSession>();
    if (lab.ros() == 2) {
        if (Status joined = live->startRos2(lab.ros2Options()); !joined)
            return joined;
    } else {
        live->setRosMasterUri(lab.rosMasterUri());
    }
    MqttProfile profile = MqttProfile::fromUrl(lab.brokerUrl());
    profile.caFile = lab.caFile();
    live->connectBroker(profile);
    measure = std::make_unique<MeasureSession>(LiveParts::measure(live.get()));
    measure->setRos1(lab.ros() == 1); // a ROS 2 cell has no master: none is asked, none is named
    measure->setPipeline(*pipeline);
    return {};
}
