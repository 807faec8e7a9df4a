// SPDX-License-Identifier: MIT
#pragma once

#include "config/bridgeconfig.h"
#include "config/configwriter.h"

#include <algorithm>
#include <QString>

/// Compares configs by meaning: "60" and "60.0" are the same double, "yes" and "true" the same
/// boolean. Returns an empty string when equal, else the first difference.
namespace ConfigCompare {

inline QString normalised(OptionScope scope, const QString& path, const QString& text)
{
    const OptionSpec* spec = OptionSchema::find(scope, path);
    if (!spec)
        return text;
    if (spec->kind == OptionKind::Double) {
        bool ok = false;
        const double d = text.toDouble(&ok);
        return ok ? QString::number(d, 'g', 17) : text;
    }
    if (spec->kind == OptionKind::Bool) {
        static const QStringList yes
            = {QStringLiteral("true"), QStringLiteral("True"), QStringLiteral("yes"), QStringLiteral("on")};
        static const QStringList no
            = {QStringLiteral("false"), QStringLiteral("False"), QStringLiteral("no"), QStringLiteral("off")};
        if (yes.contains(text))
            return QStringLiteral("true");
        if (no.contains(text))
            return QStringLiteral("false");
    }
    return text;
}

inline QString compareBlocks(OptionScope scope, const OptionBlock& a, const OptionBlock& b,
                             const QString& where)
{
    QStringList paths = a.values.paths();
    for (const QString& p : b.values.paths()) {
        if (!paths.contains(p))
            paths << p;
    }
    for (const QString& p : std::as_const(paths)) {
        if (a.values.has(p) != b.values.has(p))
            return QStringLiteral("%1: '%2' set on one side only").arg(where, p);
        if (a.values.list(p) != b.values.list(p)
            && normalised(scope, p, a.values.text(p)) != normalised(scope, p, b.values.text(p)))
            return QStringLiteral("%1: '%2' is '%3' vs '%4'")
                .arg(where, p, a.values.text(p), b.values.text(p));
    }
    if (!sameExtras(a.extras, b.extras)) {
        QStringList ea, eb;
        for (const ExtraValue& e : a.extras)
            ea << e.path.join(u'.') + u'=' + e.yaml;
        for (const ExtraValue& e : b.extras)
            eb << e.path.join(u'.') + u'=' + e.yaml;
        return QStringLiteral("%1: unknown keys differ: [%2] vs [%3]")
            .arg(where, ea.join(u", "), eb.join(u", "));
    }
    return QString();
}

inline QString difference(const BridgeConfig& a, const BridgeConfig& b)
{
    QString d = compareBlocks(OptionScope::Broker, a.broker, b.broker, QStringLiteral("broker"));
    if (d.isEmpty())
        d = compareBlocks(OptionScope::Client, a.client, b.client, QStringLiteral("client"));
    if (!d.isEmpty())
        return d;
    if (!sameExtras(a.rootExtras, b.rootExtras))
        return QStringLiteral("root unknown keys differ");
    if (!sameExtras(a.bridgeExtras, b.bridgeExtras))
        return QStringLiteral("bridge unknown keys differ");
    if (!sameExtras(a.documentExtras, b.documentExtras))
        return QStringLiteral("document unknown keys differ");
    if (a.mappings.size() != b.mappings.size())
        return QStringLiteral("%1 vs %2 mappings").arg(a.mappings.size()).arg(b.mappings.size());
    // Layouts group mappings by direction; order within a direction must be kept.
    auto byDirection = [](QList<Mapping> list) {
        std::stable_sort(list.begin(), list.end(), [](const Mapping& x, const Mapping& y) {
            return int(x.direction) < int(y.direction);
        });
        return list;
    };
    const QList<Mapping> la = byDirection(a.mappings);
    const QList<Mapping> lb = byDirection(b.mappings);
    for (int i = 0; i < la.size(); ++i) {
        const Mapping& ma = la[i];
        const Mapping& mb = lb[i];
        if (ma.direction != mb.direction)
            return QStringLiteral("mapping %1: direction differs").arg(i);
        d = compareBlocks(ma.scope(), ma.block, mb.block,
                          QStringLiteral("mapping %1 (%2)").arg(i).arg(ma.sourceTopic()));
        if (!d.isEmpty())
            return d;
    }
    return QString();
}
} // namespace ConfigCompare
