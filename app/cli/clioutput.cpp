// SPDX-License-Identifier: MIT
#include "clioutput.h"

#include "text/editdistance.h"
#include "files/regularfile.h"
#include "yaml/secrets.h"

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <malloc.h>
#include <QCommandLineParser>
#include <QCoreApplication>
#include <QElapsedTimer>
#include <QRegularExpression>
#include <QTimer>

namespace CliOutput {

namespace {
int g_stdoutErrno = 0; // the first error of stdout, for finish()

bool flushStdout()
{
    errno = 0;
    const bool ok = std::fflush(stdout) == 0 && !std::ferror(stdout);
    if (!ok && g_stdoutErrno == 0)
        g_stdoutErrno = errno ? errno : EIO;
    return ok;
}
} // namespace

void out(const QString& text)
{
    const QByteArray bytes = text.toLocal8Bit();
    std::fwrite(bytes.constData(), 1, size_t(bytes.size()), stdout);
    std::fputc('\n', stdout);
    flushStdout();
}

void err(const QString& text)
{
    const QByteArray bytes = text.toLocal8Bit();
    std::fwrite(bytes.constData(), 1, size_t(bytes.size()), stderr);
    std::fputc('\n', stderr);
    std::fflush(stderr);
}

bool writeStdout(const QByteArray& bytes)
{
    if (!bytes.isEmpty())
        std::fwrite(bytes.constData(), 1, size_t(bytes.size()), stdout);
    return flushStdout();
}

int finish(int exitCode)
{
    static bool reported = false;
    if (flushStdout() && g_stdoutErrno == 0)
        return exitCode;
    if (!reported) {
        err(QCoreApplication::translate("Cli", "error: cannot write to standard output: %1")
                .arg(QString::fromLocal8Bit(std::strerror(g_stdoutErrno))));
        reported = true;
    }
    return ExitUsage;
}

namespace {
volatile std::sig_atomic_t g_stopRequested = 0;

void requestStop(int)
{
    g_stopRequested = 1;
    RegularFile::requestStop(); // a long read of a file stops too, wherever it is
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

void whenStopRequested(QObject* context, std::function<void()> onStop)
{
    catchStopSignals();
    auto* check = new QTimer(context);
    QObject::connect(check, &QTimer::timeout, context, [check, onStop = std::move(onStop)] {
        if (!stopRequested())
            return;
        check->stop();
        onStop();
    });
    check->start(100);
}

int runUntil(const std::function<std::optional<int>(qint64 elapsedMs)>& check,
             const std::function<void(qint64 elapsedMs)>& everySecond)
{
    QTimer timer;
    whenStopRequested(&timer, [] { QCoreApplication::exit(ExitOk); });
    QElapsedTimer clock;
    clock.start();
    qint64 lastSecond = 0;
    QObject::connect(&timer, &QTimer::timeout, [&] {
        const qint64 elapsed = clock.elapsed();
        if (const std::optional<int> status = check(elapsed)) {
            QCoreApplication::exit(*status);
            return;
        }
        if (everySecond && elapsed - lastSecond >= 1000) {
            lastSecond = elapsed;
            everySecond(elapsed);
        }
    });
    timer.start(50);
    return QCoreApplication::exec();
}

void hideCredentials(int argc, char** argv)
{
    for (int i = 1; i < argc; ++i) {
        char* arg = argv[i];
        const char* scheme = std::strstr(arg, "://");
        const char* at = std::strrchr(arg, '@');
        if (!scheme || !at || at <= scheme + 3)
            continue;
        // The copy is what every later reader of argv gets; it lives as long as the process.
        char* typed = ::strdup(arg);
        if (!typed)
            continue; // no memory: the argument stays readable to the command, and to ps
        std::memset(arg + (scheme + 3 - arg), '*', std::size_t(at - scheme - 3));
        argv[i] = typed;
    }
}

bool readSeconds(const QString& text, double* seconds)
{
    bool ok = false;
    const double v = text.toDouble(&ok);
    if (!ok || !(v >= 0 && v <= kMaxSeconds)) // NaN fails too
        return false;
    *seconds = v;
    return true;
}

QString secondsError()
{
    return QCoreApplication::translate("Cli", "--seconds takes 0 to %1 seconds (a year)")
        .arg(qint64(kMaxSeconds));
}

void keepFreedMemory()
{
    mallopt(M_MMAP_THRESHOLD, 32 * 1024 * 1024); // glibc's maximum on 64-bit
    mallopt(M_TRIM_THRESHOLD, 512 * 1024 * 1024);
}

QString closest(const QString& word, const QStringList& known)
{
    QString nearest;
    int best = 3; // at most two edits away
    for (const QString& k : known)
        if (const int d = editDistance(word.toLower(), k); d < best) {
            best = d;
            nearest = k;
        }
    return nearest;
}

QStringList optionNames(const QCommandLineParser& parser)
{
    // Qt's help lists each option as "  -o, --output <OUT>  text": the names before the text.
    static const QRegularExpression entry(QStringLiteral("^  (-[\\w-]+)(?:, (--[\\w-]+))?"),
                                          QRegularExpression::MultilineOption);
    QStringList names;
    for (auto it = entry.globalMatch(parser.helpText()); it.hasNext();) {
        const QRegularExpressionMatch m = it.next();
        for (int i = 1; i <= 2; ++i)
            if (m.hasCaptured(i))
                names << m.captured(i);
    }
    return names;
}

QString parseError(const QCommandLineParser& parser, const QString& command)
{
    QStringList lines;
    const QStringList known = optionNames(parser);
    for (const QString& name : parser.unknownOptionNames()) {
        const QString typed = (name.size() == 1 ? QStringLiteral("-") : QStringLiteral("--")) + name;
        QString line = QCoreApplication::translate("Cli", "%1: unknown option %2").arg(command, typed);
        if (const QString nearest = name.size() > 1 ? closest(typed, known) : QString(); !nearest.isEmpty())
            line += u'\n' + QCoreApplication::translate("Cli", "Did you mean %1?").arg(nearest);
        lines << line;
    }
    if (lines.isEmpty())
        lines << parser.errorText();
    lines << QCoreApplication::translate("Cli", "Run '%1 --help' for usage.").arg(command);
    return lines.join(u'\n');
}

int parseCommand(QCommandLineParser& parser, const QStringList& args, const QString& description)
{
    parser.setApplicationDescription(description);
    const QCommandLineOption help({QStringLiteral("h"), QStringLiteral("help")},
                                  QCoreApplication::translate("Cli", "Show this help."));
    parser.addOption(help);
    if (!parser.parse(args)) {
        err(parseError(parser, args.first()));
        return ExitUsage;
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
        return ExitOk;
    }
    return -1;
}

int parseCommand(QCommandLineParser& parser, QStringList arguments, const QString& command,
                 const QString& description)
{
    arguments.replace(0, command);
    return parseCommand(parser, arguments, description);
}

} // namespace CliOutput
