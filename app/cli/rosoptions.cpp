// SPDX-License-Identifier: MIT
#include "rosoptions.h"

using namespace Qt::StringLiterals;

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

bool RosOptions::read(const QCommandLineParser& parser, QString* error)
{
    const QString which = parser.value(m_graphs);
    if (which != u"1"_s && which != u"2"_s && which != u"both"_s) {
        *error = tr("--ros takes 1, 2 or both, not \"%1\"").arg(which.left(40));
        return false;
    }
    graphsSet = parser.isSet(m_graphs);
    ros1 = which != u"2"_s;
    ros2 = which != u"1"_s;
    ros2Options = Ros2Options::fromEnvironment(&environmentError);
    if (parser.isSet(m_domain)) {
        bool ok = false;
        const int id = parser.value(m_domain).toInt(&ok);
        if (!ok || id < 0 || id > Ros2Options::kMaxDomain) {
            *error = tr("--ros-domain takes a domain id from 0 to %1").arg(Ros2Options::kMaxDomain);
            return false;
        }
        ros2Options.domain = id;
    }
    if (parser.isSet(m_localhost))
        ros2Options.localhostOnly = true;
    ros2OptionsSet = parser.isSet(m_domain) || parser.isSet(m_localhost);
    return true;
}
