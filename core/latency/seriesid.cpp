// SPDX-License-Identifier: MIT
#include "seriesid.h"

using namespace Qt::StringLiterals;

namespace {
constexpr QStringView stagePrefix = u"stage:";
constexpr QStringView externalPrefix = u"ext:";
constexpr QStringView observedPrefix = u"observed ";
constexpr QStringView correctedPrefix = u"corrected:";
constexpr std::pair<SeriesKind, QStringView> fixedIds[] = {
    {SeriesKind::Total, u"total"},         {SeriesKind::RoundTrip, u"round_trip"},
    {SeriesKind::OneWay, u"one_way"},      {SeriesKind::ClockOffset, u"clock_offset"},
    {SeriesKind::There, u"there"},         {SeriesKind::Back, u"back"},
    {SeriesKind::Asymmetry, u"asymmetry"},
};

/// The stage index after `prefix`, or -1.
int indexAfter(const QString& text, QStringView prefix)
{
    bool ok = false;
    const int index = QStringView(text).mid(prefix.size()).toInt(&ok);
    return ok && index >= 0 ? index : -1;
}
} // namespace

QString SeriesId::toString() const
{
    switch (kind) {
    case SeriesKind::Stage:
        return stagePrefix + QString::number(stage);
    case SeriesKind::Corrected:
        return correctedPrefix + QString::number(stage);
    case SeriesKind::External:
        return externalPrefix + name;
    default:
        for (const auto& [k, text] : fixedIds)
            if (k == kind)
                return text.toString();
    }
    return {};
}

std::optional<SeriesId> SeriesId::parse(const QString& text)
{
    for (const auto& [prefix, kind] :
         {std::pair {stagePrefix, SeriesKind::Stage}, std::pair {correctedPrefix, SeriesKind::Corrected}}) {
        if (!text.startsWith(prefix))
            continue;
        const int index = indexAfter(text, prefix);
        if (index < 0)
            return std::nullopt;
        return SeriesId {kind, index, {}};
    }
    if (text.startsWith(externalPrefix))
        return external(text.mid(externalPrefix.size()));
    for (const auto& [k, id] : fixedIds)
        if (text == id)
            return ofKind(k);
    return std::nullopt;
}

QString SeriesId::observedName(const QString& source, const QString& destination)
{
    return observedPrefix.toString() + source + u" \u2192 "_s + destination;
}

bool SeriesId::isObserved(const QString& name)
{
    return name.startsWith(observedPrefix);
}
