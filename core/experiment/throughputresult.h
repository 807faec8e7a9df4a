// SPDX-License-Identifier: MIT
#pragma once

#include <QJsonObject>
#include <QList>
#include <QString>

/// One rate of an experiment's throughput step: what arrived in its window.
struct ThroughputPoint
{
    double rateHz = 0;
    qint64 samples = 0; ///< complete samples in the window
    qint64 expected = 0; ///< rate x window
    qint64 dropped = 0;
    double p50Ms = 0; ///< of the total
    double p99Ms = 0;
    bool sustainable = false;
};

/// The throughput step of one payload size: rates up to the first one not sustained. What the
/// runner makes, the folder keeps (DIR/throughput.json) and the report shows; written and read
/// here, beside each other.
struct ThroughputResult
{
    /// At most this many rates a size are read back from a file.
    static constexpr int kMaxPoints = 1000;

    int payloadBytes = 0;
    QString level; ///< as the plan writes it, or the bytes
    QList<ThroughputPoint> points;
    bool complete = false;
    /// The highest rate sustained (0: none) and the payload bytes per second it carries.
    double maxSustainableHz() const;
    double megabytesPerSecond() const { return maxSustainableHz() * payloadBytes / 1e6; }
    QJsonObject toJson() const; ///< as DIR/throughput.json and the report's JSON have it
    /// What toJson() wrote (a hostile file's level cut at 256 characters, its rates at kMaxPoints).
    static ThroughputResult fromJson(const QJsonObject& o);
};
