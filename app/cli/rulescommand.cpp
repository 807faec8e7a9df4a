// SPDX-License-Identifier: MIT
#include "rulescommand.h"

#include "app/cli/clioutput.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QFile>

using namespace Qt::StringLiterals;

namespace {
class Rules
{
    Q_DECLARE_TR_FUNCTIONS(Rules)
public:
    static QString help()
    {
        return tr("Prints the Prometheus rules for the metrics of watch --metrics: recording rules per "
                  "link, bridge and host, and alerts (a bridge down, a link in alert or stalled, loss "
                  "over 1 %, latency p99 over 100 ms, a host's watch gone). Save them where Prometheus "
                  "reads its rule_files:\n"
                  "  bridgescope rules > /etc/prometheus/bridgescope-rules.yml\n"
                  "Exit status: 0 printed, 2 bad arguments or standard output cannot be written.");
    }
};
} // namespace

int runRulesCommand(const QStringList& arguments)
{
    QCommandLineParser parser;
    const int parsed = CliOutput::parseCommand(parser, arguments, u"bridgescope rules"_s, Rules::help());
    if (parsed >= 0)
        return parsed;
    if (!parser.positionalArguments().isEmpty()) {
        CliOutput::err(Rules::tr("rules takes no arguments; see bridgescope rules --help"));
        return CliOutput::ExitUsage;
    }
    QFile rules(u":/prometheus/bridgescope-rules.yml"_s);
    if (!rules.open(QIODevice::ReadOnly)) { // only a broken build lacks its own resource
        CliOutput::err(Rules::tr("error: the rules are not in this build: %1").arg(rules.errorString()));
        return CliOutput::ExitFailed;
    }
    return CliOutput::writeStdout(rules.readAll()) ? CliOutput::ExitOk : CliOutput::ExitUsage;
}
