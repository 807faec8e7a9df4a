// SPDX-License-Identifier: MIT
#include "cli/clioutput.h"
#include "cli/configcommand.h"

#include <QCoreApplication>

using namespace Qt::StringLiterals;

int main(int argc, char** argv)
{
    QCoreApplication app(argc, argv);
    const QStringList args = app.arguments().mid(1);
    if (!args.isEmpty() && args.first() == u"config"_s)
        return runConfigCommand(args);
    CliOutput::err(u"usage: bridgescope config ..."_s);
    return 2;
}
