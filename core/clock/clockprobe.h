// SPDX-License-Identifier: MIT
#pragma once

#include "base/result.h"
#include "clock/clocksync.h"

#include <QByteArray>
#include <QCoreApplication>
#include <QString>
#include <QtGlobal>

/// A four-timestamp clock probe or its answer, as it travels over UDP and MQTT: the same
/// kSize bytes both ways (docs/formats.md, "Clock probes").
///
/// The prober sends a probe with a nonce and t1 (its send time); the server answers with the same
/// nonce and t1, its receive time t2, its send time t3, its name and its sync state. Over MQTT a
/// probe carries the topic to answer on. decode() refuses anything but exactly kSize well-formed
/// bytes.
struct ClockProbe
{
    Q_DECLARE_TR_FUNCTIONS(ClockProbe)
public:
    enum class Kind : quint8 { Probe = 1, Answer = 2 };

    static constexpr qsizetype kSize = 288;
    static constexpr quint8 kVersion = 1;
    static constexpr int kMaxNameBytes = 64;
    static constexpr int kMaxReplyTopicBytes = 120;

    Kind kind = Kind::Probe;
    quint64 nonce = 0;
    qint64 t1 = 0; ///< prober's clock, when the probe was sent (ns since the epoch)
    qint64 t2 = 0; ///< server's clock, when the probe arrived (0 in a probe)
    qint64 t3 = 0; ///< server's clock, when the answer left (0 in a probe)
    QString name; ///< answer: the answering host; probe: the host asked (may be empty over UDP)
    QString replyTopic; ///< MQTT probes: where to answer; empty otherwise
    ClockSyncState sync; ///< answer: the server's own sync state

    /// The answer to this probe from `host`, stamped t2 and t3.
    ClockProbe answer(const QString& host, qint64 t2Ns, qint64 t3Ns, const ClockSyncState& state) const;

    QByteArray encode() const;
    /// The probe or answer in `bytes`, or why they are not one.
    static Result<ClockProbe> decode(const QByteArray& bytes);

    /// Whether `name` may name a host: 1 to kMaxNameBytes bytes of UTF-8, printable, no spaces and
    /// none of '/', '+', '#' (it becomes an MQTT topic level).
    static bool isValidName(const QString& name);

    bool operator==(const ClockProbe& o) const;
};
