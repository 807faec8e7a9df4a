// SPDX-License-Identifier: MIT
#include "cli/clioutput.h"
#include "cli/configcommand.h"
#include "cli/discovercommand.h"
#include "cli/reportcommand.h"
#include "guimain.h"

#include <QCoreApplication>

using namespace Qt::StringLiterals;

namespace {
void setIdentity()
{
    QCoreApplication::setOrganizationName(u"Bridgescope"_s);
    QCoreApplication::setApplicationName(u"bridgescope"_s);
    QCoreApplication::setApplicationVersion(QStringLiteral(BRIDGESCOPE_VERSION));
}
} // namespace

int main(int argc, char** argv)
{
    setIdentity();
    const QString first = argc > 1 ? QString::fromLocal8Bit(argv[1]) : QString();
    const bool help = first == u"-h"_s || first == u"--help"_s;
    const bool version = first == u"-v"_s || first == u"--version"_s;
    static const QStringList commands = {u"config"_s, u"discover"_s, u"report"_s};
    if (commands.contains(first) || help || version) {
        // Commands need no display.
        QCoreApplication app(argc, argv);
        installTranslations(app);
        const QStringList args = app.arguments().mid(1);
        if (help) {
            CliOutput::out(bridgescopeUsage());
            return 0;
        }
        if (version) {
            CliOutput::out(u"bridgescope "_s + QCoreApplication::applicationVersion());
            return 0;
        }
        if (first == u"discover"_s)
            return runDiscoverCommand(args);
        if (first == u"report"_s)
            return runReportCommand(args);
        return runConfigCommand(args);
    }
    return runGui(argc, argv);
}
