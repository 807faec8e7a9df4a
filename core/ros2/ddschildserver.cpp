// SPDX-License-Identifier: MIT
#include "ros2/ddschildserver.h"

#include "ros2/ros2names.h"

#include <QCoreApplication>

using Ros2Protocol::Kind;

DdsChildServer::Turn DdsChildServer::handlePending(int maxFrames)
{
    for (int n = 0; n < maxFrames; ++n) {
        const auto f = m_reader.next();
        if (!f) {
            if (m_reader.failed()) {
                m_error = m_reader.error();
                return Turn::Failed;
            }
            return Turn::Idle;
        }
        if (!handle(*f)) {
            m_error = QCoreApplication::translate("DdsChildServer", "a request of kind %1 does not read")
                          .arg(int(f->kind));
            return Turn::Failed;
        }
    }
    return m_reader.pending() >= 5 ? Turn::More : Turn::Idle;
}

bool DdsChildServer::handle(const Ros2Protocol::Frame& f)
{
    switch (f.kind) {
    case Kind::Start: {
        const auto r = Ros2Protocol::decodeStart(f.body);
        if (!r)
            return false;
        m_engine.setGraphInterval(r->graphIntervalMs);
        if (const Status started = m_engine.start(r->options))
            m_send(Kind::Started, {});
        else
            m_send(Kind::StartFailed, Ros2Protocol::encodeStrings({started.error().message}));
        return true;
    }
    case Kind::GraphInterval: {
        const auto ms = Ros2Protocol::decodeNumber(f.body);
        if (!ms || *ms < 1 || *ms > 3'600'000)
            return false;
        m_engine.setGraphInterval(int(*ms));
        return true;
    }
    case Kind::Monitor:
    case Kind::Unmonitor:
    case Kind::Unwatch: {
        const auto topic = Ros2Protocol::decodeStrings(f.body, 1);
        if (!topic)
            return false;
        const QString& t = topic->first();
        if (f.kind == Kind::Monitor) {
            m_engine.monitor(t, true);
        } else if (f.kind == Kind::Unmonitor) {
            m_engine.unmonitor(t);
            m_sentMessages.erase(t);
        } else {
            m_engine.unwatchMessages(t);
            m_watched.erase(t);
        }
        return true;
    }
    case Kind::Watch: {
        const auto w = Ros2Protocol::decodeWatch(f.body);
        if (!w)
            return false;
        m_engine.watchMessages(w->topic, std::size_t(w->maxMessages), w->maxBytes);
        m_watched.insert(w->topic);
        return true;
    }
    case Kind::KeepArrivals: {
        const auto n = Ros2Protocol::decodeNumber(f.body);
        if (!n || *n > 100'000'000)
            return false;
        m_engine.keepArrivals(std::size_t(*n));
        return true;
    }
    default:
        return handleEndpoint(f);
    }
}

/// Requests of our own endpoints (Ros2Participant's advertise(), publish(), subscribe()).
bool DdsChildServer::handleEndpoint(const Ros2Protocol::Frame& f)
{
    switch (f.kind) {
    case Kind::SetNode: {
        const auto node = Ros2Protocol::decodeStrings(f.body, 2);
        if (!node)
            return false;
        m_engine.setNode(node->at(0), node->at(1));
        return true;
    }
    case Kind::Advertise:
    case Kind::Subscribe: {
        const auto e = Ros2Protocol::decodeEndpoint(f.body);
        if (!e)
            return false;
        const bool advertise = f.kind == Kind::Advertise;
        QString why;
        // the parent checks these too; checked here again, so that nothing reaches DDS unchecked
        bool made = Ros2Names::isValidTopic(e->topic, &why) && Ros2Names::isValidType(e->type, &why);
        if (made) {
            const Status endpoint = advertise ? m_engine.advertise(e->topic, e->type, e->qos)
                                              : m_engine.subscribeSamples(e->topic, e->type, e->qos);
            made = endpoint.ok();
            why = endpoint.error().message;
        }
        if (!made && why.isEmpty())
            why = QCoreApplication::translate("DdsChildServer", "Cyclone DDS refused it");
        m_send(Kind::EndpointDone,
               Ros2Protocol::encodeEndpointDone({advertise, e->topic, e->type, made ? QString() : why}));
        return true;
    }
    case Kind::Unadvertise:
    case Kind::Unsubscribe: {
        const auto topic = Ros2Protocol::decodeStrings(f.body, 1);
        if (!topic)
            return false;
        if (f.kind == Kind::Unadvertise)
            m_engine.unadvertise(topic->first());
        else
            m_engine.unsubscribeSamples(topic->first());
        return true;
    }
    case Kind::Publish: {
        const auto p = Ros2Protocol::decodePublish(f.body);
        if (!p)
            return false;
        m_engine.publish(p->topic, p->cdr); // one Cyclone refuses is lost, as on a full network
        return true;
    }
    default:
        return false;
    }
}
