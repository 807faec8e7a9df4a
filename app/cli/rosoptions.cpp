// SPDX-License-Identifier: MIT
#include "rosoptions.h"

using namespace Qt::StringLiterals;

namespace {
/// The distributions by their ROS_DISTRO names (REP 3, REP 2000), the oldest first.
const QStringList& ros1Distros()
{
    static const QStringList names {u"boxturtle"_s, u"cturtle"_s, u"diamondback"_s, u"electric"_s, u"fuerte"_s,
                                    u"groovy"_s,    u"hydro"_s,   u"indigo"_s,      u"jade"_s,     u"kinetic"_s,
                                    u"lunar"_s,     u"melodic"_s, u"noetic"_s};
    return names;
}
const QStringList& ros2Distros()
{
    static const QStringList names {u"ardent"_s, u"bouncy"_s, u"crystal"_s, u"dashing"_s, u"eloquent"_s,
                                    u"foxy"_s,   u"galactic"_s, u"humble"_s, u"iron"_s,    u"jazzy"_s,
                                    u"kilted"_s, u"lyrical"_s,  u"rolling"_s};
    return names;
}
} // namespace

QString RosOptions::environmentGraphs(QString* why, QString* warning)
{
    const QString version = qEnvironmentVariable("ROS_VERSION").trimmed();
    if (version == u"1"_s || version == u"2"_s) {
        *why = u"ROS_VERSION="_s + version;
        return version;
    }
    if (!version.isEmpty())
        *warning = tr("ROS_VERSION is \"%1\", not 1 or 2: ignored").arg(version.left(40));
    const QString distro = qEnvironmentVariable("ROS_DISTRO").trimmed().toLower();
    if (distro.isEmpty())
        return {};
    const bool one = ros1Distros().contains(distro);
    if (!one && !ros2Distros().contains(distro)) {
        const QString unknown = tr("ROS_DISTRO is \"%1\", not a ROS distribution known here: ignored")
                                    .arg(distro.left(40));
        *warning = warning->isEmpty() ? unknown : *warning + u"; "_s + unknown;
        return {};
    }
    *why = u"ROS_DISTRO="_s + distro;
    return one ? u"1"_s : u"2"_s;
}

QString RosOptions::choice() const
{
    QString graphs = ros1 && ros2 ? tr("ROS 1 and ROS 2") : (ros2 ? tr("ROS 2") : tr("ROS 1"));
    graphs += u" ("_s + (reason == u"default"_s ? tr("default") : reason) + u")"_s;
    if (ros2)
        graphs += u", "_s + tr("domain %1").arg(ros2Options.domain)
            + (ros2Options.localhostOnly ? u", "_s + tr("this host only") : QString());
    return graphs;
}

QStringList RosOptions::notes() const
{
    QStringList lines;
    if (ros2 && !domainSet && !environmentError.isEmpty())
        lines << environmentError;
    if (!environmentWarning.isEmpty())
        lines << environmentWarning;
    lines << choice();
    return lines;
}

RosOptions::RosOptions(const QString& defaultGraphs)
    : m_graphs(u"ros"_s,
               tr("Which ROS graphs: 1 (through the master), 2 (through DDS) or both (default %1).")
                   .arg(defaultGraphs),
               u"1|2|both"_s, defaultGraphs)
    , m_domain(u"ros-domain"_s, tr("ROS 2 domain id, 0 to 232 (default $ROS_DOMAIN_ID, else 0)."), u"ID"_s)
    , m_localhost(u"ros-localhost-only"_s,
                  tr("ROS 2 discovery on this host only, over 127.0.0.1 (as ROS_LOCALHOST_ONLY=1)."))
    , m_default(defaultGraphs)
{ }

void RosOptions::addTo(QCommandLineParser& parser) const
{
    parser.addOptions({m_graphs, m_domain, m_localhost});
}

Status RosOptions::read(const QCommandLineParser& parser)
{
    graphsSet = parser.isSet(m_graphs);
    QString which = parser.value(m_graphs);
    if (which != u"1"_s && which != u"2"_s && which != u"both"_s)
        return LocatedError {tr("--ros takes 1, 2 or both, not \"%1\"").arg(which.left(40))};
    environmentWarning.clear();
    QString why;
    const QString fromEnvironment = environmentGraphs(&why, &environmentWarning);
    graphsFromEnvironment = !graphsSet && !fromEnvironment.isEmpty();
    if (graphsSet)
        reason = u"--ros "_s + which;
    else if (graphsFromEnvironment)
        reason = why;
    else
        reason = u"default"_s;
    if (graphsFromEnvironment)
        which = fromEnvironment;
    ros1 = which != u"2"_s;
    ros2 = which != u"1"_s;
    ros2Options = Ros2Options::fromEnvironment(&environmentError);
    if (parser.isSet(m_domain)) {
        bool ok = false;
        const int id = parser.value(m_domain).toInt(&ok);
        if (!ok || id < 0 || id > Ros2Options::kMaxDomain)
            return LocatedError {
                tr("--ros-domain takes a domain id from 0 to %1").arg(Ros2Options::kMaxDomain)};
        ros2Options.domain = id;
    }
    if (parser.isSet(m_localhost))
        ros2Options.localhostOnly = true;
    domainSet = parser.isSet(m_domain);
    ros2OptionsSet = domainSet || parser.isSet(m_localhost);
    return {};
}
