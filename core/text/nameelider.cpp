// SPDX-License-Identifier: MIT
#include "nameelider.h"

#include <algorithm>
#include <QSet>

namespace {

const QString ellipsis = QStringLiteral("\u2026");

int commonPrefix(const QString& a, const QString& b)
{
    const int n = int(std::min(a.size(), b.size()));
    int i = 0;
    while (i < n && a.at(i) == b.at(i))
        ++i;
    return i;
}

/// A name's segments; dropped ones (null) are drawn as one `…` a run.
QString render(const QStringList& shown)
{
    QStringList parts;
    for (int i = 0; i < shown.size(); ++i) {
        if (!shown.at(i).isNull())
            parts << shown.at(i);
        else if (parts.isEmpty() || parts.last() != ellipsis)
            parts << ellipsis;
    }
    return parts.join(u'/');
}

} // namespace

QString NameElider::elideTail(const QString& name, qsizetype max)
{
    if (name.size() <= max)
        return name;
    if (max < 2)
        return name.left(max);
    qsizetype from = name.size() - (max - 1);
    if (name.at(from).isLowSurrogate())
        ++from;
    return ellipsis + name.mid(from);
}

void NameElider::setNames(const QStringList& names)
{
    m_names = names;
    m_namespaces.clear();
    // Each namespace's children (a namespace's siblings), over every name.
    QHash<QString, QSet<QString>> children;
    for (const QString& name : names) {
        const QStringList segments = name.split(u'/');
        if (segments.size() > MaxSegments)
            continue;
        QString path;
        for (int i = 0; i + 1 < segments.size(); ++i) { // the last segment is not a namespace
            children[path].insert(segments.at(i));
            path += segments.at(i) + u'/';
        }
    }
    // In sorted order a namespace's closest siblings are its neighbours.
    for (auto it = children.cbegin(); it != children.cend(); ++it) {
        QStringList sorted(it.value().cbegin(), it.value().cend());
        std::sort(sorted.begin(), sorted.end());
        for (int i = 0; i < sorted.size(); ++i) {
            Namespace ns;
            ns.siblings = int(sorted.size()) - 1;
            if (i > 0)
                ns.shared = std::max(ns.shared, commonPrefix(sorted.at(i), sorted.at(i - 1)));
            if (i + 1 < sorted.size())
                ns.shared = std::max(ns.shared, commonPrefix(sorted.at(i), sorted.at(i + 1)));
            m_namespaces.insert(it.key() + sorted.at(i), ns);
        }
    }
}

QString NameElider::abbreviated(const QString& segment, const Namespace& ns) const
{
    QString shorter;
    if (ns.shared >= segment.size())
        return segment; // a sibling begins with all of it
    if (ns.shared <= 2)
        shorter = segment.left(ns.shared + 1) + ellipsis; // `b…` for benchmarking_suite beside vehicle
    else if (segment.size() - ns.shared >= 3)
        shorter = ellipsis + segment.mid(ns.shared); // `…vehicle` beside mqtt_interface_cloud
    else
        return segment; // `…2` for cloud2 beside cloud says too little
    // Only when it saves room: `…` takes about a character's width itself.
    return shorter.size() < segment.size() ? shorter : segment;
}

QStringList NameElider::forms(const QString& name) const
{
    QStringList result {name};
    const QStringList segments = name.split(u'/');
    const int n = int(segments.size());
    if (n < 2 || n > MaxSegments)
        return result;
    const bool rooted = segments.at(0).isEmpty();
    QList<Namespace> spaces;
    QString path;
    for (int i = 0; i + 1 < n; ++i) {
        spaces << m_namespaces.value(path + segments.at(i));
        path += segments.at(i) + u'/';
    }
    const int first = rooted ? 1 : 0; // the root of `/a/b` is no namespace to shorten
    // 1. Abbreviate the namespaces from the left.
    QStringList shown = segments;
    for (int i = first; i + 1 < n; ++i) {
        shown[i] = abbreviated(segments.at(i), spaces.at(i));
        if (shown.at(i) != segments.at(i))
            result << render(shown);
    }
    const auto drop = [&](int i) {
        shown[i] = QString();
        if (i == first && rooted)
            shown[0] = QString(); // `…/b`, not `/…/b`
        result << render(shown);
    };
    // 2. Drop the namespaces without siblings: they tell no names apart.
    for (int i = first; i + 1 < n; ++i)
        if (spaces.at(i).siblings == 0)
            drop(i);
    // 3. Then the others, from the left.
    for (int i = first; i + 1 < n; ++i)
        if (!shown.at(i).isNull())
            drop(i);
    result.removeDuplicates();
    return result;
}
