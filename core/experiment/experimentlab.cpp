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
    // The plan reads its hosts (PlanHosts) and core/remote runs programs there, but the lab does not
    // start its sides over ssh yet: a cell fails saying so rather than run both sides here unnoticed.
    if (plan.hosts.any())
        return LocatedError {ExperimentPlan::tr("this version runs both sides of a cell on this machine: "
                                                "remove hosts: from the plan to run it here")};
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
            Result<std::unique_ptr<LinkRelay>> started
                = LinkRelay::start(profile, broker.host(), port, 2u * quint32(seed) + n);
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
    pipeline->setOneClock(true); // every component of the cell stamps with this machine's clock
    live = std::make_unique<LiveSession>();
    if (lab.ros() == 2) {
        Ros2Options dds;
        dds.domain = lab.rosDomain();
        dds.localhostOnly = true;
        if (Status joined = live->startRos2(dds); !joined)
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
