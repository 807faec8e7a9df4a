// SPDX-License-Identifier: MIT
#pragma once

#include <QMetaType>
#include <QString>

/// One timestamp of one sample, as a pipeline component published it.
///
/// `sampleNs` identifies the sample (the sample header's stamp, ns since the epoch); `timeNs` is
/// the wall-clock moment the component stamped it; `receivedNs` is when Bridgescope got it (the
/// joiner's timeouts run on this clock, never on the stamps of other hosts).
struct StampEvent
{
    QString topic;
    qint64 sampleNs = 0;
    qint64 timeNs = 0;
    qint64 receivedNs = 0;
};

/// One latency measured by somebody else (mqtt_client's `~/latencies/<topic>`, a stamped MQTT
/// payload): a single-stage series of its own.
struct LatencyValue
{
    QString series;
    qint64 valueNs = 0;
    qint64 receivedNs = 0;
};

Q_DECLARE_METATYPE(StampEvent)
Q_DECLARE_METATYPE(LatencyValue)
