// SPDX-License-Identifier: MIT
#pragma once

#include "base/result.h"
#include "fleet/prometheusanswer.h"

#include <functional>
#include <map>
#include <QByteArray>
#include <QObject>
#include <QUrl>

class QNetworkAccessManager;
class QNetworkReply;

/// A client of Prometheus's HTTP API (/api/v1/query, /api/v1/query_range) on Qt's event loop:
/// every call returns at once and its answer comes later, so a window's thread never waits on the
/// network. Each answer is bounded before it is parsed: at most kMaxAnswerBytes (the reply is
/// aborted past them), at most kTimeoutMs from the request to the last byte, then
/// PrometheusAnswer::read's bounds; and the answers in flight together at most kMaxInFlightBytes
/// (the reply whose bytes would pass it is aborted), so a refresh's parallel queries cannot each
/// take a whole budget. A refused reply is aborted while it runs, which closes its connection
/// (Qt closes a connection whose reply did not finish): the next query never waits on it. The password of
/// basic auth is only held in memory and only sent in the Authorization header; it is never logged or shown.
class PrometheusClient : public QObject
{
    Q_OBJECT
public:
    static constexpr qint64 kMaxAnswerBytes = 32 * 1024 * 1024;
    static constexpr int kTimeoutMs = 10'000;
    /// The bodies of all answers in flight: two answers' budgets. All 15 answers of a refresh are
    /// about 22 MB at 10,000 links (2.2 MB at 1,000, bench_fleetscale), and at most 6 are in flight
    /// at a time (QNetworkAccessManager's connections to one host).
    static constexpr qint64 kMaxInFlightBytes = 2 * kMaxAnswerBytes;
    /// What Qt's network thread reads of one answer ahead of this client. Without a bound that
    /// thread reads an answer for as long as its socket has bytes, and does nothing else meanwhile:
    /// a server that sends faster than it reads kept it there, so a refused reply's abort was never
    /// handled and its connection read on (43 GB in a minute under ASan) while other queries waited.
    static constexpr qint64 kReadAheadBytes = 1024 * 1024;

    explicit PrometheusClient(QObject* parent = nullptr);
    ~PrometheusClient() override;

    /// The server's base URL (http or https, no user or password in it): "http://host:9090" or a
    /// path prefix behind a proxy ("https://host/prometheus"). Other schemes are refused.
    static Result<QUrl> checkUrl(const QString& text);
    /// Where the queries go; aborts what is in flight (their callbacks get an error).
    void setServer(const QUrl& base, const QString& user = {}, const QString& password = {});
    QUrl server() const { return m_base; }
    /// The answer bound, for tests (default kMaxAnswerBytes).
    void setMaxAnswerBytes(qint64 bytes) { m_maxBytes = bytes; }
    /// The bound of all answers in flight, for tests (default kMaxInFlightBytes).
    void setMaxInFlightBytes(qint64 bytes) { m_maxInFlightBytes = bytes; }
    /// The bytes of the answers in flight now (their bodies read so far).
    qint64 inFlightBytes() const { return m_inFlightBytes; }
    void setTimeoutMs(int ms) { m_timeoutMs = ms; }

    using Callback = std::function<void(const PrometheusAnswer&)>;
    /// An instant query at now (or at `time`, seconds since the epoch, when > 0).
    void query(const QString& promql, Callback done, double time = 0);
    /// A range query from `start` to `end` (seconds since the epoch) every `stepSeconds`.
    void queryRange(const QString& promql, double start, double end, double stepSeconds, Callback done);
    /// Aborts every request in flight; their callbacks get "aborted".
    void abortAll();
    int inFlight() const { return int(m_replies.size()); }
    /// Answers refused so far: too big, too slow, unreachable, not the API's form.
    quint64 failures() const { return m_failures; }

    /// `"value"` escaped for a PromQL string literal (backslash, quote, newline).
    static QString quoted(const QString& value);

private:
    void send(const QString& path, const QList<std::pair<QString, QString>>& params, Callback done);
    /// Reads what `reply` has into its pending body; false (the reply finished with an error)
    /// past the bound, or when it is no longer pending.
    bool take(QNetworkReply* reply);
    QString timedOut() const;
    /// `body` by value: the pending entry it may come from is erased here.
    void finish(QNetworkReply* reply, QByteArray body, const QString& error);

    QNetworkAccessManager* m_network = nullptr;
    QUrl m_base;
    QByteArray m_authorization;
    qint64 m_maxBytes = kMaxAnswerBytes;
    qint64 m_maxInFlightBytes = kMaxInFlightBytes;
    qint64 m_inFlightBytes = 0;
    /// The label strings of all answers: those of one refresh share them (see PrometheusLabelPool).
    PrometheusLabelPool m_labels;
    int m_timeoutMs = kTimeoutMs;
    quint64 m_failures = 0;
    struct Pending
    {
        Callback done;
        QByteArray body;
    };
    std::map<QNetworkReply*, Pending> m_replies;
};
