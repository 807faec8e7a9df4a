// SPDX-License-Identifier: MIT
#pragma once

#include <QCoreApplication>
#include <QMetaType>
#include <QString>
#include <QtGlobal>

/// How a host's own clock is disciplined, as its time daemon reports it (chrony or linuxptp).
/// A far host sends it with its probe answers; "not reported" when it runs neither or they fail.
struct ClockSyncState
{
    enum class Source : quint8 { None = 0, Chrony = 1, Ptp = 2 };
    static constexpr int kMaxReferenceBytes = 20;

    Source source = Source::None;
    /// chrony: leap status (0 normal, 1 insert second, 2 delete second, 3 not synchronised);
    /// linuxptp: 1 when a grandmaster is present, else 0.
    quint8 status = 0;
    /// chrony: the system clock's offset from NTP time as `tracking` reports it (positive: slow);
    /// linuxptp: master_offset.
    qint64 offsetNs = 0;
    qint64 rootDelayNs = 0; ///< chrony only
    qint64 rootDispersionNs = 0; ///< chrony only
    qint64 frequencyPpb = 0; ///< chrony: the clock's frequency error, parts per billion
    qint64 skewPpb = 0; ///< chrony: the error bound of that frequency
    QString reference; ///< chrony: the reference's name or address; linuxptp: gmIdentity

    bool isReported() const { return source != Source::None; }
    /// Whether the daemon says the clock is synchronised.
    bool isSynchronised() const;
    /// One line for people: "chrony, synchronised to 10.0.0.1: offset +0.012 ms, root delay ...".
    QString text() const;
    bool operator==(const ClockSyncState& o) const;
};

Q_DECLARE_METATYPE(ClockSyncState)

/// Reads the host's sync state: parses `chronyc -c tracking` and linuxptp's
/// `pmc -u -b 0 'GET TIME_STATUS_NP'`, and runs them. Every parser refuses what does not look
/// exactly like the program's output, and output larger than kMaxOutputBytes.
class ClockSync
{
    Q_DECLARE_TR_FUNCTIONS(ClockSync)
public:
    static constexpr qsizetype kMaxOutputBytes = 8 * 1024;
    static constexpr int kTimeoutMs = 2000;

    /// One line of `chronyc -c tracking` (14 comma-separated fields); Source::None when it is not one.
    static ClockSyncState parseChrony(const QByteArray& output);
    /// The answer of `pmc -u -b 0 'GET TIME_STATUS_NP'`; Source::None when it holds none.
    static ClockSyncState parsePmc(const QByteArray& output);

    /// Runs chronyc, then pmc, each only when it is on PATH and for at most `timeoutMs`; the first
    /// that reports wins. Blocks: never call it on the GUI thread (ClockSyncReader runs it on a thread).
    static ClockSyncState read(int timeoutMs = kTimeoutMs);
    /// Runs `program` with `arguments` (only when on PATH), at most `timeoutMs`; its standard output,
    /// or empty when it is absent, failed, took too long or wrote more than kMaxOutputBytes.
    static QByteArray run(const QString& program, const QStringList& arguments, int timeoutMs);
};
