// SPDX-License-Identifier: MIT
#pragma once

#include "record/runfile.h"

#include <functional>
#include <optional>
#include <QDateTime>
#include <QWidget>

class MeasureSession;
class QLabel;
class QPushButton;
class QTimer;

/// The Measure page's run controls: record the live measurement into a run file, open a run (or
/// import a suite CSV or a bag) to see it as it was, save an import as a run, and go back to live.
class RunBar : public QWidget
{
    Q_OBJECT
public:
    using ConfigProvider = std::function<std::pair<QString, QByteArray>()>;

    explicit RunBar(MeasureSession* measure, QWidget* parent = nullptr);

    /// Where the open bridge config comes from (path and text), kept with each run.
    void setBridgeConfigProvider(ConfigProvider provider) { m_config = std::move(provider); }

    Result<void> startRecording(const QString& path, const QString& name, const QString& notes);
    Result<void> stopRecording();
    /// Opens a run, suite CSV or bag (with a progress dialog when it takes long). When the user
    /// cancels, the error is empty.
    Status openRun(const QString& path);
    Result<void> saveRunAs(const QString& path);
    void backToLive();

    QPushButton* saveButton() const { return m_save; }

signals:
    /// A recording finished and its file is complete.
    void runRecorded(const QString& path);

private:
    void toggleRecording();
    void chooseRun();
    void chooseSaveRun();
    void updateState();
    /// While recording with nothing committed for WaitingText::kGraceMs: what it waits for.
    QString waitingText() const;

    MeasureSession* m_measure;
    ConfigProvider m_config;
    QPushButton* m_record;
    QPushButton* m_open;
    QPushButton* m_save;
    QPushButton* m_live;
    QLabel* m_status;
    QString m_recordingName;
    QDateTime m_recordingSince; ///< when the recording started, for what it waits for
    QTimer* m_waitTimer; ///< while recording: says when nothing has arrived
    QString m_shownPath;
    std::optional<RunData> m_shown;
};
