// SPDX-License-Identifier: MIT
#include "planhosts.h"

#include "yaml/yamlreader.h"

#include <yaml-cpp/yaml.h>

using namespace Qt::StringLiterals;

namespace {
constexpr int kMaxProgramLength = 1024;

Result<QString> readProgram(const YamlReader& r, const YAML::Node& n)
{
    const QString path = YamlReader::text(n);
    if (!n.IsScalar() || !path.startsWith(u'/') || path.size() > kMaxProgramLength || path.contains(QChar(0))
        || path.contains(u'\n'))
        return r.errorAt(n,
                         PlanHosts::tr("program is the absolute path of bridgescope on the far host "
                                       "(/usr/bin/bridgescope), at most %1 characters")
                             .arg(kMaxProgramLength));
    return path;
}

Result<PlanHost> readHost(const YamlReader& r, const YAML::Node& n)
{
    PlanHost side;
    const YAML::Node url = n.IsMap() ? n["url"] : n;
    if (n.IsMap()) {
        if (const Status keys = r.checkKeys(n, {u"url"_s, u"program"_s}); !keys)
            return keys.error();
        if (const YAML::Node program = n["program"]) {
            const Result<QString> path = readProgram(r, program);
            if (!path)
                return path.error();
            side.program = *path;
        }
        if (!url)
            return r.errorAt(
                n, PlanHosts::tr("a host is ssh://user@host[:port] or {url: ssh://…, program: PATH}"));
    }
    if (!url.IsScalar())
        return r.errorAt(url,
                         PlanHosts::tr("a host is ssh://user@host[:port] or {url: ssh://…, program: PATH}"));
    const Result<RemoteHost> host = RemoteHost::parse(YamlReader::text(url));
    if (!host)
        return r.errorAt(url, host.error().message);
    side.host = *host;
    return side;
}
} // namespace

const std::optional<PlanHost>& PlanHosts::side(const QString& role) const
{
    static const std::optional<PlanHost> none;
    return role == u"vehicle"_s ? vehicle : role == u"cloud"_s ? cloud : none;
}

QString PlanHosts::programFor(const QString& role, const QString& localProgram) const
{
    const std::optional<PlanHost>& s = side(role);
    if (s && !s->program.isEmpty())
        return s->program;
    return program.isEmpty() ? localProgram : program;
}

Result<PlanHosts> PlanHosts::read(const YamlReader& r, const YAML::Node& hosts, const YAML::Node& program)
{
    PlanHosts result;
    if (hosts) {
        if (!hosts.IsMap() || hosts.size() == 0)
            return r.errorAt(hosts, tr("hosts is {vehicle: ssh://user@host, cloud: ssh://user@host}"));
        for (const auto& kv : hosts) {
            const QString role = YamlReader::text(kv.first);
            if (role != u"vehicle"_s && role != u"cloud"_s)
                return r.errorAt(kv.first,
                                 tr("unknown host '%1': a plan's hosts are vehicle and cloud").arg(role));
            const Result<PlanHost> side = readHost(r, kv.second);
            if (!side)
                return side.error();
            (role == u"vehicle"_s ? result.vehicle : result.cloud) = *side;
        }
    }
    if (program) {
        if (!result.any())
            return r.errorAt(program, tr("program is bridgescope's path on the hosts: it needs hosts:"));
        const Result<QString> path = readProgram(r, program);
        if (!path)
            return path.error();
        result.program = *path;
    }
    return result;
}
