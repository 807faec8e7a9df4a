// SPDX-License-Identifier: MIT
#include "discovercommand.h"

#include "app/cli/clioutput.h"
#include "app/cli/rosoptions.h"
#include "app/cli/sourcecheck.h"
#include "mqtt/mqttconnection.h"
#include "models/mqtttopictree.h"
#include "ros/rosgraphpoller.h"
#include "ros2/ros2participant.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QDateTime>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTimer>

using namespace Qt::StringLiterals;
using CliOutput::err;
using CliOutput::ExitFailed;
using CliOutput::ExitOk;
using CliOutput::ExitUsage;
using CliOutput::out;

namespace {
class Discover
{
    Q_DECLARE_TR_FUNCTIONS(DiscoverCommand)
public:
    static QJsonObject rosJson(const RosGraphPoller& poller)
    {
        QJsonObject ros;
        ros.insert(u"master"_s, poller.masterUri());
        ros.insert(u"reachable"_s, poller.isReachable());
        if (!poller.isReachable())
            ros.insert(u"error"_s, poller.lastError());
        QJsonArray topics;
        for (const TopicInfo& t : poller.graph().topics) {
            QJsonObject o;
            o.insert(u"name"_s, t.name);
            o.insert(u"type"_s, t.type);
            o.insert(u"publishers"_s, QJsonArray::fromStringList(t.publishers));
            o.insert(u"subscribers"_s, QJsonArray::fromStringList(t.subscribers));
            topics.append(o);
        }
        ros.insert(u"topics"_s, topics);
        ros.insert(u"nodes"_s, QJsonArray::fromStringList(poller.graph().nodes));
        return ros;
    }

    static QJsonArray endpointsJson(const QList<Ros2Endpoint>& endpoints)
    {
        QJsonArray list;
        for (const Ros2Endpoint& e : endpoints) {
            QJsonObject o;
            o.insert(u"node"_s, e.node);
            o.insert(u"gid"_s, QString::fromLatin1(e.gid.toHex()));
            o.insert(u"reliability"_s, e.qos.reliabilityName());
            o.insert(u"durability"_s, e.qos.durabilityName());
            list.append(o);
        }
        return list;
    }

    static QJsonObject ros2Json(const Ros2Participant& participant, const QString& error)
    {
        QJsonObject ros2;
        const Ros2Options options = participant.options();
        ros2.insert(u"domain"_s, options.domain);
        ros2.insert(u"localhost_only"_s, options.localhostOnly);
        if (!error.isEmpty())
            ros2.insert(u"error"_s, error);
        const Ros2Graph& g = participant.graph();
        ros2.insert(u"participants"_s, g.participants);
        ros2.insert(u"services"_s, g.services);
        QJsonArray topics;
        for (const Ros2Topic& t : g.topics) {
            QJsonObject o;
            o.insert(u"name"_s, t.name);
            o.insert(u"type"_s, t.type());
            if (t.types.size() > 1)
                o.insert(u"types"_s, QJsonArray::fromStringList(t.types));
            o.insert(u"publishers"_s, endpointsJson(t.publishers));
            o.insert(u"subscribers"_s, endpointsJson(t.subscribers));
            topics.append(o);
        }
        ros2.insert(u"topics"_s, topics);
        QJsonArray nodes;
        for (const Ros2Node& n : g.nodes) {
            QJsonObject o;
            o.insert(u"name"_s, n.name);
            o.insert(u"publishes"_s, QJsonArray::fromStringList(n.publishes));
            o.insert(u"subscribes"_s, QJsonArray::fromStringList(n.subscribes));
            nodes.append(o);
        }
        ros2.insert(u"nodes"_s, nodes);
        if (const quint64 bad = participant.badDiscoveryInfo())
            ros2.insert(u"unreadable_discovery_info"_s, qint64(bad));
        if (g.omitted)
            ros2.insert(u"omitted_endpoints"_s, qint64(g.omitted));
        if (const quint64 restarts = participant.restartCount().restarts()) {
            ros2.insert(u"discovery_restarts"_s, qint64(restarts));
            ros2.insert(u"last_restart_reason"_s, participant.restartCount().lastReason());
            ros2.insert(u"discovery_restarts_by_peers"_s, qint64(participant.restartCount().peerRestarts()));
        }
        if (const int loops = participant.restartCount().loopsBroken())
            ros2.insert(u"restart_loops_broken"_s, loops);
        if (const int quarantined = participant.node().quarantined()) {
            ros2.insert(u"quarantined_requests"_s, quarantined);
            ros2.insert(u"last_quarantine_reason"_s, participant.node().lastQuarantineReason());
        }
        return ros2;
    }

    static void printRos2Text(const Ros2Participant& participant, const QString& error)
    {
        const Ros2Graph& g = participant.graph();
        if (!error.isEmpty()) {
            out(tr("ROS 2 domain %1: %2").arg(participant.options().domain).arg(error));
            return;
        }
        out(tr("ROS 2 domain %1: participants %2, topics %3, nodes %4")
                .arg(participant.options().domain)
                .arg(g.participants)
                .arg(g.topics.size())
                .arg(g.nodes.size()));
        for (const Ros2Topic& t : g.topics)
            out(u"  %1  %2  pubs %3  subs %4"_s.arg(t.name, t.type())
                    .arg(t.publishers.size())
                    .arg(t.subscribers.size()));
        if (g.omitted)
            out(u"  "_s + participant.graph().omittedText());
        if (const QString restarts = participant.restartText(); !restarts.isEmpty())
            out(u"  "_s + restarts);
    }

    static QJsonObject mqttJson(const MqttConnection& connection, const MqttTopicTree& tree,
                                bool everConnected)
    {
        QJsonObject mqtt;
        mqtt.insert(u"broker"_s, connection.profile().url);
        mqtt.insert(u"connected"_s, everConnected);
        if (!everConnected)
            mqtt.insert(u"error"_s, connection.stateDetail());
        QJsonArray topics;
        for (const MqttTopicTree::TopicInfo& t : tree.topicData().topics()) {
            QJsonObject o;
            o.insert(u"name"_s, t.topic);
            o.insert(u"messages"_s, qint64(t.messages));
            o.insert(u"bytes"_s, qint64(t.bytes));
            o.insert(u"retained"_s, t.retainedMessages > 0);
            if (t.rosType) {
                o.insert(u"ros_type"_s, t.rosType->name);
                o.insert(u"stamped"_s, t.rosType->stamped);
            }
            topics.append(o);
        }
        mqtt.insert(u"topics"_s, topics);
        // Nothing silent: past the tree's budgets the list is not all there was (issue 41).
        mqtt.insert(u"complete"_s, tree.topicData().store().untrackedMessages() == 0);
        if (const quint64 untracked = tree.topicData().store().untrackedMessages()) {
            mqtt.insert(u"untracked_messages"_s, qint64(untracked));
            mqtt.insert(u"topic_budget"_s, tree.topicData().store().topicBudget());
            mqtt.insert(u"names_budget_bytes"_s, tree.topicData().store().structureBudget());
        }
        return mqtt;
    }

    static void printText(const RosGraphPoller* poller, const MqttConnection& connection,
                          const MqttTopicTree& tree, bool connected)
    {
        if (poller) {
            out(tr("ROS master %1: %2")
                    .arg(poller->masterUri(),
                         poller->isReachable() ? tr("reachable")
                                               : tr("unreachable (%1)").arg(poller->lastError())));
            for (const TopicInfo& t : poller->graph().topics)
                out(u"  %1  %2  pubs %3  subs %4"_s.arg(t.name, t.type)
                        .arg(t.publishers.size())
                        .arg(t.subscribers.size()));
        }
        out(tr("MQTT broker %1: %2")
                .arg(connection.profile().url,
                     connected ? tr("connected") : tr("not connected (%1)").arg(connection.stateDetail())));
        const QList<MqttTopicTree::TopicInfo> topics = tree.topicData().topics();
        for (const MqttTopicTree::TopicInfo& t : topics) {
            out(u"  %1  %2 msg  %3 B%4%5"_s.arg(t.topic)
                    .arg(t.messages)
                    .arg(t.bytes)
                    .arg(t.retainedMessages ? tr("  retained") : QString())
                    .arg(t.rosType ? u"  "_s + t.rosType->name : QString()));
        }
        if (const QString line = untrackedLine(tree, topics.size()); !line.isEmpty())
            out(u"  "_s + line);
    }

    /// What the topic tree did not keep, empty when it kept every topic.
    static QString untrackedLine(const MqttTopicTree& tree, qsizetype listed)
    {
        const quint64 untracked = tree.topicData().store().untrackedMessages();
        if (untracked == 0)
            return {};
        return tr("not complete: %1 messages on topics not kept (budget %2 topics, %3 MiB of names); %4 "
                  "topics listed")
            .arg(untracked)
            .arg(tree.topicData().store().topicBudget())
            .arg(tree.topicData().store().structureBudget() / (1024 * 1024))
            .arg(listed);
    }
};

/// What the command line asks for.
struct DiscoverRequest
{
    MqttProfile profile;
    QString masterUri;
    double seconds = 2;
    bool json = false;
    bool ros1 = true;
    bool ros2 = false;
    Ros2Options ros2Options;
};

/// Parses and checks the command line. -1 to go on with `request`, otherwise the exit status.
int parseDiscover(const QStringList& arguments, DiscoverRequest* request)
{
    QCommandLineParser parser;
    const QCommandLineOption broker(u"broker"_s, Discover::tr("Broker URL (default tcp://localhost:1883)."),
                                    u"URL"_s, u"tcp://localhost:1883"_s);
    const QCommandLineOption master(u"ros-master"_s,
                                    Discover::tr("ROS master URI (default $ROS_MASTER_URI)."), u"URI"_s,
                                    RosMasterApi::defaultMasterUri());
    const QCommandLineOption seconds(u"seconds"_s, Discover::tr("How long to listen (default 2)."), u"N"_s,
                                     u"2"_s);
    const QCommandLineOption json(u"json"_s, Discover::tr("Print one JSON document."));
    const QCommandLineOption filter(
        u"filter"_s, Discover::tr("MQTT topic filter to subscribe (default #; repeatable)."), u"FILTER"_s);
    parser.addOptions({broker, master, seconds, json, filter});
    RosOptions ros;
    ros.addTo(parser);
    const int parsed = CliOutput::parseCommand(
        parser, arguments, u"bridgescope discover"_s,
        Discover::tr("Lists what is on the ROS master and the MQTT broker after listening for a while. Exit "
                     "status: 0 when at least one of them answered, 1 when neither did, 2 on bad options."));
    if (parsed >= 0)
        return parsed;
    if (!CliOutput::readSeconds(parser.value(seconds), &request->seconds) || request->seconds <= 0) {
        err(Discover::tr("--seconds takes a positive number up to a year"));
        return ExitUsage;
    }
    MqttProfile& profile = request->profile;
    profile = MqttProfile::fromUrl(parser.value(broker));
    if (parser.isSet(filter))
        profile.filters = parser.values(filter);
    if (const Status valid = profile.validate(); !valid) {
        err(valid.error().toString());
        return ExitUsage;
    }
    request->masterUri = parser.value(master);
    request->json = parser.isSet(json);
    if (const Status read = ros.read(parser); !read) {
        err(read.error().toString());
        return ExitUsage;
    }
    request->ros1 = ros.ros1;
    request->ros2 = ros.ros2;
    request->ros2Options = ros.ros2Options;
    for (const QString& line : ros.notes())
        err(line);
    return -1;
}

/// What was heard: the ROS graph, the MQTT connection and its topics.
struct Heard
{
    RosGraphPoller poller;
    MqttConnection connection;
    MqttTopicTree tree;
    bool connected = false;
    Ros2Participant ros2;
    QString ros2Error;
};

/// How long discover waits for the DDS process to join the domain before it starts counting anyway.
constexpr int kJoinWaitMs = 10'000;

/// Listens to the master and the broker for the time asked for.
void listen(const DiscoverRequest& request, Heard* heard)
{
    if (request.ros1) {
        heard->poller.setMasterUri(request.masterUri);
        heard->poller.start(500);
    }
    if (request.ros2) {
        if (const Status joined = heard->ros2.start(request.ros2Options); !joined)
            heard->ros2Error = joined.error().message.isEmpty() ? Discover::tr("no participant")
                                                                : joined.error().toString();
    }
    // said as it happens, not only at the end: a restart of the DDS process is news
    sayRos2Restarts(&heard->ros2);
    QObject::connect(&heard->connection, &MqttConnection::stateChanged, [heard](MqttConnection::State s) {
        heard->connected = heard->connected || s == MqttConnection::State::Connected;
    });
    heard->connection.open(request.profile);
    QTimer drain;
    QObject::connect(&drain, &QTimer::timeout,
                     [heard] { heard->tree.apply(heard->connection.takeMessages()); });
    drain.start(33);
    // The time asked for is time listened: with ROS 2 it counts from when the DDS process is on the
    // domain (or said it cannot be), which a loaded machine can delay by seconds; at most
    // kJoinWaitMs is waited for that.
    QTimer listened;
    listened.setSingleShot(true);
    listened.setInterval(int(request.seconds * 1000));
    QObject::connect(&listened, &QTimer::timeout, [] { QCoreApplication::exit(ExitOk); });
    if (request.ros2 && heard->ros2Error.isEmpty()) {
        QObject::connect(&heard->ros2, &Ros2Participant::joined, &listened, [&listened] {
            if (!listened.isActive())
                listened.start();
        });
        QTimer::singleShot(kJoinWaitMs, &listened, [&listened] {
            if (!listened.isActive())
                listened.start();
        });
    } else {
        listened.start();
    }
    QCoreApplication::exec();
    heard->tree.apply(heard->connection.takeMessages());
    if (heard->ros2Error.isEmpty())
        heard->ros2Error = heard->ros2.lastError(); // Cyclone DDS could not make the participant
}

/// Prints what was heard as text or JSON; fails when neither side answered.
int printDiscover(const DiscoverRequest& request, const Heard& heard)
{
    const RosGraphPoller& poller = heard.poller;
    const MqttConnection& connection = heard.connection;
    const MqttTopicTree& tree = heard.tree;
    const bool connected = heard.connected;
    if (request.json) {
        QJsonObject doc;
        if (request.ros1)
            doc.insert(u"ros"_s, Discover::rosJson(poller));
        if (request.ros2)
            doc.insert(u"ros2"_s, Discover::ros2Json(heard.ros2, heard.ros2Error));
        doc.insert(u"mqtt"_s, Discover::mqttJson(connection, tree, connected));
        // As bytes: a text copy of a document of 150,000 topics would be three times its size.
        CliOutput::writeStdout(QJsonDocument(doc).toJson(QJsonDocument::Indented));
    } else {
        Discover::printText(request.ros1 ? &poller : nullptr, connection, tree, connected);
        if (request.ros2)
            Discover::printRos2Text(heard.ros2, heard.ros2Error);
    }
    const bool ros1Answered = request.ros1 && poller.isReachable();
    const bool ros2Answered
        = request.ros2 && heard.ros2Error.isEmpty() && heard.ros2.graph().participants > 0;
    if (!ros1Answered && !ros2Answered && !connected) {
        if (request.ros2 && !request.ros1) {
            err(Discover::tr(
                    "No ROS 2 participant answered on domain %1 and the MQTT broker (%2) could not be "
                    "reached.")
                    .arg(request.ros2Options.domain)
                    .arg(request.profile.url));
            return ExitFailed;
        }
        err(Discover::tr("Neither the ROS master (%1) nor the MQTT broker (%2) could be reached.")
                .arg(poller.masterUri(), request.profile.url));
        return ExitFailed;
    }
    return ExitOk;
}
} // namespace

int runDiscoverCommand(const QStringList& arguments)
{
    DiscoverRequest request;
    if (const int status = parseDiscover(arguments, &request); status >= 0)
        return status;
    Heard heard;
    listen(request, &heard);
    return printDiscover(request, heard);
}
