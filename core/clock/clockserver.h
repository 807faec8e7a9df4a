// SPDX-License-Identifier: MIT
#pragma once

#include "base/result.h"
#include "clock/clockbudget.h"
#include "clock/clockprobe.h"
#include "clock/clocksync.h"

#include <optional>
#include <QHostAddress>
#include <QObject>
#include <QString>

class QUdpSocket;

/// What a clock service answers as, and where.
struct ClockServerOptions
{
    QString name; ///< the host's name, as pipelines name it (ClockProbe::isValidName)
    QHostAddress udpAddress = QHostAddress::LocalHost;
    int udpPort = -1; ///< < 0: no UDP port; 0: a free one (udpPort() says which)
    /// Added to t2 and t3: simulates a far clock that is this far ahead (tests, the demo lab).
    double clockOffsetMs = 0;
};

/// What the clock service did with what it was sent. Every probe is counted once.
struct ClockServerCounters
{
    quint64 answered = 0;
    quint64 malformed = 0; ///< not a probe: wrong size, magic, version or fields
    quint64 refused
        = 0; ///< a well-formed probe it does not answer (an answer, another host's name, a bad reply topic)
    quint64 overBudget = 0; ///< dropped by the per-peer or the total rate budget, or too many peers
    quint64 sendFailed = 0; ///< the answer could not be sent
    quint64 total() const { return answered + malformed + refused + overBudget + sendFailed; }
};

/// The clock service: answers four-timestamp probes (ClockProbe) on a UDP port and, through
/// MqttClockServer (core/mqtt), on an MQTT topic, within a rate budget (ClockBudget), with the
/// host's sync state. t2 is taken as soon as a datagram is read, t3 just before the answer is sent.
class ClockServer : public QObject
{
    Q_OBJECT
public:
    /// Datagrams read per turn of the event loop before others get their turn.
    static constexpr int kMaxDatagramsPerTurn = 64;

    explicit ClockServer(ClockServerOptions options, QObject* parent = nullptr);
    ~ClockServer() override;

    /// Checks the name and binds the UDP port, if one is asked for; the error names the address.
    Status listen();
    quint16 udpPort() const;
    const ClockServerOptions& options() const { return m_options; }
    ClockServerCounters counters() const { return m_counters; }

    /// The sync state sent with every answer (ClockSyncReader keeps it fresh).
    void setSyncState(const ClockSyncState& state) { m_sync = state; }
    /// This host's clock as the answers show it: `wallNs` plus the simulated offset.
    qint64 serverClockNs(qint64 wallNs) const;

    /// A transport's probe: the probe when it is to be answered, or nothing (counted). `peer` is
    /// whom the budget charges (empty: the probe's reply topic). `replyPrefix`, when not empty, is
    /// the prefix the probe's reply topic must have, with more after it (MQTT); otherwise the
    /// probe must carry none.
    std::optional<ClockProbe> accept(const QByteArray& bytes, const QString& peer,
                                     const QString& replyPrefix);
    /// The answer to `probe` received at `arrivedWallNs`, with t3 taken now: call right before sending.
    QByteArray answerBytes(const ClockProbe& probe, qint64 arrivedWallNs) const;
    void countAnswered(bool sent);

signals:
    /// Once per turn of the event loop in which something was counted.
    void countersChanged();

private:
    void readDatagrams();
    void changed();

    ClockServerOptions m_options;
    qint64 m_offsetNs = 0;
    QUdpSocket* m_udp = nullptr;
    ClockBudget m_budget;
    ClockSyncState m_sync;
    ClockServerCounters m_counters;
    bool m_changePosted = false;
};
