// SPDX-License-Identifier: MIT
#include "ros2/ros2participant.h"

#include "base/logging.h"

#include <QCoreApplication>
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
    connect(&m_link.endpoints(), &Ros2EndpointLink::endpointRefused, this, &Ros2Participant::endpointRefused);
    connect(&m_link.endpoints(), &Ros2EndpointLink::received, this, &Ros2Participant::received);
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

QString Ros2Participant::omittedText() const
{
    const quint64 omitted = graph().omitted;
    if (omitted == 0)
        return {};
    return tr("%n endpoint(s) not listed (over a bound)", nullptr, int(std::min<quint64>(omitted, INT_MAX)));
}

QString Ros2Participant::restartText() const
{
    QString text;
    if (restarts() > 0)
        text = tr("ROS 2 discovery restarted %n time(s), %1 caused by peers (last: %2)", nullptr,
                  int(qMin<quint64>(restarts(), INT_MAX)))
                   .arg(peerRestarts())
                   .arg(lastRestartReason());
    if (restartLoopsBroken() > 0)
        text += u"; "_s + tr("a restart loop broken: the graph limited");
    const QString quarantine = quarantineText();
    if (!quarantine.isEmpty())
        text += (text.isEmpty() ? QString() : u"; "_s) + quarantine;
    return text;
}

QString Ros2Participant::quarantineText() const
{
    if (quarantined() == 0)
        return {};
    return tr("%n ROS 2 request(s) quarantined (last: %1)", nullptr, quarantined())
        .arg(lastQuarantineReason());
}

void Ros2Participant::setGraphInterval(int ms)
{
    m_link.setGraphInterval(ms);
}

bool Ros2Participant::start(const Ros2Options& options, QString* error)
{
    stop();
    if (options.domain < 0 || options.domain > Ros2Options::kMaxDomain) {
        if (error)
            *error = tr("domain %1 is out of range: ROS 2 domains are 0 to %2")
                         .arg(options.domain)
                         .arg(Ros2Options::kMaxDomain);
        return false;
    }
    if (program().isEmpty()) {
        if (error)
            *error = tr("cannot see ROS 2: the helper program bridgescope-dds is not installed");
        return false;
    }
    m_options = options;
    m_link.resetBadDiscoveryInfo();
    qCDebug(lcRos2).noquote() << "joining domain" << m_options.domain;
    return m_supervisor.start(error);
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
    if (restarts() > 0)
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
        m_link->openQueue(m_topic, maxMessages, maxBytes, this);
    }
    ~Ros2Tap() override
    {
        if (m_participant) // the participant (and its link) may have gone first
            m_link->closeQueue(m_topic, this);
    }
    std::vector<SourceArrival> take() override
    {
        if (!m_participant)
            return {};
        const Ros2Topic* t = m_participant->graph().topic(m_topic);
        const QString type = t ? t->type() : QString();
        std::vector<SourceArrival> out;
        for (Ros2Sample& s : m_link->takeQueued(m_topic, this))
            out.push_back({SourceGraph::Ros2, m_topic, type, s.receivedNs, std::move(s.bytes)});
        return out;
    }
    quint64 dropped() const override { return m_participant ? m_link->droppedQueued(m_topic, this) : 0; }

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

void Ros2Participant::keepArrivals(std::size_t maxArrivals)
{
    m_link.keepArrivals(maxArrivals);
}

std::vector<SourceHead> Ros2Participant::takeArrivals()
{
    return m_link.takeArrivals();
}

quint64 Ros2Participant::droppedArrivals() const
{
    return m_link.droppedArrivals();
}

void Ros2Participant::setNode(const QString& nameSpace, const QString& name)
{
    m_link.endpoints().setNode(nameSpace, name);
}

bool Ros2Participant::advertise(const QString& topic, const QString& type, const Ros2Qos& qos)
{
    return m_link.endpoints().advertise(topic, type, qos);
}

void Ros2Participant::unadvertise(const QString& topic)
{
    m_link.endpoints().unadvertise(topic);
}

bool Ros2Participant::publish(const QString& topic, const QByteArray& cdr)
{
    return m_link.endpoints().publish(topic, cdr);
}

bool Ros2Participant::subscribe(const QString& topic, const QString& type, const Ros2Qos& qos)
{
    return m_link.endpoints().subscribe(topic, type, qos);
}

void Ros2Participant::unsubscribe(const QString& topic)
{
    m_link.endpoints().unsubscribe(topic);
}

quint64 Ros2Participant::droppedReceived() const
{
    return m_link.endpoints().droppedReceived();
}
