// SPDX-License-Identifier: MIT
#include "clioutput.h"

#include <csignal>
#include <cstdio>
#include <malloc.h>
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

namespace {
volatile std::sig_atomic_t g_stopRequested = 0;

void requestStop(int)
{
    g_stopRequested = 1;
}
} // namespace

void catchStopSignals()
{
    std::signal(SIGINT, requestStop);
    std::signal(SIGTERM, requestStop);
}

bool stopRequested()
{
    return g_stopRequested != 0;
}

void keepFreedMemory()
{
    mallopt(M_MMAP_THRESHOLD, 32 * 1024 * 1024); // glibc's maximum on 64-bit
    mallopt(M_TRIM_THRESHOLD, 512 * 1024 * 1024);
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
        // Qt names the program in the usage line; the command ("bridgescope report") is what to type.
        QString text = parser.helpText();
        const QString usage = QStringLiteral("Usage: ");
        if (text.startsWith(usage)) {
            const qsizetype end = text.indexOf(QStringLiteral(" [options]"));
            if (end > 0 && !QCoreApplication::arguments().isEmpty())
                text.replace(usage.size(), end - usage.size(), args.first());
        }
        out(text);
        return 0;
    }
    return -1;
}

} // namespace CliOutput
