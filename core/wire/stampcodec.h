// SPDX-License-Identifier: MIT
#pragma once

#include "base/result.h"
#include "wire/stampevent.h"

#include <optional>
#include <QByteArray>
#include <QCoreApplication>
#include <QString>

/// The timestamp formats Bridgescope reads, decoded without ROS or MQTT libraries.
///
/// - `benchmarking_suite/TimeStamped {Header header; time time}`, ROS 1 serialized: the sample is
///   `header.stamp`, the stamp is `time`.
/// - JSON `{"sample": "<id>", "time": <seconds | "sec.nsec">}` from non-ROS devices. A sample id
///   that reads as a time ("sec.nsec" or seconds) is that time, so it joins with ROS stamps of
///   the same sample; any other id is hashed (FNV-1a, 64 bit).
class StampCodec
{
    Q_DECLARE_TR_FUNCTIONS(StampCodec)
public:
    static constexpr const char* typeName() { return "benchmarking_suite/TimeStamped"; }
    static constexpr const char* md5() { return "6c3188ca087b31af579ede0943a09e20"; }
    /// Stamps are ROS times: 0 up to (not including) 2^32 s after the epoch, in ns. Any two differ
    /// by less than 2^62 ns, so their differences (and differences of those) never overflow.
    static constexpr qint64 kMaxTimeNs = (qint64(1) << 32) * 1'000'000'000LL;
    static constexpr bool inRange(qint64 ns) { return ns >= 0 && ns < kMaxTimeNs; }
    /// Why a time is not usable as a stamp, for messages ("outside 0 … 4294967296 s").
    static QString rangeText();
    /// The full definition as roscpp and mqtt_client carry it (with the Header dependency).
    static QString definition();

    struct Decoded
    {
        qint64 sampleNs = 0;
        qint64 timeNs = 0;
        quint32 seq = 0;
        QString frameId;
    };
    static Result<Decoded> decodeTimeStamped(const QByteArray& bytes);
    /// The std_msgs/Header a serialized message starts with (seq, stamp as `sampleNs`, frame_id);
    /// `consumed` gets its length.
    static std::optional<Decoded> decodeHeader(const QByteArray& bytes, qsizetype* consumed = nullptr);
    /// A sample id for what has no time: FNV-1a (64 bit) of the bytes, never negative.
    static qint64 hashId(const QByteArray& bytes);
    static QByteArray encodeTimeStamped(const Decoded& stamp);

    /// The ROS 2 form, `benchmarking_suite/msg/TimeStamped {std_msgs/msg/Header header;
    /// builtin_interfaces/msg/Time time}` (a ROS 2 Header has no seq: `seq` stays 0), as DDS
    /// carries it: CDR (XCDR1) after a 4-byte encapsulation header, little- or big-endian as the
    /// header says, aligned from the end of the header; the frame_id's length counts its NUL. Up
    /// to three bytes of padding may follow. The work is bounded by the bytes (no length is
    /// trusted before it is checked against what is left).
    static constexpr const char* ros2TypeName() { return "benchmarking_suite/msg/TimeStamped"; }
    static Result<Decoded> decodeTimeStampedCdr(const QByteArray& bytes);
    /// Little-endian, as rmw writes it on every host we build for.
    static QByteArray encodeTimeStampedCdr(const Decoded& stamp);

    /// JSON stamps are small; larger payloads are an error, not parsed (the work bound per message).
    static constexpr qsizetype kMaxJsonBytes = 4096;
    static Result<Decoded> decodeJson(const QByteArray& payload);
    static QByteArray encodeJson(qint64 sampleNs, qint64 timeNs);

    /// "sec.nsec" or decimal seconds as ns since the epoch (exact for "sec.nsec" text).
    static std::optional<qint64> parseTime(QStringView text);
    /// ns since the epoch as "sec.nsec", nine digits of nanoseconds (the suite's CSV cells).
    static QString timeText(qint64 ns);
    /// A std_msgs/Float64 payload (8 bytes, little-endian) in seconds, as ns; a latency, so
    /// negative values are kept, but none as large as kMaxTimeNs.
    static std::optional<qint64> decodeFloat64Seconds(const QByteArray& bytes);
    /// The same for a ROS 2 std_msgs/msg/Float64 sample (CDR: encapsulation header, 8 bytes).
    static std::optional<qint64> decodeFloat64SecondsCdr(const QByteArray& bytes);
};
