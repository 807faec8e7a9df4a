// SPDX-License-Identifier: MIT
#include "clock/clockprobe.h"

#include <algorithm>
#include <cstring>
#include <QtEndian>

using namespace Qt::StringLiterals;

namespace {
// The layout (docs/formats.md): every integer little-endian, every text zero-padded UTF-8.
constexpr char kMagic[4] = {'B', 'S', 'C', 'K'};
constexpr int kVersionAt = 4;
constexpr int kKindAt = 5;
constexpr int kNameLengthAt = 6;
constexpr int kReplyLengthAt = 7;
constexpr int kNonceAt = 8;
constexpr int kT1At = 16;
constexpr int kT2At = 24;
constexpr int kT3At = 32;
constexpr int kNameAt = 40;
constexpr int kReplyAt = kNameAt + ClockProbe::kMaxNameBytes; // 104
constexpr int kSyncSourceAt = kReplyAt + ClockProbe::kMaxReplyTopicBytes; // 224
constexpr int kSyncStatusAt = 225;
constexpr int kReferenceLengthAt = 226;
constexpr int kReservedAt = 227;
constexpr int kSyncOffsetAt = 228;
constexpr int kRootDelayAt = 236;
constexpr int kRootDispersionAt = 244;
constexpr int kFrequencyAt = 252;
constexpr int kSkewAt = 260;
constexpr int kReferenceAt = 268;
static_assert(kReferenceAt + ClockSyncState::kMaxReferenceBytes == ClockProbe::kSize);

/// Text at `at` of `length` bytes in a field of `field` bytes: valid UTF-8 without control
/// characters, the rest of the field zeros. False when not.
bool readText(const uchar* bytes, int at, int length, int field, QString* text)
{
    if (length > field)
        return false;
    for (int i = length; i < field; ++i)
        if (bytes[at + i] != 0)
            return false;
    const QByteArray raw(reinterpret_cast<const char*>(bytes + at), length);
    QString decoded = QString::fromUtf8(raw);
    if (decoded.toUtf8() != raw)
        return false;
    for (const QChar c : decoded)
        if (c.category() == QChar::Other_Control || c == QChar::ReplacementCharacter)
            return false;
    *text = std::move(decoded);
    return true;
}

void writeText(uchar* bytes, int at, const QByteArray& text)
{
    std::memcpy(bytes + at, text.constData(), std::size_t(text.size()));
}

bool isValidReplyTopic(const QString& topic)
{
    return !topic.contains(u'+') && !topic.contains(u'#')
        && topic.toUtf8().size() <= ClockProbe::kMaxReplyTopicBytes;
}
} // namespace

bool ClockProbe::isValidName(const QString& name)
{
    const QByteArray utf8 = name.toUtf8();
    if (utf8.isEmpty() || utf8.size() > kMaxNameBytes || QString::fromUtf8(utf8) != name)
        return false;
    for (const QChar c : name)
        if (!c.isPrint() || c.isSpace() || c == u'/' || c == u'+' || c == u'#' || c.isSurrogate())
            return false;
    return true;
}

ClockProbe ClockProbe::answer(const QString& host, qint64 t2Ns, qint64 t3Ns,
                              const ClockSyncState& state) const
{
    ClockProbe a;
    a.kind = Kind::Answer;
    a.nonce = nonce;
    a.t1 = t1;
    a.t2 = t2Ns;
    a.t3 = t3Ns;
    a.name = host;
    a.sync = state;
    return a;
}

QByteArray ClockProbe::encode() const
{
    QByteArray out(kSize, '\0');
    auto* b = reinterpret_cast<uchar*>(out.data());
    const QByteArray host = name.toUtf8().left(kMaxNameBytes);
    const QByteArray reply = replyTopic.toUtf8().left(kMaxReplyTopicBytes);
    const QByteArray reference = sync.reference.toLatin1().left(ClockSyncState::kMaxReferenceBytes);
    std::memcpy(b, kMagic, sizeof kMagic);
    b[kVersionAt] = kVersion;
    b[kKindAt] = quint8(kind);
    b[kNameLengthAt] = uchar(host.size());
    b[kReplyLengthAt] = uchar(reply.size());
    qToLittleEndian<quint64>(nonce, b + kNonceAt);
    qToLittleEndian<qint64>(t1, b + kT1At);
    qToLittleEndian<qint64>(t2, b + kT2At);
    qToLittleEndian<qint64>(t3, b + kT3At);
    writeText(b, kNameAt, host);
    writeText(b, kReplyAt, reply);
    if (sync.isReported()) {
        b[kSyncSourceAt] = quint8(sync.source);
        b[kSyncStatusAt] = sync.status;
        b[kReferenceLengthAt] = uchar(reference.size());
        qToLittleEndian<qint64>(sync.offsetNs, b + kSyncOffsetAt);
        qToLittleEndian<qint64>(sync.rootDelayNs, b + kRootDelayAt);
        qToLittleEndian<qint64>(sync.rootDispersionNs, b + kRootDispersionAt);
        qToLittleEndian<qint64>(sync.frequencyPpb, b + kFrequencyAt);
        qToLittleEndian<qint64>(sync.skewPpb, b + kSkewAt);
        writeText(b, kReferenceAt, reference);
    }
    return out;
}

Result<ClockProbe> ClockProbe::decode(const QByteArray& bytes)
{
    if (bytes.size() != kSize)
        return LocatedError {tr("a clock probe has %1 bytes, not %2").arg(kSize).arg(bytes.size())};
    const auto* b = reinterpret_cast<const uchar*>(bytes.constData());
    if (std::memcmp(b, kMagic, sizeof kMagic) != 0)
        return LocatedError {tr("not a clock probe (wrong magic)")};
    if (b[kVersionAt] != kVersion)
        return LocatedError {
            tr("clock probe version %1 is not known (%2 is)").arg(b[kVersionAt]).arg(kVersion)};
    ClockProbe p;
    if (b[kKindAt] != quint8(Kind::Probe) && b[kKindAt] != quint8(Kind::Answer))
        return LocatedError {tr("clock probe kind %1 is not known").arg(b[kKindAt])};
    p.kind = Kind(b[kKindAt]);
    p.nonce = qFromLittleEndian<quint64>(b + kNonceAt);
    p.t1 = qFromLittleEndian<qint64>(b + kT1At);
    p.t2 = qFromLittleEndian<qint64>(b + kT2At);
    p.t3 = qFromLittleEndian<qint64>(b + kT3At);
    if (!readText(b, kNameAt, b[kNameLengthAt], kMaxNameBytes, &p.name)
        || (!p.name.isEmpty() && !isValidName(p.name)))
        return LocatedError {tr("the host name of a clock probe is not valid")};
    if (!readText(b, kReplyAt, b[kReplyLengthAt], kMaxReplyTopicBytes, &p.replyTopic)
        || !isValidReplyTopic(p.replyTopic))
        return LocatedError {tr("the reply topic of a clock probe is not valid")};
    if (p.kind == Kind::Probe) {
        if (p.t2 != 0 || p.t3 != 0 || b[kSyncSourceAt] != 0)
            return LocatedError {tr("a clock probe carries server fields")};
    } else if (p.name.isEmpty() || !p.replyTopic.isEmpty() || p.t3 < p.t2) {
        return LocatedError {tr("a clock probe's answer lacks its host or has t3 before t2")};
    }
    const quint8 source = b[kSyncSourceAt];
    const int referenceLength = b[kReferenceLengthAt];
    if (b[kReservedAt] != 0 || source > quint8(ClockSyncState::Source::Ptp))
        return LocatedError {tr("the sync state of a clock probe is not valid")};
    if (source == 0) {
        for (int i = kSyncStatusAt; i < kSize; ++i)
            if (b[i] != 0)
                return LocatedError {tr("the sync state of a clock probe is not valid")};
        return p;
    }
    ClockSyncState& s = p.sync;
    s.source = ClockSyncState::Source(source);
    s.status = b[kSyncStatusAt];
    s.offsetNs = qFromLittleEndian<qint64>(b + kSyncOffsetAt);
    s.rootDelayNs = qFromLittleEndian<qint64>(b + kRootDelayAt);
    s.rootDispersionNs = qFromLittleEndian<qint64>(b + kRootDispersionAt);
    s.frequencyPpb = qFromLittleEndian<qint64>(b + kFrequencyAt);
    s.skewPpb = qFromLittleEndian<qint64>(b + kSkewAt);
    QString reference;
    if (s.status > 3 || referenceLength > ClockSyncState::kMaxReferenceBytes
        || !readText(b, kReferenceAt, referenceLength, ClockSyncState::kMaxReferenceBytes, &reference)
        || !std::all_of(b + kReferenceAt, b + kReferenceAt + referenceLength,
                        [](uchar c) { return c > ' ' && c <= '~'; }))
        return LocatedError {tr("the sync state of a clock probe is not valid")};
    s.reference = reference;
    return p;
}

bool ClockProbe::operator==(const ClockProbe& o) const
{
    return kind == o.kind && nonce == o.nonce && t1 == o.t1 && t2 == o.t2 && t3 == o.t3 && name == o.name
        && replyTopic == o.replyTopic && sync == o.sync;
}
