// SPDX-License-Identifier: MIT
#include "ros2/ros2participant.h"

#include "base/logging.h"

#include <QCoreApplication>
#include <QHostAddress>
#include <QtGlobal>

using namespace Qt::StringLiterals;

Ros2Options Ros2Options::fromEnvironment(QString* error)
{
    Ros2Options o;
    const QString domain = qEnvironmentVariable("ROS_DOMAIN_ID").trimmed();
    if (!domain.isEmpty()) {
        bool ok = false;
        const int d = domain.toInt(&ok);
        if (ok && d >= 0 && d <= kMaxDomain)
            o.domain = d;
        else if (error)
            *error = QCoreApplication::translate("Ros2Options",
                                                 "ROS_DOMAIN_ID is \"%1\", not a domain from 0 to %2")
                         .arg(domain.left(40))
                         .arg(kMaxDomain);
    }
    o.localhostOnly = qEnvironmentVariable("ROS_LOCALHOST_ONLY").trimmed() == QLatin1String("1");
    const QStringList peers
        = qEnvironmentVariable("ROS_STATIC_PEERS").split(QLatin1Char(';'), Qt::SkipEmptyParts);
    for (const QString& peer : peers) {
        const QHostAddress address(peer.trimmed());
        if (address.isNull() || o.staticPeers.size() >= kMaxStaticPeers) {
            if (error)
                *error
                    = QCoreApplication::translate("Ros2Options",
                                                  "ROS_STATIC_PEERS takes at most %1 IP addresses separated "
                                                  "by ';', not \"%2\"")
                          .arg(kMaxStaticPeers)
                          .arg(peer.left(40));
            o.staticPeers.clear();
            break;
        }
        o.staticPeers << address.toString();
    }
    return o;
}

Ros2Participant::Ros2Participant(QObject* parent)
    : QObject(parent)
    , m_supervisor(this)
    , m_link(m_supervisor, this)
{
    m_supervisor.setCauseOfEnd([this](bool ranInto) {
        return DdsChildSupervisor::Cause {m_link.makingRequests(), m_link.causedByPeers(ranInto)};
    });
    connect(&m_supervisor, &DdsChildSupervisor::launched, this, &Ros2Participant::onLaunched);
    connect(&m_supervisor, &DdsChildSupervisor::launchFailed, this, &Ros2Participant::onLaunchFailed);
    connect(&m_supervisor, &DdsChildSupervisor::childFailed, this, &Ros2Participant::onChildFailed);
    connect(&m_supervisor, &DdsChildSupervisor::frameRead, this, [this](const Ros2Protocol::Frame& f) {
        if (!m_link.handle(f))
            m_supervisor.rejectFrame(f.kind);
    });
    connect(&m_link, &Ros2Link::started, this, [this] { emit joined(true); });
    connect(&m_link, &Ros2Link::startFailed, this, [this](const QString& why) {
        m_error = why;
        emit graphChanged(m_link.graph());
        emit joined(false);
    });
    connect(&m_link, &Ros2Link::graphChanged, this, &Ros2Participant::graphChanged);
    connect(&m_link, &Ros2Link::monitorFailed, this, &Ros2Participant::monitorFailed);
}

Ros2Participant::~Ros2Participant()
{
    m_supervisor.disconnect(this);
    m_link.disconnect(this);
    m_link.endpoints().disconnect(this);
}

bool Ros2Participant::isRunning() const
{
    return m_supervisor.isWanted() && m_error.isEmpty(); // also while a restart waits for its backoff
}

namespace {
/// "1 ROS 2 request quarantined (last: …)", or empty.
QString quarantineText(const Ros2EndpointLink& node)
{
    if (node.quarantined() == 0)
        return {};
    return Ros2Participant::tr("%n ROS 2 request(s) quarantined (last: %1)", nullptr, node.quarantined())
        .arg(node.lastQuarantineReason());
}
} // namespace

QString Ros2Participant::restartText() const
{
    QString text;
    if (restartCount().restarts() > 0)
        text = tr("ROS 2 discovery restarted %n time(s), %1 caused by peers (last: %2)", nullptr,
                  int(qMin<quint64>(restartCount().restarts(), INT_MAX)))
                   .arg(restartCount().peerRestarts())
                   .arg(restartCount().lastReason());
    if (restartCount().loopsBroken() > 0)
        text += u"; "_s + tr("a restart loop broken: the graph limited");
    const QString quarantine = quarantineText(node());
    if (!quarantine.isEmpty())
        text += (text.isEmpty() ? QString() : u"; "_s) + quarantine;
    return text;
}

void Ros2Participant::setGraphInterval(int ms)
{
    m_link.setGraphInterval(ms);
}

Status Ros2Participant::start(const Ros2Options& options)
{
    stop();
    if (options.domain < 0 || options.domain > Ros2Options::kMaxDomain)
        return LocatedError {tr("domain %1 is out of range: ROS 2 domains are 0 to %2")
                                 .arg(options.domain)
                                 .arg(Ros2Options::kMaxDomain)};
    if (DdsChildSupervisor::program().isEmpty())
        return LocatedError {tr("cannot see ROS 2: the helper program bridgescope-dds is not installed")};
    m_options = options;
    m_link.resetBadDiscoveryInfo();
    qCDebug(lcRos2).noquote() << "joining domain" << m_options.domain;
    return m_supervisor.start();
}

void Ros2Participant::onLaunched(bool limitedGraph)
{
    m_error.clear();
    Ros2Options options = m_options;
    options.limitedGraph = limitedGraph;
    m_link.replay(options);
}

void Ros2Participant::onLaunchFailed(const QString& why)
{
    m_error = why;
    if (restartCount().restarts() > 0)
        emit graphChanged(graph()); // a restart that failed: lastError() says why
}

void Ros2Participant::onChildFailed(const QString& why, const QString& loopBroken)
{
    m_link.childLost(why); // quarantines what it was making: endpointRefused()
    emit restarted(why);
    if (!loopBroken.isEmpty())
        emit restartLoopBroken(loopBroken);
    emit graphChanged(graph());
}

void Ros2Participant::stop()
{
    m_supervisor.stop();
    m_link.childStopped();
    m_error.clear();
}

void Ros2Participant::monitor(const QString& topic)
{
    m_link.monitor(topic);
}

void Ros2Participant::unmonitor(const QString& topic)
{
    m_link.unmonitor(topic);
}

bool Ros2Participant::isMonitored(const QString& topic) const
{
    return m_link.isMonitored(topic);
}

QHash<QString, Ros2MonitorStats> Ros2Participant::snapshot(qint64) const
{
    return m_link.stats();
}

QHash<QString, TopicFigures> Ros2Participant::figures(qint64 nowNs) const
{
    return topicFiguresOf(snapshot(nowNs));
}

namespace {
/// A tap of the participant: its own queue in the link, keyed by the tap itself.
class Ros2Tap : public Tap
{
public:
    Ros2Tap(Ros2Participant* participant, Ros2Link* link, QString topic, std::size_t maxMessages, qint64 maxBytes)
        : m_participant(participant)
        , m_link(link)
        , m_topic(std::move(topic))
    {
        m_link->watches().openQueue(m_topic, maxMessages, maxBytes, this);
    }
    ~Ros2Tap() override
    {
        if (m_participant) // the participant (and its link) may have gone first
            m_link->watches().closeQueue(m_topic, this);
    }
    std::vector<SourceArrival> take() override
    {
        if (!m_participant)
            return {};
        const Ros2Topic* t = m_participant->graph().topic(m_topic);
        const QString type = t ? t->type() : QString();
        std::vector<SourceArrival> out;
        for (Ros2Sample& s : m_link->watches().takeQueued(m_topic, this))
            out.push_back({SourceGraph::Ros2, m_topic, type, s.receivedNs, std::move(s.bytes)});
        return out;
    }
    quint64 dropped() const override { return m_participant ? m_link->watches().droppedQueued(m_topic, this) : 0; }

private:
    QPointer<Ros2Participant> m_participant;
    Ros2Link* m_link;
    QString m_topic;
};
} // namespace

std::unique_ptr<Tap> Ros2Participant::openTap(const QString& topic, std::size_t maxMessages, qint64 maxBytes)
{
    return std::make_unique<Ros2Tap>(this, &m_link, topic, maxMessages, maxBytes);
}

std::unique_ptr<HeadTap> Ros2Participant::openHeadTap(std::size_t maxHeads)
{
    return m_link.openHeadTap(maxHeads);
}

