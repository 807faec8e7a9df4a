// SPDX-License-Identifier: MIT
#pragma once

#include "base/result.h"
#include "ros2/ros2graph.h"
#include "ros2/ros2protocol.h"
#include "ros2/ros2types.h"

#include <functional>
#include <map>
#include <QByteArray>
#include <QString>
#include <set>

/// What `bridgescope-dds` asks of its DDS participant (Ros2Engine, core/dds, implements it): the
/// requests of Ros2Protocol, one call each. An interface so that the dispatcher below has no DDS
/// in it (it is fuzzed without a domain: tests/fuzz/fuzz_ddschild.cpp).
class Ros2ChildEngine
{
public:
    virtual ~Ros2ChildEngine() = default;
    virtual Status start(const Ros2Options& options) = 0;
    virtual void setGraphInterval(int ms) = 0;
    virtual void monitor(const QString& topic, bool waitForType) = 0;
    virtual void unmonitor(const QString& topic) = 0;
    virtual void watchMessages(const QString& topic, std::size_t maxMessages, qint64 maxBytes) = 0;
    virtual void unwatchMessages(const QString& topic) = 0;
    virtual void keepArrivals(std::size_t maxArrivals) = 0;
    virtual void setNode(const QString& nameSpace, const QString& name) = 0;
    /// The error's message may be empty: the server then says Cyclone refused it.
    virtual Status advertise(const QString& topic, const QString& type, const Ros2Qos& qos) = 0;
    virtual void unadvertise(const QString& topic) = 0;
    virtual bool publish(const QString& topic, const QByteArray& cdr) = 0;
    virtual Status subscribeSamples(const QString& topic, const QString& type, const Ros2Qos& qos) = 0;
    virtual void unsubscribeSamples(const QString& topic) = 0;
};

/// The request side of `bridgescope-dds`: cuts the parent's bytes into frames and hands each
/// request to the engine, a bounded number a turn (so that its event loop, and the heartbeat on
/// it, runs between turns however many requests wait: issue 41). Names and types of endpoints are
/// checked (Ros2Names::isValidTopic, isValidType) before the engine sees them; every Advertise and
/// Subscribe is answered with an EndpointDone frame (empty why: made), which the parent waits for
/// before it counts the request as done (its quarantine, Ros2Participant).
class DdsChildServer
{
public:
    using Send = std::function<void(Ros2Protocol::Kind, const QByteArray&)>;
    DdsChildServer(Ros2ChildEngine& engine, Send send)
        : m_engine(engine)
        , m_send(std::move(send))
    { }

    /// Requests handled a turn; the rest wait for the next turn.
    static constexpr int kFramesPerTurn = 64;

    /// Bytes from the parent.
    void append(const QByteArray& bytes) { m_reader.append(bytes); }
    enum class Turn { Idle, More, Failed };
    /// Handles up to `maxFrames` whole requests: Idle when none waits any more, More when some
    /// do, Failed when the stream or a request did not read (error() says which; the parent's bug,
    /// not hostile input: the child ends).
    Turn handlePending(int maxFrames = kFramesPerTurn);
    QString error() const { return m_error; }
    /// Bytes held that are not a whole frame yet, or frames not handled yet.
    qsizetype pending() const { return m_reader.pending(); }

    /// Topics watched (Watch, not Unwatch since), for the drain.
    const std::set<QString>& watched() const { return m_watched; }
    /// The monitored topics' message counts last sent with their last message (Unmonitor forgets).
    std::map<QString, quint64>& sentMessages() { return m_sentMessages; }

    /// One request; false when it does not read.
    bool handle(const Ros2Protocol::Frame& f);

private:
    bool handleEndpoint(const Ros2Protocol::Frame& f);

    Ros2ChildEngine& m_engine;
    Send m_send;
    Ros2Protocol::FrameReader m_reader;
    QString m_error;
    std::set<QString> m_watched;
    std::map<QString, quint64> m_sentMessages;
};
