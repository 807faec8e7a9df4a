// SPDX-License-Identifier: MIT
#include "prometheusanswer.h"

#include <algorithm>
#include <cmath>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

using namespace Qt::StringLiterals;

namespace {
constexpr qsizetype kMaxWarnings = 5;

QString bounded(const QString& text)
{
    return text.size() > PrometheusAnswer::kMaxTextChars ? text.left(PrometheusAnswer::kMaxTextChars) + u'…'
                                                         : text;
}

/// [time, "value"] into `out`; false when it has another form.
bool readPoint(const QJsonValue& v, PrometheusAnswer::Point* out)
{
    if (!v.isArray())
        return false;
    const QJsonArray pair = v.toArray();
    if (pair.size() != 2 || !pair.at(0).isDouble() || !pair.at(1).isString())
        return false;
    const double t = pair.at(0).toDouble();
    if (!std::isfinite(t))
        return false;
    out->time = t;
    return PrometheusAnswer::readValue(pair.at(1).toString(), &out->value);
}

/// The labels of `metric`, bounded; false when it is not an object of strings.
bool readLabels(const QJsonValue& metric, QList<PrometheusAnswer::Label>* out)
{
    if (metric.isUndefined())
        return true; // a series without labels (e.g. of sum())
    if (!metric.isObject())
        return false;
    const QJsonObject o = metric.toObject();
    out->reserve(std::min(o.size(), PrometheusAnswer::kMaxLabels));
    for (auto it = o.begin(); it != o.end(); ++it) {
        if (!it.value().isString())
            return false;
        if (out->size() >= PrometheusAnswer::kMaxLabels)
            break;
        out->append({bounded(it.key()), bounded(it.value().toString())});
    }
    return true;
}
} // namespace

bool PrometheusAnswer::readValue(const QString& text, double* out)
{
    if (text == "NaN"_L1) {
        *out = qQNaN();
        return true;
    }
    if (text == "+Inf"_L1 || text == "Inf"_L1) {
        *out = qInf();
        return true;
    }
    if (text == "-Inf"_L1) {
        *out = -qInf();
        return true;
    }
    if (text.size() > 64)
        return false;
    bool ok = false;
    const double v = text.toDouble(&ok);
    if (!ok || !std::isfinite(v))
        return false; // "1e999" is not a number Prometheus writes
    *out = v;
    return true;
}

PrometheusAnswer PrometheusAnswer::read(const QByteArray& json)
{
    PrometheusAnswer a;
    QJsonParseError parseError {};
    const QJsonDocument doc = QJsonDocument::fromJson(json, &parseError);
    if (parseError.error != QJsonParseError::NoError) {
        a.error = tr("not JSON at byte %1 (%2)").arg(parseError.offset).arg(parseError.errorString());
        return a;
    }
    if (!doc.isObject()) {
        a.error = tr("not an answer of the Prometheus HTTP API (no object)");
        return a;
    }
    const QJsonObject top = doc.object();
    for (const QJsonValue& w : top.value("warnings"_L1).toArray())
        if (a.warnings.size() < kMaxWarnings && w.isString())
            a.warnings << bounded(w.toString());
    const QString status = top.value("status"_L1).toString();
    if (status != "success"_L1) {
        const QString type = bounded(top.value("errorType"_L1).toString());
        const QString text = bounded(top.value("error"_L1).toString());
        a.error = status == "error"_L1
            ? tr("the server refused the query: %1: %2").arg(type.isEmpty() ? u"error"_s : type, text)
            : tr("not an answer of the Prometheus HTTP API (status \"%1\")").arg(bounded(status));
        return a;
    }
    const QJsonObject data = top.value("data"_L1).toObject();
    const QString type = data.value("resultType"_L1).toString();
    const QJsonValue result = data.value("result"_L1);
    if (type == "scalar"_L1) {
        Series s;
        Point p;
        if (readPoint(result, &p)) {
            s.points << p;
            a.series << s;
        } else {
            ++a.badSamples;
        }
        return a;
    }
    if ((type != "vector"_L1 && type != "matrix"_L1) || !result.isArray()) {
        a.error = tr("not an answer of the Prometheus HTTP API (result type \"%1\")").arg(bounded(type));
        return a;
    }
    const bool matrix = type == "matrix"_L1;
    const QJsonArray results = result.toArray();
    qsizetype points = 0;
    for (const QJsonValue& r : results) {
        if (a.series.size() >= kMaxSeries) {
            ++a.droppedSeries;
            continue;
        }
        const QJsonObject o = r.toObject();
        Series s;
        if (!r.isObject() || !readLabels(o.value("metric"_L1), &s.labels)) {
            ++a.badSamples;
            continue;
        }
        if (matrix) {
            const QJsonValue values = o.value("values"_L1);
            if (!values.isArray()) {
                ++a.badSamples;
                continue;
            }
            for (const QJsonValue& v : values.toArray()) {
                Point p;
                if (points >= kMaxPoints) {
                    ++a.droppedPoints;
                } else if (readPoint(v, &p)) {
                    s.points << p;
                    ++points;
                } else {
                    ++a.badSamples;
                }
            }
        } else {
            Point p;
            if (!readPoint(o.value("value"_L1), &p)) {
                ++a.badSamples;
                continue;
            }
            s.points << p;
        }
        a.series << std::move(s);
    }
    return a;
}
