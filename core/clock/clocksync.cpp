// SPDX-License-Identifier: MIT
#include "clock/clocksync.h"

#include "base/ioappend.h"

#include <cmath>
#include <QDeadlineTimer>
#include <QProcess>
#include <QStandardPaths>

using namespace Qt::StringLiterals;

namespace {
/// A number as text (seconds, ppm) times `scale` (to ns, ppb); false unless finite and within ±1e6.
bool readScaled(const QByteArray& text, double scale, qint64* value)
{
    bool ok = false;
    const double v = text.trimmed().toDouble(&ok);
    if (!ok || !std::isfinite(v) || std::fabs(v) > 1e6)
        return false;
    *value = qint64(std::llround(v * scale));
    return true;
}

/// A reference name: printable ASCII without spaces, at most kMaxReferenceBytes; empty when not one.
bool isReference(const QByteArray& text)
{
    if (text.size() > ClockSyncState::kMaxReferenceBytes)
        return false;
    for (const char c : text)
        if (c <= ' ' || c > '~')
            return false;
    return true;
}

QString ms(qint64 ns)
{
    return (ns >= 0 ? u"+"_s : QString()) + QString::number(double(ns) / 1e6, 'f', 3);
}
} // namespace

bool ClockSyncState::isSynchronised() const
{
    switch (source) {
    case Source::Chrony:
        return status != 3;
    case Source::Ptp:
        return status == 1;
    case Source::None:
        break;
    }
    return false;
}

QString ClockSyncState::text() const
{
    switch (source) {
    case Source::Chrony:
        return ClockSync::tr("chrony, %1 (%2): offset %3 ms, root delay %4 ms, root dispersion %5 ms, "
                             "frequency %6 ppm")
            .arg(isSynchronised() ? ClockSync::tr("synchronised") : ClockSync::tr("not synchronised"),
                 reference, ms(offsetNs))
            .arg(double(rootDelayNs) / 1e6, 0, 'f', 3)
            .arg(double(rootDispersionNs) / 1e6, 0, 'f', 3)
            .arg(double(frequencyPpb) / 1e3, 0, 'f', 3);
    case Source::Ptp:
        return ClockSync::tr("linuxptp, %1 (%2): master offset %3 ms")
            .arg(isSynchronised() ? ClockSync::tr("grandmaster present") : ClockSync::tr("no grandmaster"),
                 reference, ms(offsetNs));
    case Source::None:
        break;
    }
    return ClockSync::tr("not reported");
}

bool ClockSyncState::operator==(const ClockSyncState& o) const
{
    return source == o.source && status == o.status && offsetNs == o.offsetNs && rootDelayNs == o.rootDelayNs
        && rootDispersionNs == o.rootDispersionNs && frequencyPpb == o.frequencyPpb && skewPpb == o.skewPpb
        && reference == o.reference;
}

ClockSyncState ClockSync::parseChrony(const QByteArray& output)
{
    // Reference ID, name, stratum, ref time, system time, last offset, RMS offset, frequency,
    // residual frequency, skew, root delay, root dispersion, update interval, leap status.
    if (output.size() > kMaxOutputBytes)
        return {};
    const QByteArray line = output.trimmed();
    if (line.contains('\n'))
        return {};
    const QList<QByteArray> f = line.split(',');
    if (f.size() != 14)
        return {};
    ClockSyncState s;
    constexpr double kNsPerSecond = 1e9;
    constexpr double kPpbPerPpm = 1e3;
    if (!isReference(f[1]) || !readScaled(f[4], kNsPerSecond, &s.offsetNs)
        || !readScaled(f[7], kPpbPerPpm, &s.frequencyPpb) || !readScaled(f[9], kPpbPerPpm, &s.skewPpb)
        || !readScaled(f[10], kNsPerSecond, &s.rootDelayNs)
        || !readScaled(f[11], kNsPerSecond, &s.rootDispersionNs))
        return {};
    static const QList<QByteArray> leap = {"Normal", "Insert second", "Delete second", "Not synchronised"};
    const qsizetype status = leap.indexOf(f[13]);
    if (status < 0)
        return {};
    s.status = quint8(status);
    s.reference = QString::fromLatin1(f[1]);
    s.source = ClockSyncState::Source::Chrony;
    return s;
}

ClockSyncState ClockSync::parsePmc(const QByteArray& output)
{
    if (output.size() > kMaxOutputBytes || !output.contains("RESPONSE MANAGEMENT TIME_STATUS_NP"))
        return {};
    ClockSyncState s;
    bool offset = false;
    bool present = false;
    const QList<QByteArray> lines = output.split('\n');
    for (const QByteArray& raw : lines) {
        const QList<QByteArray> words = raw.simplified().split(' ');
        if (words.size() != 2)
            continue;
        if (words[0] == "master_offset") {
            bool ok = false;
            s.offsetNs = words[1].toLongLong(&ok);
            if (!ok)
                return {};
            offset = true;
        } else if (words[0] == "gmPresent") {
            if (words[1] != "true" && words[1] != "false")
                return {};
            s.status = words[1] == "true" ? 1 : 0;
            present = true;
        } else if (words[0] == "gmIdentity" && isReference(words[1])) {
            s.reference = QString::fromLatin1(words[1]);
        }
    }
    if (!offset || !present)
        return {};
    s.source = ClockSyncState::Source::Ptp;
    return s;
}

QByteArray ClockSync::run(const QString& program, const QStringList& arguments, int timeoutMs)
{
    const QString path = QStandardPaths::findExecutable(program);
    if (path.isEmpty())
        return {};
    QProcess process;
    process.setProcessChannelMode(QProcess::SeparateChannels);
    process.setStandardInputFile(QProcess::nullDevice());
    process.setStandardErrorFile(QProcess::nullDevice());
    process.start(path, arguments, QIODevice::ReadOnly);
    QByteArray output;
    QDeadlineTimer deadline(timeoutMs);
    if (!process.waitForStarted(int(deadline.remainingTime())))
        return {};
    while (process.state() != QProcess::NotRunning && !deadline.hasExpired()) {
        process.waitForReadyRead(int(qMax<qint64>(1, deadline.remainingTime())));
        IoAppend::available(process, output, kMaxOutputBytes + 1);
        if (output.size() > kMaxOutputBytes)
            break;
    }
    if (process.state() != QProcess::NotRunning) {
        process.kill();
        process.waitForFinished(1000);
        return {};
    }
    IoAppend::available(process, output, kMaxOutputBytes + 1);
    if (output.size() > kMaxOutputBytes || process.exitStatus() != QProcess::NormalExit
        || process.exitCode() != 0)
        return {};
    return output;
}

ClockSyncState ClockSync::read(int timeoutMs)
{
    if (const ClockSyncState chrony = parseChrony(run(u"chronyc"_s, {u"-c"_s, u"tracking"_s}, timeoutMs));
        chrony.isReported())
        return chrony;
    return parsePmc(run(u"pmc"_s, {u"-u"_s, u"-b"_s, u"0"_s, u"GET TIME_STATUS_NP"_s}, timeoutMs));
}
