// SPDX-License-Identifier: MIT
#include "runrecorder.h"

#include "base/logging.h"

#include <atomic>
#include <mutex>
#include <QDateTime>
#include <QPointer>
#include <QThread>
#include <QTimer>

struct RunRecorder::Private
{
    struct Tick
    {
        std::vector<StampEvent> stamps;
        std::vector<LatencyValue> latencies;
        qint64 drainedNs = 0;
    };
    std::mutex mutex;
    std::vector<Tick> queued; ///< guarded by mutex
    std::vector<RecordedEvent> queuedEvents; ///< guarded by mutex
    std::vector<RecordedClock> queuedClocks; ///< guarded by mutex
    std::atomic<qint64> queuedStamps {0};
    std::atomic<qint64> committed {0};
    std::atomic<bool> recording {false};
    QString path;
    QThread thread;
    QObject* worker = nullptr; ///< lives in `thread`, owns the writer and the timer
    std::unique_ptr<RunWriter> writer; ///< touched on the worker only
    QTimer* timer = nullptr;

    // Worker thread: one transaction per tick of the GUI, committed together.
    Result<void> flush()
    {
        std::vector<Tick> ticks;
        std::vector<RecordedEvent> events;
        std::vector<RecordedClock> clocks;
        {
            std::lock_guard<std::mutex> lock(mutex);
            ticks.swap(queued);
            events.swap(queuedEvents);
            clocks.swap(queuedClocks);
        }
        for (const Tick& t : ticks) {
            if (Result<void> appended = writer->append(t.stamps, t.latencies, t.drainedNs); !appended)
                return appended;
            queuedStamps.fetch_sub(qint64(t.stamps.size()));
        }
        if (Result<void> put = writer->putEvents(events); !put)
            return put;
        if (Result<void> put = writer->putClocks(clocks); !put)
            return put;
        committed.store(writer->stampCount());
        return {};
    }
};

RunRecorder::RunRecorder(QObject* parent)
    : QObject(parent)
    , d(std::make_shared<Private>())
{
    d->thread.setObjectName(QStringLiteral("run-recorder"));
}

RunRecorder::~RunRecorder()
{
    if (isRecording())
        static_cast<void>(stop()); // nobody is left to tell of a failure
}

Result<void> RunRecorder::start(const QString& path, const RunInfo& info)
{
    if (isRecording())
        return LocatedError {tr("already recording to %1").arg(d->path)};
    // The file is created here, so that a bad path is reported at once; writing moves to the worker.
    auto writer = std::make_unique<RunWriter>();
    if (Result<void> created = writer->create(path, info); !created)
        return created;
    writer.reset(); // the connection belongs to this thread: reopen on the worker
    d->path = path;
    d->committed = 0;
    d->queuedStamps = 0;
    d->worker = new QObject;
    d->worker->moveToThread(&d->thread);
    connect(&d->thread, &QThread::finished, d->worker, &QObject::deleteLater);
    d->thread.start();
    d->recording = true;
    qCDebug(lcRecord).noquote() << "recording to" << path;
    std::shared_ptr<Private> p = d;
    QPointer<RunRecorder> self(this);
    QString openError;
    QMetaObject::invokeMethod(
        p->worker,
        [p, self, &openError] {
            p->writer = std::make_unique<RunWriter>();
            if (const Result<void> opened = p->writer->open(p->path); !opened) {
                openError = opened.error().toString();
                return;
            }
            p->timer = new QTimer(p->worker);
            p->timer->setInterval(kCommitIntervalMs);
            QObject::connect(p->timer, &QTimer::timeout, p->worker, [p, self] {
                if (const Result<void> flushed = p->flush(); !flushed) {
                    const QString why = flushed.error().toString();
                    p->timer->stop();
                    p->recording = false;
                    QMetaObject::invokeMethod(self, [self, why] {
                        if (self)
                            emit self->failed(why);
                    });
                    return;
                }
                const qint64 n = p->committed.load();
                QMetaObject::invokeMethod(self, [self, n] {
                    if (self)
                        emit self->committed(n);
                });
            });
            p->timer->start();
        },
        Qt::BlockingQueuedConnection);
    if (!openError.isEmpty()) {
        d->recording = false;
        d->thread.quit();
        d->thread.wait();
        return LocatedError {openError};
    }
    return {};
}

void RunRecorder::add(const std::vector<StampEvent>& stamps, const std::vector<LatencyValue>& latencies,
                      qint64 drainedNs)
{
    if (!d->recording || (stamps.empty() && latencies.empty()))
        return;
    std::lock_guard<std::mutex> lock(d->mutex);
    d->queued.push_back({stamps, latencies, drainedNs});
    d->queuedStamps.fetch_add(qint64(stamps.size()));
}

void RunRecorder::addEvent(const RecordedEvent& event)
{
    if (!d->recording)
        return;
    std::lock_guard<std::mutex> lock(d->mutex);
    d->queuedEvents.push_back(event);
}

void RunRecorder::addClock(const ClockEstimate& estimate, qint64 drainedNs)
{
    if (!d->recording)
        return;
    std::lock_guard<std::mutex> lock(d->mutex);
    d->queuedClocks.push_back({estimate, drainedNs});
}

Result<void> RunRecorder::stop()
{
    if (!d->thread.isRunning())
        return LocatedError {}; // nothing to stop: no message, as the callers check first
    std::shared_ptr<Private> p = d;
    Result<void> stopped = LocatedError {}; // no writer: its open failed and was reported
    QMetaObject::invokeMethod(
        p->worker,
        [p, &stopped] {
            if (p->timer)
                p->timer->stop();
            if (p->writer) {
                stopped = p->flush();
                if (stopped)
                    stopped = p->writer->finish(QDateTime::currentMSecsSinceEpoch() * 1'000'000);
            }
            p->writer.reset();
        },
        Qt::BlockingQueuedConnection);
    d->recording = false;
    qCDebug(lcRecord).noquote() << "stopped recording to" << d->path << (stopped ? "" : "failed:")
                                << (stopped ? QString() : stopped.error().toString());
    d->thread.quit();
    d->thread.wait();
    return stopped;
}

bool RunRecorder::isRecording() const
{
    return d->recording;
}

QString RunRecorder::path() const
{
    return d->path;
}

qint64 RunRecorder::committedStamps() const
{
    return d->committed.load();
}

qint64 RunRecorder::queuedStamps() const
{
    return d->queuedStamps.load();
}
