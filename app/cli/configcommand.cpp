// SPDX-License-Identifier: MIT
#include "configcommand.h"

#include "app/cli/clioutput.h"
#include "config/configreader.h"
#include "config/configvalidator.h"
#include "config/configwriter.h"
#include "config/mqttclientrelease.h"
#include "config/peerconfig.h"
#include "files/atomicfile.h"
#include "files/regularfile.h"
#include "yaml/yamllimits.h"

#include <limits>
#include <QCommandLineParser>
#include <QCoreApplication>
#include <QFile>

using namespace Qt::StringLiterals;
using CliOutput::err;
using CliOutput::ExitFailed;
using CliOutput::ExitOk;
using CliOutput::ExitUsage;
using CliOutput::out;

namespace {

class ConfigCommand
{
    Q_DECLARE_TR_FUNCTIONS(ConfigCommand)
public:
    static QString usage()
    {
        return tr(
            "Usage: bridgescope config <command> [options]\n"
            "\n"
            "Commands:\n"
            "  validate FILE... [--target RELEASE]      check bridge configs (against an mqtt_client "
            "release); "
            "exit 0 valid, 1 invalid, 2 unreadable\n"
            "  convert FILE --to ros1|ros2|mqtt_bridge  write the config in another layout (a valid one, "
            "or --force)\n"
            "  peer FILE [--client-id ID]               write the config for the other end of the link (a "
            "valid one, or --force)\n"
            "\n"
            "Run 'bridgescope config <command> --help' for the options of a command.");
    }

    // Parses a sub-command's options; returns -1 to go on, or the exit code.
    static int parse(QCommandLineParser& parser, const QStringList& args, const QString& description)
    {
        return CliOutput::parseCommand(parser, args, description);
    }

    struct Loaded
    {
        ConfigReadResult read;
        int exit = ExitOk;
    };

    static Loaded load(const QString& path)
    {
        Loaded l;
        // One byte past the limit is enough for the reader to say the file is too large; a FIFO or
        // a device such as /dev/zero is refused.
        const Result<RegularFile::Opened> opened
            = RegularFile::open(path, std::numeric_limits<qint64>::max());
        if (!opened) {
            err(tr("%1: error: cannot read the file: %2").arg(path, opened.error().toString()));
            l.exit = ExitUsage;
            return l;
        }
        if (opened->size > YamlLimits::maxBytes) { // said by its size ("17 MB, the limit is 8 MB"), unread
            err(ConfigReader::tooLarge(opened->size).format(path));
            l.exit = ExitFailed;
            return l;
        }
        l.read = ConfigReader::read(opened->file->read(opened->size));
        if (!l.read.parsed) {
            for (const Problem& p : std::as_const(l.read.problems))
                err(p.format(path));
            l.exit = ExitFailed;
        }
        return l;
    }

    static int writeOutput(const QString& outPath, const QString& text)
    {
        if (outPath.isEmpty() || outPath == u"-"_s)
            return CliOutput::finish(CliOutput::writeStdout(text.toUtf8()) ? ExitOk : ExitUsage);
        if (const Status written = AtomicFile::write(outPath, text.toUtf8()); !written) {
            err(tr("%1: error: %2").arg(outPath, written.error().toString()));
            return ExitUsage;
        }
        return ExitOk;
    }

    static QCommandLineOption forceOption()
    {
        return QCommandLineOption(u"force"_s,
                                  tr("Write even an invalid config; what cannot be written is named on "
                                     "standard error."));
    }

    // An invalid config is not written (its content would not survive, see "broker: [1, 2]")
    // unless forced; either way its errors are printed.
    static bool acceptable(const QString& path, const ConfigReadResult& read, bool force)
    {
        QList<Problem> problems = read.problems + ConfigValidator::validate(read.config);
        if (!hasErrors(problems))
            return true;
        std::stable_sort(problems.begin(), problems.end(), [](const Problem& a, const Problem& b) {
            return a.pos.line != b.pos.line ? a.pos.line < b.pos.line : a.pos.column < b.pos.column;
        });
        for (const Problem& p : std::as_const(problems)) {
            if (p.severity == Severity::Error)
                err(p.format(path));
        }
        for (const Problem& p : read.dropped)
            err(p.format(path));
        if (!force) {
            err(tr("%1: error: the config is invalid; nothing was written (--force writes it anyway)")
                    .arg(path));
            return false;
        }
        return true;
    }

    static void printNotes(const QString& path, const QStringList& notes, const QStringList& dropped)
    {
        for (const QString& n : notes)
            err(tr("%1: note: %2").arg(path, n));
        for (const QString& d : dropped)
            err(tr("%1: warning: %2").arg(path, d));
    }

    static int validate(const QStringList& args)
    {
        QCommandLineParser parser;
        const QCommandLineOption quiet({u"q"_s, u"quiet"_s}, tr("Print errors only, no warnings."));
        const QCommandLineOption target(
            u"target"_s,
            tr("Check against this mqtt_client release: %1, or auto (the newest release that loads the "
               "file's layout, the default). Says which on a note line.")
                .arg(MqttClientReleases::names().join(u", "_s)),
            u"RELEASE"_s);
        parser.addOptions({quiet, target});
        parser.addPositionalArgument(u"FILE"_s, tr("Bridge configs (mqtt_client ROS 1/ROS 2, mqtt_bridge)."),
                                     u"FILE..."_s);
        if (const int r
            = parse(parser, args,
                    tr("Checks bridge configs. Prints FILE:LINE:COL: severity: message (fix) for each "
                       "problem. Exit status: 0 all valid (warnings allowed), 1 some invalid, 2 some "
                       "unreadable."));
            r >= 0)
            return r;
        const QStringList files = parser.positionalArguments();
        if (files.isEmpty()) {
            err(tr("bridgescope config validate: no FILE given"));
            return ExitUsage;
        }
        ConfigValidator::Options options;
        if (parser.isSet(target) && parser.value(target) != u"auto"_s) {
            options.target = MqttClientReleases::fromName(parser.value(target));
            if (!options.target) {
                err(tr("bridgescope config validate: --target '%1' is not a release of mqtt_client; use one "
                       "of "
                       "%2, or auto")
                        .arg(parser.value(target), MqttClientReleases::names().join(u", "_s)));
                return ExitUsage;
            }
        }
        int worst = ExitOk;
        for (const QString& path : files) {
            Loaded l = load(path);
            if (l.exit != ExitOk) {
                worst = std::max(worst, l.exit);
                continue;
            }
            QList<Problem> problems = l.read.problems + ConfigValidator::validate(l.read.config, options);
            std::stable_sort(problems.begin(), problems.end(), [](const Problem& a, const Problem& b) {
                return a.pos.line != b.pos.line ? a.pos.line < b.pos.line : a.pos.column < b.pos.column;
            });
            if (parser.isSet(target) && !parser.isSet(quiet))
                out(tr("%1: note: %2").arg(path, MqttClientReleases::summary(l.read.config, options.target)));
            for (const Problem& p : std::as_const(problems)) {
                if (p.severity == Severity::Error || !parser.isSet(quiet))
                    out(p.format(path));
            }
            if (hasErrors(problems))
                worst = std::max(worst, int(ExitFailed));
        }
        return worst;
    }

    static int convert(const QStringList& args)
    {
        QCommandLineParser parser;
        const QCommandLineOption to(u"to"_s, tr("Layout to write: ros1, ros2 or mqtt_bridge."), u"LAYOUT"_s);
        const QCommandLineOption output({u"o"_s, u"output"_s}, tr("Write to OUT instead of standard output."),
                                        u"OUT"_s);
        const QCommandLineOption node(u"node"_s,
                                      tr("ROS 2 node name above ros__parameters (default: as read, "
                                         "or mqtt_client)."),
                                      u"NAME"_s);
        const QCommandLineOption force = forceOption();
        parser.addOptions({to, output, node, force});
        parser.addPositionalArgument(u"FILE"_s, tr("The bridge config to convert."));
        if (const int r = parse(parser, args,
                                tr("Writes a bridge config in another layout; unknown keys, "
                                   "substitutions and values behind aliases are kept. An invalid config "
                                   "is refused (exit 1, its errors printed) unless --force."));
            r >= 0)
            return r;
        ConfigLayout layout;
        if (parser.positionalArguments().size() != 1 || !parser.isSet(to)
            || !layoutFromName(parser.value(to), &layout)) {
            err(tr("Usage: bridgescope config convert FILE --to ros1|ros2|mqtt_bridge [-o OUT] [--force]"));
            return ExitUsage;
        }
        const QString path = parser.positionalArguments().first();
        Loaded l = load(path);
        if (l.exit != ExitOk)
            return l.exit;
        if (!acceptable(path, l.read, parser.isSet(force)))
            return ExitFailed;
        BridgeConfig cfg = l.read.config;
        if (parser.isSet(node))
            cfg.ros2NodeName = parser.value(node);
        QStringList notes, dropped;
        const QString text = ConfigWriter::write(cfg, layout, &notes, &dropped);
        printNotes(path, notes, dropped);
        const QString target = parser.value(output);
        printLayoutWarnings(target.isEmpty() ? tr("<stdout>") : target, text);
        return writeOutput(target, text);
    }

    /// What the written layout does not understand, as `config validate` would say it of the written
    /// file: a ROS 2-only key in a ROS 1 file, a roslaunch substitution in a ROS 2 file. One line per
    /// key on stderr, with its line in the written text and its path.
    static void printLayoutWarnings(const QString& target, const QString& text)
    {
        const ConfigReadResult written = ConfigReader::read(text.toUtf8());
        if (!written.parsed)
            return;
        for (const Problem& p : ConfigValidator::validate(written.config))
            if (p.code == u"ros2-only-option"_s || p.code == u"substitution-in-ros2"_s)
                err(p.format(target));
    }

    static int peer(const QStringList& args)
    {
        QCommandLineParser parser;
        const QCommandLineOption output({u"o"_s, u"output"_s}, tr("Write to OUT instead of standard output."),
                                        u"OUT"_s);
        const QCommandLineOption clientId(u"client-id"_s,
                                          tr("Client id of the peer (default: the id with "
                                             "\"_peer\" appended)."),
                                          u"ID"_s);
        const QCommandLineOption to(u"to"_s, tr("Layout to write (default: the input's)."), u"LAYOUT"_s);
        const QCommandLineOption force = forceOption();
        parser.addOptions({output, clientId, to, force});
        parser.addPositionalArgument(u"FILE"_s, tr("This host's bridge config."));
        if (const int r = parse(parser, args,
                                tr("Writes the config for the other end of the link: every ros2mqtt "
                                   "becomes an mqtt2ros and the reverse. An invalid config is refused "
                                   "(exit 1, its errors printed) unless --force."));
            r >= 0)
            return r;
        if (parser.positionalArguments().size() != 1) {
            err(tr("Usage: bridgescope config peer FILE [-o OUT] [--client-id ID] [--force]"));
            return ExitUsage;
        }
        const QString path = parser.positionalArguments().first();
        Loaded l = load(path);
        if (l.exit != ExitOk)
            return l.exit;
        if (!acceptable(path, l.read, parser.isSet(force)))
            return ExitFailed;
        ConfigLayout layout = l.read.config.layout;
        if (parser.isSet(to) && !layoutFromName(parser.value(to), &layout)) {
            err(tr("--to takes ros1, ros2 or mqtt_bridge"));
            return ExitUsage;
        }
        const PeerConfig::Result peerResult = PeerConfig::make(l.read.config, parser.value(clientId));
        QStringList notes = peerResult.notes, dropped;
        const QString text = ConfigWriter::write(peerResult.config, layout, &notes, &dropped);
        printNotes(path, notes, dropped);
        return writeOutput(parser.value(output), text);
    }
};

} // namespace

int runConfigCommand(const QStringList& arguments)
{
    // arguments: "config", <command>, ...
    if (arguments.size() < 2 || arguments[1] == u"--help"_s || arguments[1] == u"-h"_s) {
        out(ConfigCommand::usage());
        return arguments.size() < 2 ? ExitUsage : ExitOk;
    }
    const QString& command = arguments[1];
    QStringList rest = arguments.mid(2);
    rest.prepend(u"bridgescope config "_s + command);
    // Every command prints its result to stdout: a full disk there is an error too.
    if (command == u"validate"_s)
        return CliOutput::finish(ConfigCommand::validate(rest));
    if (command == u"convert"_s)
        return CliOutput::finish(ConfigCommand::convert(rest));
    if (command == u"peer"_s)
        return CliOutput::finish(ConfigCommand::peer(rest));
    err(ConfigCommand::tr("bridgescope config: unknown command '%1'").arg(command));
    if (const QString nearest = CliOutput::closest(command, {u"validate"_s, u"convert"_s, u"peer"_s});
        !nearest.isEmpty()) {
        err(ConfigCommand::tr("Did you mean 'bridgescope config %1'?").arg(nearest));
        err(ConfigCommand::tr("Run 'bridgescope config --help' for the commands."));
    } else {
        err(ConfigCommand::usage());
    }
    return ExitUsage;
}
