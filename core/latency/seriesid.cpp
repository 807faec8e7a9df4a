// SPDX-License-Identifier: MIT
#include "seriesid.h"

using namespace Qt::StringLiterals;

namespace {
constexpr QStringView stagePrefix = u"stage:";
constexpr QStringView externalPrefix = u"ext:";
constexpr std::pair<SeriesKind, QStringView> fixedIds[] = {
    {SeriesKind::Total, u"total"},
    {SeriesKind::RoundTrip, u"round_trip"},
    {SeriesKind::OneWay, u"one_way"},
    {SeriesKind::ClockOffset, u"clock_offset"},
    {SeriesKind::There, u"there"},
    {SeriesKind::Back, u"back"},
};
} // namespace

QString SeriesId::toString() const
{
    switch (kind) {
    case SeriesKind::Stage:
        return stagePrefix + QString::number(stage);
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
    if (text.startsWith(stagePrefix)) {
        bool ok = false;
        const int index = QStringView(text).mid(stagePrefix.size()).toInt(&ok);
        if (!ok || index < 0)
            return std::nullopt;
        return ofStage(index);
    }
    if (text.startsWith(externalPrefix))
        return external(text.mid(externalPrefix.size()));
    for (const auto& [k, id] : fixedIds)
        if (text == id)
            return ofKind(k);
    return std::nullopt;
}
