// SPDX-License-Identifier: MIT
#pragma once

#include <deque>
#include <QByteArray>
#include <QByteArrayView>
#include <QCoreApplication>
#include <QHash>
#include <QList>
#include <QString>
#include <QStringList>
#include <utility>

/// A label of a series: its name and its value.
using PrometheusLabel = std::pair<QString, QString>;

/// The label strings of the answers read with it, each text made once: the fleet view's answers of
/// one refresh name the same links, so their series share one string for each label value, and a
/// series finds its link by the strings' data (FleetSnapshotBuilder) without hashing their text.
/// The labels of a whole metric object (`{"host":"a",…}`) are kept by its bytes too: a series
/// whose object was met before, in this answer or an earlier one, shares that list of labels (the
/// same data) and is not read label by label again. Prometheus gives the series of its answers in
/// the order of their labels, the same for every answer of a kind: the object met after another
/// last time is tried first, by its bytes alone, before the hash of all objects.
/// Bounded: past kMaxBytes of text it starts again empty (a hostile server's ever new labels).
class PrometheusLabelPool
{
public:
    static constexpr qsizetype kMaxBytes = 16 * 1024 * 1024;
    /// What a list of labels costs the pool beside its object's bytes: a few of its own pointers.
    static constexpr qsizetype kListBytes = 128;
    /// The string of `utf8` (valid UTF-8), the same one each time while the pool holds it.
    QString intern(QByteArrayView utf8);
    /// An answer begins: no object was met before its first.
    void startAnswer() { m_cursor = nullptr; }
    /// The labels read from the metric object `raw` before (its bytes from '{' to '}'), or null.
    const QList<PrometheusLabel>* labels(QByteArrayView raw);
    /// Keeps `labels`, read from the metric object `raw`, for the next object of the same bytes.
    void keep(QByteArrayView raw, const QList<PrometheusLabel>& labels);
    qsizetype size() const { return m_strings.size(); }
    qsizetype lists() const { return qsizetype(m_lists.size()); }
    /// Objects found as the one that followed the object before them last time (no hash).
    quint64 followed() const { return m_followed; }

private:
    struct Known
    {
        QByteArray raw;
        QList<PrometheusLabel> labels;
        Known* next = nullptr; ///< the object met after this one last time
    };
    /// Empties the pool when `bytes` more would pass kMaxBytes, then counts them.
    void admit(qsizetype bytes);
    /// `known` was met now: after the object before it, and before the next.
    const QList<PrometheusLabel>* met(Known* known);

    QHash<QByteArrayView, QString> m_strings; ///< viewing the bytes kept in m_bytes
    QList<QByteArray> m_bytes; ///< their data never moves (a QByteArray moves only its handle)
    std::deque<Known> m_lists; ///< never moved while kept (a deque keeps its elements in place)
    QHash<QByteArrayView, Known*> m_byRaw; ///< viewing their raw bytes
    Known* m_cursor = nullptr; ///< the object met last in this answer
    quint64 m_followed = 0;
    qsizetype m_total = 0;
};

/// What one answer of Prometheus's HTTP API (/api/v1/query, /api/v1/query_range) said, as far as
/// the fleet view reads it: a vector or a matrix of series, each its labels and its samples.
///
/// The bytes come from a server on the network and are hostile: read() is bounded (at most
/// kMaxSeries series and kMaxPoints points in all, the rest counted in `droppedSeries` /
/// `droppedPoints`), and what does not have the expected form (wrong types, values that are not
/// numbers, missing fields) is counted in `badSamples`, never a crash. An answer that is not a
/// success at all is an error with the server's own words.
struct PrometheusAnswer
{
    Q_DECLARE_TR_FUNCTIONS(PrometheusAnswer)
public:
    /// Series taken from one answer: the fleet view's per-side answers hold 2 a link, so 25,000
    /// links (10,000 use 40 % of it). A memory bound: a series of the fleet's few short labels
    /// takes well under 1 KiB, and the bytes of an answer are bounded before it is parsed.
    static constexpr qsizetype kMaxSeries = 50'000;
    static constexpr qsizetype kMaxPoints = 2'000'000; ///< samples taken from one answer, in all
    static constexpr qsizetype kMaxLabels = 64; ///< labels of one series (the rest dropped)
    static constexpr qsizetype kMaxTextChars = 4096; ///< one label name or value, the error text

    struct Point
    {
        double time = 0; ///< seconds since the epoch
        double value = 0; ///< may be NaN or ±Inf (Prometheus writes them as "NaN", "+Inf")
    };
    using Label = PrometheusLabel;
    struct Series
    {
        /// In name order: a few a series (the fleet's queries aggregate to the labels
        /// they use), so a flat list and not a hash of its own for each of thousands of series.
        QList<Label> labels;
        QList<Point> points; ///< one for a vector, in time order for a matrix
        /// The value of the label `name`, empty when there is none.
        QString label(QStringView name) const
        {
            for (const Label& l : labels)
                if (l.first == name)
                    return l.second;
            return {};
        }
    };

    QList<Series> series;
    qsizetype droppedSeries = 0; ///< past kMaxSeries
    qsizetype droppedPoints = 0; ///< past kMaxPoints
    qsizetype badSamples = 0; ///< series or samples of the wrong form, skipped
    QString error; ///< empty on success: "bad_data: …", "not JSON at byte 12", …
    QStringList warnings; ///< the server's own warnings, at most a few

    bool ok() const { return error.isEmpty(); }
    /// Reads an answer's bytes (already bounded in size by the client): Prometheus's usual form
    /// straight from the bytes, anything else as readGeneral() does, with the same result. The
    /// usual form's label strings come from `labels` when given (shared with other answers).
    static PrometheusAnswer read(const QByteArray& json, PrometheusLabelPool* labels = nullptr);
    /// Reads Prometheus's usual form of an answer (success, a vector or a matrix, strings without
    /// escapes, within the bounds) straight from the bytes; false, `out` untouched, for any other.
    static bool readUsual(const QByteArray& json, PrometheusAnswer* out,
                          PrometheusLabelPool* labels = nullptr);
    /// Reads any answer through a JSON document: errors, warnings, scalars, escapes, what is past
    /// a bound or of the wrong form (counted).
    static PrometheusAnswer readGeneral(const QByteArray& json);
    /// A sample value as Prometheus writes it: a JSON string of a float ("1.5", "NaN", "+Inf").
    /// Anything else is not a value (false).
    static bool readValue(const QString& text, double* out);
};
