// SPDX-License-Identifier: MIT
#include "experimentlab.h"

#include "yaml/secrets.h"
#include "experiment/linkrelay.h"
#include "latency/pipeline.h"
#include "mqtt/mqttprofile.h"
#include "session/livesession.h"
#include "session/measuresession.h"

#include <QDir>
#include <QUrl>

using namespace Qt::StringLiterals;

ExperimentLab::ExperimentLab() = default;
ExperimentLab::~ExperimentLab() = default;

bool ExperimentLab::start(const ExperimentPlan& plan, const CellSettings& s, int seed,
                          const QString& directory, const QString& program, QString* why)
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
    if (!lab.startServers(o, why))
        return false;
    if (!s.link.isNone()) {
        // host and port without the user info: a password may hold what QUrl refuses
        const QUrl broker(Secrets::urlWithoutCredentials(lab.brokerUrl()));
        const quint16 port = quint16(broker.port(1883));
        vehicleRelay = LinkRelay::start(s.link, broker.host(), port, why, 2u * quint32(seed) + 1);
        cloudRelay = vehicleRelay ? LinkRelay::start(s.link, broker.host(), port, why, 2u * quint32(seed) + 2)
                                  : nullptr;
        if (!cloudRelay)
            return false;
        lab.setBridgePort(u"vehicle"_s, vehicleRelay->port());
        lab.setBridgePort(u"cloud"_s, cloudRelay->port());
    }
    if (!lab.startComponents(why))
        return false;
    Result<Pipeline> pipeline
        = Pipeline::readFile(plan.pipelinePath.isEmpty() ? lab.pipelinePath() : plan.pipelinePath);
    if (!pipeline) {
        if (why)
            *why = pipeline.error().toString();
        return false;
    }
    pipeline->setOneClock(true); // every component of the cell stamps with this machine's clock
    live = std::make_unique<LiveSession>();
    if (lab.ros() == 2) {
        Ros2Options dds;
        dds.domain = lab.rosDomain();
        dds.localhostOnly = true;
        if (!live->startRos2(dds, why))
            return false;
    } else {
        live->setRosMasterUri(lab.rosMasterUri());
    }
    MqttProfile profile = MqttProfile::fromUrl(lab.brokerUrl());
    profile.caFile = lab.caFile();
    live->connectBroker(profile);
    measure = std::make_unique<MeasureSession>(live.get());
    measure->setRos1(lab.ros() == 1); // a ROS 2 cell has no master: none is asked, none is named
    measure->setPipeline(*pipeline);
    return true;
}
