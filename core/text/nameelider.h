// SPDX-License-Identifier: MIT
#pragma once

#include <QHash>
#include <QString>
#include <QStringList>

/// Shortens slash-separated names (ROS topics, MQTT topics, ROS types) so that what tells them
/// apart survives. Qt's middle elision turns `/benchmarking_suite/stamps/vehicle/object_list/in`
/// and `/benchmarking_suite/stamps/cloud/object_list/in` into the same `/ben…t/in`; this keeps the
/// last segment whole and gives up the namespaces from the left: first it abbreviates each to what
/// its siblings among the names do not share (`benchmarking_suite` among `vehicle` and `cloud` is
/// `b…`; `mqtt_interface_vehicle` beside `mqtt_interface_cloud` is `…vehicle`), then it drops the
/// namespaces that have no siblings (they tell nothing apart), then the others from the left, each
/// run of dropped namespaces shown as one `…`.
///
/// setNames() indexes the names a view shows (their siblings decide the abbreviations); forms()
/// lists a name's shortenings, longest first, for the caller to pick the first that fits.
class NameElider
{
public:
    /// Names with more segments than this are elided by the caller alone (bounded work).
    static constexpr int MaxSegments = 32;

    /// The most characters of a name laid out where its length is not bounded otherwise (reports,
    /// tables): laying out a 5-million-character name took minutes (docs/user-guide.md, "Reports").
    static constexpr qsizetype MaxShown = 200;
    /// `name` cut to `max` characters keeping its tail (what tells names apart), after a `…`; a
    /// shorter name as it is. Never splits a surrogate pair.
    static QString elideTail(const QString& name, qsizetype max = MaxShown);

    void setNames(const QStringList& names);
    const QStringList& names() const { return m_names; }

    /// The full name, then each shorter form, ending with `…/last` (which the caller may elide
    /// further).
    QStringList forms(const QString& name) const;

private:
    struct Namespace
    {
        int shared = 0; ///< the longest prefix it shares with a sibling
        int siblings = 0; ///< other namespaces under the same parent
    };
    QString abbreviated(const QString& segment, const Namespace& ns) const;

    QStringList m_names;
    /// Full path of a namespace (`/a/b`) -> what its siblings share with it.
    QHash<QString, Namespace> m_namespaces;
};
