// SPDX-License-Identifier: MIT
#include "prometheusanswer.h"

#include <algorithm>
#include <cmath>
#include <QByteArrayView>
#include <QHash>
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

/// Reads the form Prometheus gives its answers of success, a vector or a matrix of series whose
/// strings have no escapes, straight from the bytes: no JSON document built and destroyed for
/// each answer, every label string made once per answer (a refresh of a fleet of 10,000 links reads
/// 150,000 series, and the document was most of its CPU). Anything else (an error, a scalar, an
/// escape, a bound reached, a field of another form or another name) is false and nothing is
/// taken: PrometheusAnswer::readGeneral() reads it, with its counts and its messages.
class FastReader
{
public:
    FastReader(const QByteArray& json, PrometheusLabelPool* labels)
        : m_p(json.constData())
        , m_end(json.constData() + json.size())
        , m_labels(labels ? labels : &m_own)
    { }

    bool read(PrometheusAnswer* out)
    {
        m_labels->startAnswer();
        bool success = false, data = false;
        if (!eat('{'))
            return false;
        do {
            QByteArrayView key, status;
            if (!rawString(&key) || !eat(':'))
                return false;
            if (key == "status" && rawString(&status))
                success = status == "success";
            else if (key == "data" && !data && readData(out))
                data = true;
            else
                return false; // a data that is not the usual one is not read on from its middle
        } while (eat(','));
        if (!eat('}') || !success || !data)
            return false;
        space();
        return m_p == m_end;
    }

private:
    using Point = PrometheusAnswer::Point;
    enum Kind { None, Vector, Matrix, Mixed };

    void space()
    {
        while (m_p < m_end && (*m_p == ' ' || *m_p == '\n' || *m_p == '\r' || *m_p == '\t'))
            ++m_p;
    }
    bool eat(char c)
    {
        space();
        if (m_p == m_end || *m_p != c)
            return false;
        ++m_p;
        return true;
    }
    /// A string without escapes or control characters, valid UTF-8, its bytes without the quotes.
    bool rawString(QByteArrayView* out)
    {
        if (!eat('"'))
            return false;
        const char* start = m_p;
        bool ascii = true;
        for (; m_p < m_end && *m_p != '"'; ++m_p) {
            const auto c = static_cast<unsigned char>(*m_p);
            if (c == '\\' || c < 0x20)
                return false;
            ascii = ascii && c < 0x80;
        }
        if (m_p == m_end)
            return false;
        *out = QByteArrayView(start, m_p - start);
        ++m_p;
        return ascii || out->isValidUtf8();
    }
    /// A label name or value within its bound, made once per answer (or per pool).
    bool text(QString* out)
    {
        QByteArrayView bytes;
        if (!rawString(&bytes) || bytes.size() > PrometheusAnswer::kMaxTextChars)
            return false;
        *out = m_labels->intern(bytes);
        return true;
    }
    /// A number as JSON writes it, finite: false for anything else.
    static bool number(QByteArrayView text, double* out)
    {
        const auto digits = [&](qsizetype i) {
            const qsizetype from = i;
            while (i < text.size() && text[i] >= '0' && text[i] <= '9')
                ++i;
            return i > from ? i : -1;
        };
        const qsizetype sign = text.startsWith('-') ? 1 : 0;
        qsizetype i = sign;
        if (i + 1 < text.size() && text[i] == '0' && text[i + 1] >= '0' && text[i + 1] <= '9')
            return false; // JSON has no leading zeros: the document refuses "08", so must this
        if ((i = digits(i)) < 0)
            return false;
        const qsizetype wholeEnd = i; // where the integer part ends
        if (i < text.size() && text[i] == '.' && (i = digits(i + 1)) < 0)
            return false;
        if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
            ++i;
            if (i < text.size() && (text[i] == '+' || text[i] == '-'))
                ++i;
            if ((i = digits(i)) < 0)
                return false;
        }
        if (i != text.size())
            return false;
        if (wholeEnd == i && i - sign <= 15) {
            // A whole number of at most 15 digits is exact as a double: most counts and states.
            qint64 whole = 0;
            for (qsizetype d = sign; d < i; ++d)
                whole = whole * 10 + (text[d] - '0');
            *out = sign ? -double(whole) : double(whole);
            return true;
        }
        bool ok = false;
        *out = text.toDouble(&ok);
        return ok && std::isfinite(*out);
    }
    /// [time, "value"], as readPoint() takes it.
    bool point(Point* out)
    {
        space();
        const char* start = m_p;
        while (m_p < m_end && *m_p != ',' && *m_p != ']' && *m_p != ' ')
            ++m_p;
        // The samples of an instant query share their time: read once.
        const QByteArrayView time(start, m_p - start);
        if (time.isEmpty() || time != m_lastTime) {
            if (!number(time, &m_lastTimeValue)) {
                m_lastTime = {};
                return false;
            }
            m_lastTime = time;
        }
        out->time = m_lastTimeValue;
        QByteArrayView value;
        if (!eat(',') || !rawString(&value) || !eat(']'))
            return false;
        if (value == "NaN" || value == "+Inf" || value == "Inf" || value == "-Inf")
            return PrometheusAnswer::readValue(QString::fromLatin1(value), &out->value);
        return value.size() <= 64 && number(value, &out->value);
    }
    /// Past a metric object of strings without escapes, from its '{' to its '}': false, and
    /// nowhere in particular, for anything else.
    bool skipObject()
    {
        if (!eat('{'))
            return false;
        for (; m_p < m_end; ++m_p) {
            const char c = *m_p;
            if (c == '}') {
                ++m_p;
                return true;
            }
            if (c == '{' || c == '[')
                return false;
            if (c == '"') {
                while (++m_p < m_end && *m_p != '"')
                    if (*m_p == '\\' || static_cast<unsigned char>(*m_p) < 0x20)
                        return false;
                if (m_p == m_end)
                    return false;
            }
        }
        return false;
    }
    /// The labels of a metric object: those of an object of the same bytes read before (the
    /// pool's), else read label by label and kept in the pool.
    bool labels(QList<PrometheusAnswer::Label>* out)
    {
        space();
        const char* start = m_p;
        QByteArrayView raw;
        if (skipObject()) {
            raw = QByteArrayView(start, m_p - start);
            if (const QList<PrometheusAnswer::Label>* known = m_labels->labels(raw)) {
                *out = *known;
                return true;
            }
        }
        m_p = start;
        if (!readLabels(out))
            return false;
        if (!raw.isNull())
            m_labels->keep(raw, *out);
        return true;
    }
    bool readLabels(QList<PrometheusAnswer::Label>* out)
    {
        if (!eat('{'))
            return false;
        if (eat('}'))
            return true;
        out->reserve(6); // the fleet's queries keep at most 5 labels: one allocation, not three
        do {
            QString name, value;
            if (out->size() >= PrometheusAnswer::kMaxLabels || !text(&name) || !eat(':') || !text(&value))
                return false;
            for (const PrometheusAnswer::Label& l : std::as_const(*out))
                if (l.first == name)
                    return false;
            out->append({name, value});
        } while (eat(','));
        // In name order, as the JSON document gives them (its object keeps its keys sorted).
        std::sort(out->begin(), out->end(), [](const auto& a, const auto& b) { return a.first < b.first; });
        return eat('}');
    }
    bool series(PrometheusAnswer::Series* s, Kind* kind, qsizetype* points)
    {
        if (!eat('{'))
            return false;
        bool metric = false, values = false;
        do {
            QByteArrayView key;
            if (!rawString(&key) || !eat(':'))
                return false;
            if (key == "metric" && !metric) {
                metric = labels(&s->labels);
                if (!metric)
                    return false;
                continue;
            }
            const Kind k = key == "value" ? Vector : key == "values" ? Matrix : None;
            if (k == None || values)
                return false;
            values = true;
            *kind = *kind == None || *kind == k ? k : Mixed;
            Point p;
            if (k == Vector) {
                if (!eat('[') || !point(&p))
                    return false;
                s->points << p;
            } else if (eat('[') && !eat(']')) {
                do {
                    if (++*points > PrometheusAnswer::kMaxPoints || !eat('[') || !point(&p))
                        return false;
                    s->points << p;
                } while (eat(','));
                if (!eat(']'))
                    return false;
            }
        } while (eat(','));
        return values && eat('}');
    }
    bool result(PrometheusAnswer* a, Kind* kind)
    {
        qsizetype points = 0;
        if (!eat('['))
            return false;
        if (eat(']'))
            return true;
        do {
            PrometheusAnswer::Series s;
            if (a->series.size() >= PrometheusAnswer::kMaxSeries || !series(&s, kind, &points))
                return false;
            a->series << std::move(s);
        } while (eat(','));
        return eat(']') && *kind != Mixed;
    }
    bool readData(PrometheusAnswer* a)
    {
        QByteArrayView type;
        bool haveResult = false;
        Kind kind = None;
        if (!eat('{'))
            return false;
        do {
            QByteArrayView key;
            if (!rawString(&key) || !eat(':'))
                return false;
            if (key == "resultType" && type.isNull()) {
                if (!rawString(&type))
                    return false;
            } else if (key == "result" && !haveResult) {
                haveResult = result(a, &kind);
                if (!haveResult)
                    return false;
            } else {
                return false;
            }
        } while (eat(','));
        const bool matrix = type == "matrix";
        return eat('}') && haveResult && (matrix || type == "vector")
            && (kind == None || kind == (matrix ? Matrix : Vector));
    }

    const char* m_p;
    const char* m_end;
    QByteArrayView m_lastTime; ///< the bytes of the last time read, in the answer
    double m_lastTimeValue = 0;
    PrometheusLabelPool m_own;
    PrometheusLabelPool* m_labels;
};
} // namespace

void PrometheusLabelPool::admit(qsizetype bytes)
{
    if (m_total + bytes > kMaxBytes) {
        m_strings.clear();
        m_bytes.clear();
        m_byRaw.clear();
        m_lists.clear();
        m_cursor = nullptr;
        m_total = 0;
    }
    m_total += bytes;
}

QString PrometheusLabelPool::intern(QByteArrayView utf8)
{
    if (const auto it = m_strings.constFind(utf8); it != m_strings.cend())
        return *it;
    admit(utf8.size());
    m_bytes.append(utf8.toByteArray());
    const QString text = QString::fromUtf8(utf8);
    m_strings.insert(QByteArrayView(m_bytes.constLast()), text);
    return text;
}

const QList<PrometheusLabel>* PrometheusLabelPool::met(Known* known)
{
    if (m_cursor)
        m_cursor->next = known;
    m_cursor = known;
    return &known->labels;
}

const QList<PrometheusLabel>* PrometheusLabelPool::labels(QByteArrayView raw)
{
    if (m_cursor && m_cursor->next && m_cursor->next->raw == raw) {
        ++m_followed;
        m_cursor = m_cursor->next;
        return &m_cursor->labels;
    }
    const auto it = m_byRaw.constFind(raw);
    return it == m_byRaw.cend() ? nullptr : met(*it);
}

void PrometheusLabelPool::keep(QByteArrayView raw, const QList<PrometheusLabel>& labels)
{
    // The list's strings are the pool's own (intern()), or else its own: counted with the list.
    qsizetype bytes = raw.size() + kListBytes;
    for (const PrometheusLabel& l : labels)
        bytes += 2 * (l.first.size() + l.second.size());
    admit(bytes);
    Known& known = m_lists.emplace_back(Known {raw.toByteArray(), labels});
    m_byRaw.insert(QByteArrayView(known.raw), &known);
    met(&known);
}

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

PrometheusAnswer PrometheusAnswer::read(const QByteArray& json, PrometheusLabelPool* labels)
{
    PrometheusAnswer a;
    return readUsual(json, &a, labels) ? a : readGeneral(json);
}

bool PrometheusAnswer::readUsual(const QByteArray& json, PrometheusAnswer* out, PrometheusLabelPool* labels)
{
    PrometheusAnswer a;
    if (!FastReader(json, labels).read(&a))
        return false;
    *out = std::move(a);
    return true;
}

PrometheusAnswer PrometheusAnswer::readGeneral(const QByteArray& json)
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
