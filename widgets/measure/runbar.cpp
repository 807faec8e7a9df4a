// SPDX-License-Identifier: MIT
#include "runbar.h"

#include "record/runrecorder.h"
#include "report/runloader.h"
#include "yaml/secrets.h"
#include "session/measuresession.h"
#include "session/waitingtext.h"
#include "widgets/measure/recorddialog.h"

#include <QApplication>
#include <QDateTime>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QMessageBox>
#include <QProgressDialog>
#include <QPushButton>
#include <QTimer>

using namespace Qt::StringLiterals;

RunBar::RunBar(MeasureSession* measure, QWidget* parent)
    : QWidget(parent)
    , m_measure(measure)
    , m_record(new QPushButton(tr("● Re&cord…"), this))
    , m_open(new QPushButton(tr("Open R&un…"), this))
    , m_save(new QPushButton(tr("Save Ru&n As…"), this))
    , m_live(new QPushButton(tr("&Back to Live"), this))
    , m_status(new QLabel(this))
    , m_waitTimer(new QTimer(this))
{
    m_record->setToolTip(
        tr("Record every stamp from now on into a run file, to open, compare and report later"));
    m_open->setToolTip(tr("Show a recorded run as it was, or import the suite's timestamp CSV or a ROS bag"));
    m_save->setToolTip(tr("Save the run on screen (an imported CSV or bag) as a Bridgescope run"));
    m_record->setObjectName(u"recordButton"_s);
    m_open->setObjectName(u"openButton"_s);
    m_live->setObjectName(u"liveButton"_s);
    m_status->setObjectName(u"runStatus"_s);
    m_status->setWordWrap(true); // what a silent recording waits for is long: it wraps, not widens
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_record);
    layout->addWidget(m_open);
    layout->addWidget(m_save);
    layout->addWidget(m_live);
    layout->addWidget(m_status, 1);
    connect(m_record, &QPushButton::clicked, this, &RunBar::toggleRecording);
    connect(m_open, &QPushButton::clicked, this, &RunBar::chooseRun);
    connect(m_save, &QPushButton::clicked, this, &RunBar::chooseSaveRun);
    connect(m_live, &QPushButton::clicked, this, &RunBar::backToLive);
    connect(measure, &MeasureSession::recordingChanged, this, &RunBar::updateState);
    connect(measure, &MeasureSession::showingRunChanged, this, &RunBar::updateState);
    connect(measure->recorder(), &RunRecorder::committed, this, &RunBar::updateState);
    m_waitTimer->setInterval(1000);
    connect(m_waitTimer, &QTimer::timeout, this, &RunBar::updateState);
    connect(measure, &MeasureSession::recordingFailed, this, [this](const QString& why) {
        QMessageBox::warning(
            this, tr("Recording Stopped"),
            tr("The run file could not be written: %1\nWhat was committed before is kept.").arg(why));
    });
    updateState();
}

Result<void> RunBar::startRecording(const QString& path, const QString& name, const QString& notes)
{
    RunInfo info;
    info.name = name.isEmpty() ? QFileInfo(path).completeBaseName() : name;
    info.notes = notes;
    if (m_config) {
        const auto [configPath, text] = m_config();
        info.bridgeConfigPath = configPath;
        info.bridgeConfig = text;
    }
    if (Result<void> started = m_measure->startRecording(path, info); !started)
        return started;
    m_recordingName = info.name;
    m_recordingSince = QDateTime::currentDateTime();
    updateState();
    return {};
}

Result<void> RunBar::stopRecording()
{
    const QString path = m_measure->recorder()->path();
    if (Result<void> stopped = m_measure->stopRecording(); !stopped)
        return stopped;
    updateState();
    emit runRecorded(path);
    return {};
}

void RunBar::toggleRecording()
{
    if (m_measure->isRecording()) {
        if (const Result<void> stopped = stopRecording(); !stopped && !stopped.error().toString().isEmpty())
            QMessageBox::warning(this, tr("Stop Recording"), stopped.error().toString());
        return;
    }
    RecordDialog dialog(this);
    if (dialog.exec() != QDialog::Accepted)
        return;
    if (const Result<void> started = startRecording(dialog.path(), dialog.name(), dialog.notes()); !started)
        QMessageBox::warning(this, tr("Record a Run"), started.error().toString());
}

Status RunBar::openRun(const QString& path)
{
    // Large runs take a moment: show progress (after half a second) and allow cancelling.
    QProgressDialog progress(tr("Reading %1…").arg(QFileInfo(path).fileName()), tr("Cancel"), 0, 100, this);
    progress.setWindowModality(Qt::WindowModal);
    progress.setMinimumDuration(500);
    const Progress report = [&progress](int percent) {
        progress.setValue(percent);
        QApplication::processEvents(QEventLoop::ExcludeUserInputEvents);
        return !progress.wasCanceled();
    };
    QStringList warnings;
    RunLoader::Options options;
    options.skipBadRows = true; // an interactive import shows what was skipped instead of refusing
    Result<RunData> run = RunLoader::load(path, options, &warnings, report);
    const bool cancelled = progress.wasCanceled();
    progress.reset();
    if (!run)
        return cancelled ? LocatedError {} : run.error();
    if (Status shown = m_measure->showRun(*run); !shown)
        return shown;
    m_shown = std::move(run).value();
    m_shownPath = path;
    if (!warnings.isEmpty())
        QMessageBox::information(this, tr("Open Run"),
                                 tr("%1 rows could not be read and were skipped:\n%2")
                                     .arg(warnings.size())
                                     .arg(warnings.mid(0, 10).join(u'\n')));
    updateState();
    return {};
}

Result<void> RunBar::saveRunAs(const QString& path)
{
    if (!m_shown)
        return LocatedError {tr("no run on screen")};
    QProgressDialog progress(tr("Writing %1…").arg(QFileInfo(path).fileName()), tr("Cancel"), 0, 100, this);
    progress.setWindowModality(Qt::WindowModal);
    progress.setMinimumDuration(500);
    return RunFile::write(path, *m_shown, [&progress](int percent) {
        progress.setValue(percent);
        QApplication::processEvents(QEventLoop::ExcludeUserInputEvents);
        return !progress.wasCanceled();
    });
}

void RunBar::backToLive()
{
    m_measure->showLive();
    m_shown.reset();
    m_shownPath.clear();
    updateState();
}

void RunBar::chooseRun()
{
    const QString path = QFileDialog::getOpenFileName(
        this, tr("Open Run"), QFileInfo(m_shownPath).path(),
        tr("Runs, suite CSV and bags (*.%1 *.csv *.bag);;All files (*)").arg(RunFile::suffix()));
    if (path.isEmpty())
        return;
    const Status opened = openRun(path);
    if (const QString error = opened.error().toString(); !error.isEmpty()) // empty: the user cancelled
        QMessageBox::warning(this, tr("Open Run"), error);
}

void RunBar::chooseSaveRun()
{
    QString suggestion = m_shownPath;
    suggestion = QFileInfo(suggestion).path() + u'/' + QFileInfo(suggestion).completeBaseName() + u'.'
        + RunFile::suffix();
    const QString path = QFileDialog::getSaveFileName(this, tr("Save Run As"), suggestion,
                                                      tr("Bridgescope runs (*.%1)").arg(RunFile::suffix()));
    if (path.isEmpty())
        return;
    if (const Result<void> saved = saveRunAs(path); !saved)
        QMessageBox::warning(this, tr("Save Run As"), saved.error().toString());
}

QString RunBar::waitingText() const
{
    const QDateTime now = QDateTime::currentDateTime();
    if (m_measure->recorder()->committedStamps() > 0 || !m_recordingSince.isValid()
        || m_recordingSince.msecsTo(now) < WaitingText::kGraceMs)
        return {};
    WaitingText waiting;
    waiting.what = tr("stamp");
    waiting.topics = m_measure->pipeline().topics();
    waiting.broker = Secrets::urlWithoutCredentials(m_measure->brokerUrl());
    waiting.master = Secrets::urlWithoutCredentials(m_measure->rosMasterUri());
    waiting.since = m_recordingSince;
    return waiting.text(now);
}

void RunBar::updateState()
{
    const bool recording = m_measure->isRecording();
    const bool showing = m_measure->isShowingRun();
    m_record->setText(recording ? tr("■ Stop Re&cording") : tr("● Re&cord…"));
    m_record->setEnabled(!showing);
    m_open->setEnabled(!recording);
    m_save->setVisible(showing);
    m_live->setVisible(showing);
    if (recording != m_waitTimer->isActive())
        recording ? m_waitTimer->start() : m_waitTimer->stop();
    m_status->setToolTip(QString());
    if (recording) {
        QString text = tr("<b>Recording</b> %1: %2 stamps committed to %3")
                           .arg(m_recordingName.toHtmlEscaped())
                           .arg(m_measure->recorder()->committedStamps())
                           .arg(QFileInfo(m_measure->recorder()->path()).fileName().toHtmlEscaped());
        const QString waiting = waitingText();
        if (!waiting.isEmpty())
            text += u"<br>"_s + waiting.toHtmlEscaped();
        m_status->setText(text);
        m_status->setToolTip(waiting);
    } else if (showing) {
        const RunInfo& info = m_measure->shownRun();
        const QString when = info.startedNs > 0
            ? QDateTime::fromMSecsSinceEpoch(info.startedNs / 1'000'000).toString(u"yyyy-MM-dd HH:mm"_s)
            : tr("unknown time");
        m_status->setText(
            tr("<b>Showing the run</b> %1 (%2, %3): live stamps are not measured meanwhile")
                .arg(info.name.toHtmlEscaped(), when, QFileInfo(m_shownPath).fileName().toHtmlEscaped()));
    } else {
        m_status->setText(tr("Live"));
    }
}
