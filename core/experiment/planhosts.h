// SPDX-License-Identifier: MIT
#pragma once

#include "base/result.h"
#include "remote/remotehost.h"

#include <optional>
#include <QCoreApplication>
#include <QString>

class YamlReader;
namespace YAML {
class Node;
}

/// One side of a plan's lab on a host of its own: where it is reached over ssh, and which
/// bridgescope runs there.
struct PlanHost
{
    RemoteHost host;
    QString program; ///< the bridgescope on that host; empty: the plan's, else the local one's path
};

/// Where a plan's two sides run (`hosts: {vehicle: ssh://user@a, cloud: ssh://user@b}`): a side
/// not named runs on the controller's machine, as every side of a plan without hosts does.
struct PlanHosts
{
    Q_DECLARE_TR_FUNCTIONS(PlanHosts)
public:
    std::optional<PlanHost> vehicle;
    std::optional<PlanHost> cloud;
    QString program; ///< the plan's `program:`, the default of both hosts; empty: the local one's path

    bool any() const { return vehicle || cloud; }
    /// The side `role` ("vehicle" or "cloud"), or none.
    const std::optional<PlanHost>& side(const QString& role) const;
    /// The bridgescope to run on `role`'s host: its own program, the plan's, else `localProgram`
    /// (the controller's own absolute path: the same installation on every host).
    QString programFor(const QString& role, const QString& localProgram) const;

    /// Reads a plan's `hosts:` and `program:` (either may be an absent node); every error is
    /// located at the value it is about.
    static Result<PlanHosts> read(const YamlReader& r, const YAML::Node& hosts, const YAML::Node& program);
};
