// SPDX-License-Identifier: MIT
#include "clioutput.h"

#include <cstdio>
#include <QCommandLineParser>
#include <QCoreApplication>

namespace CliOutput {

void out(const QString& text)
{
    const QByteArray bytes = text.toLocal8Bit();
    std::fwrite(bytes.constData(), 1, size_t(bytes.size()), stdout);
    std::fputc('\n', stdout);
    std::fflush(stdout);
}

void err(const QString& text)
{
    const QByteArray bytes = text.toLocal8Bit();
    std::fwrite(bytes.constData(), 1, size_t(bytes.size()), stderr);
    std::fputc('\n', stderr);
    std::fflush(stderr);
}

int parseCommand(QCommandLineParser& parser, const QStringList& args, const QString& description)
{
    parser.setApplicationDescription(description);
    const QCommandLineOption help({QStringLiteral("h"), QStringLiteral("help")},
                                  QCoreApplication::translate("Cli", "Show this help."));
    parser.addOption(help);
    if (!parser.parse(args)) {
        err(parser.errorText());
        err(QCoreApplication::translate("Cli", "Run '%1 --help' for usage.").arg(args.first()));
        return 2;
    }
    if (parser.isSet(help)) {
        out(parser.helpText());
        return 0;
    }
    return -1;
}

} // namespace CliOutput
