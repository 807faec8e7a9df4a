// SPDX-License-Identifier: MIT
#include "app/cli/bridgecommand.h"
#include "app/cli/clockcommand.h"
#include "app/cli/clioutput.h"
#include "app/cli/configcommand.h"
#include "app/cli/democommand.h"
#include "app/cli/discovercommand.h"
#include "app/cli/experimentcommand.h"
#include "app/cli/probecommand.h"
#include "app/cli/recordcommand.h"
#include "app/cli/reportcommand.h"
#include "app/cli/rulescommand.h"
#include "app/cli/watchcommand.h"
#include "app/gui/guimain.h"
#include "base/logging.h"

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <QCoreApplication>
#include <QFileInfo>
#include <QGuiApplication>

using namespace Qt::StringLiterals;
using CliOutput::ExitOk;

namespace {
void setIdentity()
{
    QCoreApplication::setOrganizationName(u"Bridgescope"_s);
    QCoreApplication::setApplicationName(u"bridgescope"_s);
    QCoreApplication::setApplicationVersion(QStringLiteral(BRIDGESCOPE_VERSION));
}
/// Whether the command line asks for a PDF (--format pdf or --format=pdf).
bool wantsPdf(int argc, char** argv)
{
    for (int i = 1; i < argc; ++i) {
        const QByteArray a(argv[i]);
        if (a == "--format=pdf" || (a == "--format" && i + 1 < argc && QByteArray(argv[i + 1]) == "pdf"))
            return true;
    }
    return false;
}

class Main
{
    Q_DECLARE_TR_FUNCTIONS(Main)
};

QtMessageHandler g_qtHandler = nullptr;

/// Passes every message on but Qt's "XDG_RUNTIME_DIR not set": a Qt GUI application looks for a
/// Wayland socket there while it picks its platform (also offscreen, as the PDF report runs), and
/// without the variable (sudo, cron, containers) it warns on every run and uses /tmp/runtime-USER,
/// which is all it needs.
void withoutRuntimeDirWarning(QtMsgType type, const QMessageLogContext& context, const QString& message)
{
    if (type == QtWarningMsg && message.startsWith(QLatin1String("QStandardPaths: XDG_RUNTIME_DIR not set")))
        return;
    if (g_qtHandler)
        g_qtHandler(type, context, message);
    else
        std::fprintf(stderr, "%s\n", qPrintable(qFormatLogMessage(type, context, message)));
}

/// Whether Qt is told which platform to use on the command line (-platform X, --platform=X).
bool platformGiven(int argc, char** argv)
{
    for (int i = 1; i < argc; ++i) {
        const QByteArray a(argv[i]);
        if (a == "-platform" || a == "--platform" || a.startsWith("-platform=")
            || a.startsWith("--platform="))
            return true;
    }
    return false;
}

/// Why the window cannot open here (no display for the platform Qt would pick), or empty. Qt
/// aborts (SIGABRT) when its platform plugin finds no display; this says so first, and how.
QString whyNoDisplay(int argc, char** argv)
{
    if (platformGiven(argc, argv))
        return {};
    const QByteArray platform = qgetenv("QT_QPA_PLATFORM");
    const bool x11 = !qgetenv("DISPLAY").isEmpty();
    const bool wayland = !qgetenv("WAYLAND_DISPLAY").isEmpty();
    bool found = true; // offscreen, minimal, vnc, eglfs, linuxfb: no display to find
    if (platform.startsWith("wayland"))
        found = wayland;
    else if (platform.isEmpty() || platform.startsWith("xcb"))
        found = x11 || wayland;
    if (found)
        return {};
    return Main::tr("bridgescope: the window needs a display, and there is none here (DISPLAY and "
                    "WAYLAND_DISPLAY are not set).\n"
                    "  On a desktop machine over SSH: ssh -X, or run it on a virtual display: "
                    "xvfb-run -a bridgescope ...\n"
                    "  Without a window: bridgescope --platform offscreen --screenshot out.png, or one "
                    "of the commands (bridgescope --help).");
}

/// A first argument that is neither an option, a command nor a file or folder: what is wrong with it.
QString unknownArgument(const QString& first, const QStringList& commands)
{
    if (first.isEmpty() || first.startsWith(u'-') || QFileInfo::exists(first))
        return {};
    // A path (it has a folder or a suffix) that is not there; otherwise a word: a command mistyped.
    if (first.contains(u'/') || first.contains(u'.'))
        return Main::tr("bridgescope: %1 does not exist").arg(first);
    QString message = Main::tr("bridgescope: '%1' is not a command. The commands: %2.")
                          .arg(first, commands.join(u", "_s));
    if (const QString closest = CliOutput::closest(first, commands); !closest.isEmpty())
        message += u'\n' + Main::tr("Did you mean '%1'?").arg(closest);
    return message + u'\n' + Main::tr("Run 'bridgescope --help' for the options and what each command does.");
}
} // namespace

int main(int argc, char** argv)
{
    CliOutput::hideCredentials(argc, argv); // a URL's password: not for ps, whatever runs
    // Time zone read once, before any thread: log lines from roscpp and Paho threads format local
    // times, and glibc's first tzset() on two threads at once races (seen by TSan).
    ::tzset();
    g_qtHandler = qInstallMessageHandler(withoutRuntimeDirWarning);
    setIdentity();
    // --verbose anywhere (before a lone --) turns on the debug messages of every layer.
    if (Logging::takeVerboseFlag(&argc, argv))
        Logging::enableVerbose();
    const QString first = argc > 1 ? QString::fromLocal8Bit(argv[1]) : QString();
    const bool help = first == u"-h"_s || first == u"--help"_s;
    const bool version = first == u"-v"_s || first == u"--version"_s;
    // The commands people type; `demo-node` (the demo lab's own child processes) is not one of
    // them: it runs, but no list, help or suggestion names it.
    static const QStringList commands
        = {u"bridge"_s, u"clock"_s,  u"config"_s, u"demo"_s,  u"discover"_s, u"experiment"_s,
           u"probe"_s,  u"record"_s, u"report"_s, u"rules"_s, u"watch"_s};
    const bool internal = first == u"demo-node"_s;
    if (first == u"report"_s && wantsPdf(argc, argv)) {
        // PDF reports lay text out with Qt GUI; no window ever opens, so no display is needed.
        if (!qEnvironmentVariableIsSet("QT_QPA_PLATFORM"))
            qputenv("QT_QPA_PLATFORM", "offscreen");
        QGuiApplication app(argc, argv);
        installTranslations(app);
        return runReportCommand(app.arguments().mid(1));
    }
    if (commands.contains(first) || internal || help || version) {
        // Commands need no display.
        QCoreApplication app(argc, argv);
        installTranslations(app);
        const QStringList args = app.arguments().mid(1);
        if (help) {
            CliOutput::out(bridgescopeUsage());
            return ExitOk;
        }
        if (version) {
            CliOutput::out(u"bridgescope "_s + QCoreApplication::applicationVersion());
            return ExitOk;
        }
        if (first == u"discover"_s)
            return CliOutput::finish(runDiscoverCommand(args));
        if (first == u"probe"_s)
            return CliOutput::finish(runProbeCommand(args));
        if (first == u"record"_s)
            return CliOutput::finish(runRecordCommand(args));
        if (first == u"bridge"_s)
            return CliOutput::finish(runBridgeCommand(args));
        if (first == u"demo"_s)
            return CliOutput::finish(runDemoCommand(args));
        if (first == u"demo-node"_s)
            return runDemoNodeCommand(args);
        if (first == u"report"_s)
            return CliOutput::finish(runReportCommand(args));
        if (first == u"watch"_s)
            return CliOutput::finish(runWatchCommand(args));
        if (first == u"experiment"_s)
            return CliOutput::finish(runExperimentCommand(args));
        if (first == u"clock"_s)
            return CliOutput::finish(runClockCommand(args));
        if (first == u"rules"_s)
            return CliOutput::finish(runRulesCommand(args));
        return runConfigCommand(args);
    }
    // A typo is not a file for the window to open, and a window without a display is not an abort;
    // an option the window does not know is refused before the display is looked for.
    const QString refusal = unknownArgument(first, commands);
    const QString noDisplay = refusal.isEmpty() ? whyNoDisplay(argc, argv) : QString();
    if (!refusal.isEmpty() || !noDisplay.isEmpty()) {
        QCoreApplication app(argc, argv);
        installTranslations(app);
        if (!refusal.isEmpty()) {
            CliOutput::err(refusal);
            return CliOutput::ExitUsage;
        }
        if (const int status = checkGuiArguments(app.arguments()); status >= 0)
            return status;
        CliOutput::err(noDisplay);
        return CliOutput::ExitFailed;
    }
    return runGui(argc, argv);
}
