// SPDX-License-Identifier: MIT
#pragma once

#include "base/result.h"
#include "record/runfile.h"

#include <QObject>

class LiveSession;
class MeasureSession;
class RunRecorder;
class WatchSession;

/// A live session and the watch on it, assembled one way for the window and `bridgescope watch`:
/// the session, the watch on its parts and, when measuring, the measurement that gives the links
/// their pipeline latency and records the watch's events with its stamps. Without a measurement a
/// run holds the events alone, in a recorder of the watch's own.
class LiveWatch : public QObject
{
    Q_OBJECT
public:
    enum class Measuring { No, Yes };

    explicit LiveWatch(Measuring measuring, QObject* parent = nullptr);
    ~LiveWatch() override;

    LiveSession* live() const { return m_live; }
    WatchSession* watch() const { return m_watch; }
    /// The measurement (null when not measuring).
    MeasureSession* measure() const { return m_measure; }
    /// Where a run goes: the measurement's recorder (stamps and events) or the watch's own (events).
    RunRecorder* recorder() const;

    /// Records a run to `path`, in recorder().
    Result<void> startRecording(const QString& path, const RunInfo& info);
    /// Stops the run being recorded, after its last stamps and events.
    Result<void> stopRecording();

private:
    LiveSession* m_live;
    MeasureSession* m_measure = nullptr;
    WatchSession* m_watch;
    RunRecorder* m_ownRecorder = nullptr;
    quint64 m_observedDroppedSaid = 0; ///< the observed values dropped, as last logged
};
