// SPDX-License-Identifier: MIT
#include "rosreregistration.h"

#include "base/logging.h"

#include <ros/master.h>
#include <ros/network.h>
#include <ros/this_node.h>
#include <ros/xmlrpc_manager.h>
#include <xmlrpcpp/XmlRpcClient.h>

using namespace Qt::StringLiterals;

namespace {

/// A call to this node's own slave API (roscpp keeps its lists of topics private).
bool callSelf(const std::string& method, XmlRpc::XmlRpcValue& params, XmlRpc::XmlRpcValue& payload)
{
    std::string host;
    uint32_t port = 0;
    if (!ros::network::splitURI(ros::XMLRPCManager::instance()->getServerURI(), host, port))
        return false;
    XmlRpc::XmlRpcClient client(host.c_str(), int(port), "/");
    XmlRpc::XmlRpcValue response;
    const bool ok = client.execute(method.c_str(), params, response);
    client.close();
    if (!ok || response.getType() != XmlRpc::XmlRpcValue::TypeArray || response.size() != 3
        || response[0].getType() != XmlRpc::XmlRpcValue::TypeInt || int(response[0]) != 1)
        return false;
    payload = response[2];
    return true;
}

/// [[topic, type], ...] from getPublications / getSubscriptions.
std::vector<std::pair<std::string, std::string>> topicsOf(const XmlRpc::XmlRpcValue& list)
{
    std::vector<std::pair<std::string, std::string>> out;
    if (list.getType() != XmlRpc::XmlRpcValue::TypeArray)
        return out;
    for (int i = 0; i < list.size(); ++i) {
        const XmlRpc::XmlRpcValue& e = list[i];
        if (e.getType() == XmlRpc::XmlRpcValue::TypeArray && e.size() == 2
            && e[0].getType() == XmlRpc::XmlRpcValue::TypeString
            && e[1].getType() == XmlRpc::XmlRpcValue::TypeString)
            out.emplace_back(std::string(e[0]), std::string(e[1]));
    }
    return out;
}

enum class Answer { Yes, No, Unreachable };

/// Calls the master on a connection of its own; `No` when it answers with an error code.
/// (Not ros::master::execute: its pooled client stayed unusable after the master was killed while
/// a call was under way, so a restart was never noticed.)
Answer askMaster(const std::string& method, const XmlRpc::XmlRpcValue& params, XmlRpc::XmlRpcValue* payload)
{
    XmlRpc::XmlRpcClient client(ros::master::getHost().c_str(), int(ros::master::getPort()), "/");
    XmlRpc::XmlRpcValue response;
    const bool ok = client.execute(method.c_str(), params, response);
    client.close();
    if (!ok || response.getType() != XmlRpc::XmlRpcValue::TypeArray || response.size() != 3
        || response[0].getType() != XmlRpc::XmlRpcValue::TypeInt)
        return Answer::Unreachable;
    if (int(response[0]) != 1)
        return Answer::No;
    if (payload)
        *payload = response[2];
    return Answer::Yes;
}

} // namespace

RosReregistration::Result RosReregistration::check(QString* detail)
{
    const std::string me = ros::this_node::getName();
    const std::string api = ros::XMLRPCManager::instance()->getServerURI();
    if (api.empty())
        return Result::Registered; // no node started yet
    XmlRpc::XmlRpcValue lookup;
    lookup[0] = me;
    lookup[1] = me;
    XmlRpc::XmlRpcValue known;
    switch (askMaster("lookupNode", lookup, &known)) {
    case Answer::Unreachable:
        return Result::MasterUnreachable;
    case Answer::Yes:
        // Another process may have taken our name on a new master: then it is not us it knows.
        if (known.getType() == XmlRpc::XmlRpcValue::TypeString && std::string(known) == api)
            return Result::Registered;
        break;
    case Answer::No:
        break;
    }

    XmlRpc::XmlRpcValue self;
    self[0] = me;
    XmlRpc::XmlRpcValue pubList;
    XmlRpc::XmlRpcValue subList;
    if (!callSelf("getPublications", self, pubList) || !callSelf("getSubscriptions", self, subList)) {
        if (detail)
            *detail = tr("cannot list this node's topics");
        return Result::Failed;
    }
    const auto publications = topicsOf(pubList);
    const auto subscriptions = topicsOf(subList);
    if (publications.empty() && subscriptions.empty())
        return Result::Registered;
    qCDebug(lcRos) << "the master does not know this node (restarted?); registering" << publications.size()
                   << "publications and" << subscriptions.size() << "subscriptions again";

    QStringList refused;
    // registerPublisher and registerSubscriber take the same arguments.
    const auto registration = [&](const std::string& topic, const std::string& type) {
        XmlRpc::XmlRpcValue args;
        args[0] = me;
        args[1] = topic;
        args[2] = type;
        args[3] = api;
        return args;
    };
    for (const auto& [topic, type] : publications) {
        const Answer a = askMaster("registerPublisher", registration(topic, type), nullptr);
        if (a == Answer::Unreachable)
            return Result::MasterUnreachable;
        if (a == Answer::No)
            refused << QString::fromStdString(topic);
    }
    for (const auto& [topic, type] : subscriptions) {
        XmlRpc::XmlRpcValue publishers;
        const Answer a = askMaster("registerSubscriber", registration(topic, type), &publishers);
        if (a == Answer::Unreachable)
            return Result::MasterUnreachable;
        if (a == Answer::No) {
            refused << QString::fromStdString(topic);
            continue;
        }
        // What roscpp does with the answer when it subscribes: connect to those publishers.
        XmlRpc::XmlRpcValue update;
        update[0] = std::string("/master");
        update[1] = topic;
        update[2]
            = publishers.getType() == XmlRpc::XmlRpcValue::TypeArray ? publishers : XmlRpc::XmlRpcValue();
        if (update[2].getType() != XmlRpc::XmlRpcValue::TypeArray)
            update[2].setSize(0);
        XmlRpc::XmlRpcValue ignored;
        callSelf("publisherUpdate", update, ignored);
    }
    if (!refused.isEmpty()) {
        if (detail)
            *detail = tr("the master refused %1").arg(refused.join(u", "_s));
        return Result::Failed;
    }
    if (detail)
        *detail
            = tr("%n topic(s) registered again", nullptr, int(publications.size() + subscriptions.size()));
    return Result::Reregistered;
}

bool RosReregistration::masterAnswers()
{
    XmlRpc::XmlRpcValue args;
    args[0] = ros::this_node::getName();
    return askMaster("getPid", args, nullptr) != Answer::Unreachable;
}
