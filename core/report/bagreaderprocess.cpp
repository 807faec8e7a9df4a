// SPDX-License-Identifier: MIT
#include "bagreaderprocess.h"

#include "files/helperprogram.h"
#include "base/logging.h"
#include "wire/bagheader.h"

#include <QElapsedTimer>
#include <QFileInfo>
#include <QProcess>
#include <QTemporaryDir>

using namespace Qt::StringLiterals;

namespace {
/// The child is killed when it reports no progress for this long (a loop in the library).
constexpr int kStallMs = 120'000;
} // namespace

QString BagReaderProcess::program()
{
#ifdef BRIDGESCOPE_BAGREADER_BUILD_PATH
    return findHelperProgram(u"bridgescope-bagreader"_s, "BRIDGESCOPE_BAGREADER", QStringLiteral(BRIDGESCOPE_BAGREADER_BUILD_PATH));
#else
    return findHelperProgram(u"bridgescope-bagreader"_s, "BRIDGESCOPE_BAGREADER");
#endif
}

Result<RunData> BagReaderProcess::read(const QString& path, const Progress& progress)
{
    const auto bagError = [&](const QString& why) { return LocatedError {why, {}, path}; };
    if (const QString why = BagHeader::refusal(path); !why.isEmpty())
        return bagError(why);
    const QString helper = program();
    if (helper.isEmpty())
        return bagError(tr("cannot read bags: the helper program bridgescope-bagreader is not installed"));
    QTemporaryDir dir;
    if (!dir.isValid())
        return bagError(tr("no temporary folder: %1").arg(dir.errorString()));
    const QString out = dir.filePath(u"bag.bsrun"_s);

    QProcess child;
    child.setProcessChannelMode(QProcess::SeparateChannels);
#if defined(__SANITIZE_ADDRESS__)
    // Under ASan (scripts/sanitize.sh) the helper has no address-space limit, and ASan would turn
    // rosbag's crashes into reports with exit code 1: let them crash as in a normal build, and
    // let a runaway allocation fail as it does there.
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(u"ASAN_OPTIONS"_s, env.value(u"ASAN_OPTIONS"_s) + u":handle_segv=0:handle_sigbus=0:allocator_may_return_null=1"_s);
    child.setProcessEnvironment(env);
#endif
    qCDebug(lcReport).noquote() << "starting" << helper << "for" << path;
    child.start(helper, {QFileInfo(path).absoluteFilePath(), out});
    if (!child.waitForStarted(10000))
        return bagError(tr("cannot start %1: %2").arg(helper, child.errorString()));
    QByteArray pending;
    QElapsedTimer sinceProgress;
    sinceProgress.start();
    bool cancelled = false;
    bool stalled = false;
    int percent = 0;
    while (child.state() != QProcess::NotRunning) {
        child.waitForReadyRead(100);
        pending += child.readAllStandardOutput();
        qsizetype nl;
        while ((nl = pending.indexOf('\n')) >= 0) {
            const QByteArray line = pending.left(nl);
            pending.remove(0, nl + 1);
            bool ok = false;
            const int said = line.startsWith("progress ") ? line.mid(9).toInt(&ok) : -1;
            if (!ok)
                continue;
            sinceProgress.restart();
            percent = qBound(0, said, 99);
        }
        // Asked every tick, not only on progress: a cancel must not wait for the next 10,000 messages.
        if (progress && !progress(percent))
            cancelled = true;
        if (sinceProgress.elapsed() > kStallMs)
            stalled = true;
        if (cancelled || stalled) {
            child.kill();
            child.waitForFinished(5000);
            break;
        }
        if (pending.size() > 4096)
            pending.clear(); // not ours to keep: the child only prints short lines
    }
    if (cancelled)
        return bagError(tr("cancelled"));
    if (stalled)
        return bagError(
            tr("the bag reader made no progress for %1 s; the bag may be damaged").arg(kStallMs / 1000));
    const QString said = QString::fromUtf8(child.readAllStandardError().left(4096)).trimmed();
    qCDebug(lcReport) << "the bag reader ended:" << (child.exitStatus() == QProcess::CrashExit ? "crashed" : "exit")
                      << child.exitCode();
    if (child.exitStatus() == QProcess::CrashExit)
        return bagError(tr("the bag is damaged: rosbag's library crashed reading it%1")
                            .arg(said.isEmpty() ? QString() : u" ("_s + said + u')'));
    if (child.exitCode() != 0) {
        if (said.startsWith(path) || said.startsWith(QFileInfo(path).absoluteFilePath()))
            return LocatedError {said}; // rosbagimport names the file itself
        return bagError(said.isEmpty() ? tr("the bag reader failed (exit %1)").arg(child.exitCode()) : said);
    }
    Result<RunData> run = RunFile::read(out);
    if (!run)
        return bagError(tr("the bag reader's result does not read: %1").arg(run.error().toString()));
    if (progress)
        progress(100);
    return run;
}
