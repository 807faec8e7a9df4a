// SPDX-License-Identifier: MIT
#include "rosreregistration.h"

#include "base/logging.h"
#include "ros/rosmasterapi.h"

#include <ros/master.h>
#include <ros/this_node.h>
#include <ros/xmlrpc_manager.h>
#include <vector>

using namespace Qt::StringLiterals;

namespace {

/// Every call below gets an answer within this, or counts as no answer: a master (or a node) that
/// accepts the connection and never answers costs this much, not the thread (roscpp's own
/// XmlRpcClient::execute has no deadline).
constexpr int kCallMs = RosReregistration::kDeadlineMs;

/// A call to this node's own slave API (roscpp keeps its lists of topics private).
bool callSelf(const QString& method, const QVariantList& params, QVariant* payload = nullptr)
{
    const RosMasterApi self(QString::fromStdString(ros::XMLRPCManager::instance()->getServerURI()),
                            QString::fromStdString(ros::this_node::getName()));
    const Result<QVariant> value = self.call(method, params, kCallMs);
    if (value && payload)
        *payload = *value;
    return value.ok();
}

/// [[topic, type], ...] from getPublications / getSubscriptions.
std::vector<std::pair<QString, QString>> topicsOf(const QVariant& list)
{
    std::vector<std::pair<QString, QString>> out;
    for (const QVariant& entry : list.toList()) {
        const QVariantList pair = entry.toList();
        if (pair.size() == 2 && pair[0].typeId() == QMetaType::QString
            && pair[1].typeId() == QMetaType::QString)
            out.emplace_back(pair[0].toString(), pair[1].toString());
    }
    return out;
}

enum class Answer { Yes, No, Unreachable };

/// Calls the master on a connection of its own, within kCallMs; `No` when it answers with an
/// error code. (Not ros::master::execute: its pooled client stayed unusable after the master was
/// killed while a call was under way, so a restart was never noticed; and it waits without end
/// for a master that does not answer.)
Answer askMaster(const QString& method, const QVariantList& params, QVariant* payload)
{
    const RosMasterApi master(QString::fromStdString(ros::master::getURI()),
                              QString::fromStdString(ros::this_node::getName()));
    const Result<QVariantList> answer = master.answer(method, params, kCallMs);
    if (!answer)
        return Answer::Unreachable;
    if ((*answer)[0].toInt() != 1)
        return Answer::No;
    if (payload)
        *payload = (*answer)[2];
    return Answer::Yes;
}

} // namespace

RosReregistration::Result RosReregistration::check(QString* detail)
{
    const QString me = QString::fromStdString(ros::this_node::getName());
    const QString api = QString::fromStdString(ros::XMLRPCManager::instance()->getServerURI());
    if (api.isEmpty())
        return Result::Registered; // no node started yet
    QVariant known;
    switch (askMaster(u"lookupNode"_s, {me, me}, &known)) {
    case Answer::Unreachable:
        return Result::MasterUnreachable;
    case Answer::Yes:
        // Another process may have taken our name on a new master: then it is not us it knows.
        if (known.typeId() == QMetaType::QString && known.toString() == api)
            return Result::Registered;
        break;
    case Answer::No:
        break;
    }

    QVariant pubList;
    QVariant subList;
    if (!callSelf(u"getPublications"_s, {me}, &pubList) || !callSelf(u"getSubscriptions"_s, {me}, &subList)) {
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
    for (const auto& [topic, type] : publications) {
        // registerPublisher and registerSubscriber take the same arguments.
        const Answer a = askMaster(u"registerPublisher"_s, {me, topic, type, api}, nullptr);
        if (a == Answer::Unreachable)
            return Result::MasterUnreachable;
        if (a == Answer::No)
            refused << topic;
    }
    for (const auto& [topic, type] : subscriptions) {
        QVariant publishers;
        const Answer a = askMaster(u"registerSubscriber"_s, {me, topic, type, api}, &publishers);
        if (a == Answer::Unreachable)
            return Result::MasterUnreachable;
        if (a == Answer::No) {
            refused << topic;
            continue;
        }
        // What roscpp does with the answer when it subscribes: connect to those publishers.
        QVariantList uris;
        for (const QVariant& uri : publishers.toList())
            if (uri.typeId() == QMetaType::QString)
                uris << uri;
        callSelf(u"publisherUpdate"_s, {u"/master"_s, topic, QVariant(uris)});
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
    return askMaster(u"getPid"_s, {QString::fromStdString(ros::this_node::getName())}, nullptr)
        != Answer::Unreachable;
}
