// SPDX-License-Identifier: MIT
#include "sourcecheck.h"

#include "app/cli/clioutput.h"
#include "yaml/secrets.h"
#include "ros/rosgraphpoller.h"
#include "ros2/ros2participant.h"
#include "session/livesession.h"
#include "session/waitingtext.h"

using namespace Qt::StringLiterals;
using CliOutput::err;

SourceCheck::SourceCheck(const LiveSession& live, bool needsMaster, std::function<qint64()> arrived,
                         QString what)
    : m_live(live)
    , m_needsMaster(needsMaster)
    , m_arrived(std::move(arrived))
    , m_what(std::move(what))
{ }

void SourceCheck::check(qint64 elapsedMs)
{
    const MqttConnection* mqtt = m_live.mqtt();
    const bool brokerUp = mqtt->state() == MqttConnection::State::Connected;
    const bool masterUp = m_live.rosGraph()->isReachable();
    m_brokerEver = m_brokerEver || brokerUp;
    m_masterEver = m_masterEver || masterUp;
    m_ros2Ever = m_ros2Ever || m_live.ros2()->graph().participants > 0;
    const bool late = elapsedMs >= kGraceMs;
    const QString broker = Secrets::urlWithoutCredentials(mqtt->profile().url);
    if (brokerUp && m_brokerSaid) {
        err(tr("the broker %1 is reached").arg(broker));
        m_brokerSaid = false;
    } else if (!brokerUp && late && !m_brokerSaid) {
        const QString detail = mqtt->stateDetail();
        err(tr("the broker %1 cannot be reached (%2); still trying")
                .arg(broker, detail.isEmpty() ? MqttConnection::stateText(mqtt->state()) : detail));
        m_brokerSaid = true;
    }
    const QString master = Secrets::urlWithoutCredentials(m_live.rosMasterUri());
    if (masterUp && m_masterSaid) {
        err(tr("the ROS master %1 is reached").arg(master));
        m_masterSaid = false;
    } else if (m_needsMaster && !masterUp && late && !m_masterSaid) {
        err(tr("the ROS master %1 cannot be reached (%2); still trying")
                .arg(master, m_live.rosGraph()->lastError()));
        m_masterSaid = true;
    }
    if (late && !m_silenceSaid && m_arrived() == 0) {
        WaitingText waiting;
        waiting.what = m_what;
        waiting.topics = m_topics;
        waiting.broker = broker;
        waiting.master = m_needsMaster ? master : QString();
        waiting.since = m_since;
        err(tr("%1; still waiting").arg(waiting.text(m_since.addMSecs(elapsedMs))));
        m_silenceSaid = true;
    }
}

QString SourceCheck::nothingHeard(bool ros1, bool ros2) const
{
    if (m_brokerEver || (ros1 && m_masterEver) || (ros2 && m_ros2Ever))
        return {};
    const QString domain = ros2 ? QString::number(m_live.ros2()->options().domain) : QString();
    if (ros1 && ros2)
        return tr("neither the broker nor the master was reached, and nobody was heard on ROS 2 domain %1")
            .arg(domain);
    if (ros2)
        return tr("the broker was not reached and nobody was heard on ROS 2 domain %1").arg(domain);
    return ros1 ? tr("neither the broker nor the master was reached") : tr("the broker was not reached");
}

void sayRos2Restarts(Ros2Participant* participant)
{
    QObject::connect(participant, &Ros2Participant::restartLoopBroken, [](const QString& what) { err(what); });
    QObject::connect(participant, &Ros2Participant::restarted, [](const QString& why) {
        err(SourceCheck::tr("ROS 2 discovery restarted: the DDS process %1").arg(why));
    });
}
