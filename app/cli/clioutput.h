// SPDX-License-Identifier: MIT
#pragma once

#include <functional>
#include <optional>
#include <QString>
#include <QStringList>

class QCommandLineParser;
class QObject;

/// Plain text to the terminal, without going through the Qt message handler, and what every
/// command shares: exit codes, option parsing, Ctrl+C.
namespace CliOutput {
/// The exit status of every command (the user guide's contract).
enum Exit : int {
    ExitOk = 0, ///< done
    ExitFailed = 1, ///< ran, but failed: an invalid config, nothing came back, a write that failed
    ExitUsage = 2, ///< bad arguments or an input that cannot be read or written: nothing done
    ExitCancelled = 130, ///< stopped by Ctrl+C or SIGTERM before the result was complete
};

void out(const QString& text); ///< a line to stdout
void err(const QString& text); ///< a line to stderr
/// Writes bytes to stdout as they are (a file printed with `-o -`); false when the stream failed.
bool writeStdout(const QByteArray& bytes);
/// Flushes stdout and says whether everything written to it arrived (a full disk, a closed pipe
/// or /dev/full fail). On failure prints why to stderr and returns ExitUsage, otherwise `exitCode`:
/// `return CliOutput::finish(code);` at the end of a command that prints its result.
int finish(int exitCode);
/// Adds -h/--help and the description, parses `args` (args[0] names the command). Returns -1 to
/// go on, ExitOk after printing the help, ExitUsage after printing the error.
int parseCommand(QCommandLineParser& parser, const QStringList& args, const QString& description);
/// parseCommand() of a command's `arguments` (as main passes them on), args[0] taken as `command`
/// ("bridgescope rules"): the name its help and its errors give.
int parseCommand(QCommandLineParser& parser, QStringList arguments, const QString& command,
                 const QString& description);
/// The word of `known` nearest to `word`, at most two edits away, or empty: "did you mean".
QString closest(const QString& word, const QStringList& known);
/// The options `parser` knows, as typed ("--output", "-o"), read from its help text.
QStringList optionNames(const QCommandLineParser& parser);
/// Why `parser` refused the command line of `command` ("bridgescope config validate"): each unknown
/// option named with the known one nearest to it, else the parser's own error; then where help is.
QString parseError(const QCommandLineParser& parser, const QString& command);
/// From now on SIGINT and SIGTERM only set stopRequested(), so that a long command can finish or
/// remove its file instead of dying halfway.
void catchStopSignals();
bool stopRequested();
/// catchStopSignals(), then calls `onStop` once, on `context`'s thread, soon after a stop was
/// requested (checked every 100 ms by a timer that `context` owns). The one way a command that runs
/// an event loop learns about Ctrl+C.
void whenStopRequested(QObject* context, std::function<void()> onStop);
/// Runs the event loop of a command that runs until it is done or stopped: every 50 ms `check`
/// is asked with the milliseconds since the start and ends the loop with the status it returns;
/// `everySecond` (optional) prints progress once a second; Ctrl+C ends it with ExitOk. Returns the
/// status the loop ended with (also from a QCoreApplication::exit() elsewhere).
int runUntil(const std::function<std::optional<int>(qint64 elapsedMs)>& check,
             const std::function<void(qint64 elapsedMs)>& everySecond = {});
/// Hides the credentials of every URL on the command line from ps, for every entry point (the
/// window, the demo, every command) and every form (`--broker URL`, `--broker=URL`, any bytes in
/// the password, percent-encoded or not): in each argument that holds "://" and a later '@',
/// everything between the first "://" and the last '@' is overwritten with '*' in the bytes the
/// kernel shows as this process's command line (/proc/PID/cmdline: `tcp://********@host`), after
/// `argv[i]` was pointed at a copy of the argument as typed, which Qt and the commands read. Call
/// first thing in main(): a typed password is then visible only from exec until this call.
void hideCredentials(int argc, char** argv);
/// The longest duration an option takes: a year. Longer ones are mistakes, and far longer ones
/// (1e300) have no milliseconds that fit a qint64.
inline constexpr double kMaxSeconds = 365.0 * 24 * 3600;
/// A duration option's value: a number of seconds from 0 to kMaxSeconds; false when `text` is not one.
bool readSeconds(const QString& text, double* seconds);
/// What to say when readSeconds() refused a --seconds value.
QString secondsError();
/// For processes that forward big messages at a high rate (bridge, demo nodes): keep freed memory
/// in the process. glibc otherwise maps each buffer over 128 KB afresh and returns it on free, and
/// the page faults of touching it again cost more than copying the message (measured with perf).
void keepFreedMemory();
} // namespace CliOutput
