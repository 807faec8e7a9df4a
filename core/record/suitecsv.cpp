// SPDX-License-Identifier: MIT
#include "suitecsv.h"

#include "wire/stampcodec.h"

#include <QFile>
#include <QSet>

using namespace Qt::StringLiterals;

namespace {
constexpr int kMaxProblems = 100;

/// Splits one CSV record (RFC 4180 quoting) starting at `pos`; advances `pos` past its line end.
/// `ok` is false for an unterminated quote.
QStringList nextRecord(const QString& text, qsizetype& pos, bool& ok, int& lines)
{
    QStringList cells;
    QString cell;
    bool quoted = false;
    ok = true;
    lines = 1;
    while (pos < text.size()) {
        const QChar c = text[pos];
        if (quoted) {
            if (c == u'"') {
                if (pos + 1 < text.size() && text[pos + 1] == u'"') {
                    cell += u'"';
                    pos += 2;
                    continue;
                }
                quoted = false;
            } else {
                if (c == u'\n')
                    ++lines;
                cell += c;
            }
            ++pos;
            continue;
        }
        if (c == u'"' && cell.isEmpty()) {
            quoted = true;
        } else if (c == u',') {
            cells << cell;
            cell.clear();
        } else if (c == u'\r' || c == u'\n') {
            if (c == u'\r' && pos + 1 < text.size() && text[pos + 1] == u'\n')
                ++pos;
            ++pos;
            cells << cell;
            return cells;
        } else {
            cell += c;
        }
        ++pos;
    }
    if (quoted)
        ok = false;
    cells << cell;
    return cells;
}

QByteArray csvCell(const QString& s)
{
    // Quoted where Python's csv writer quotes; also a leading byte order mark, which a reader
    // would take for the file's and drop (found by the fuzz target).
    if (!s.contains(u',') && !s.contains(u'"') && !s.contains(u'\n') && !s.contains(u'\r')
        && !s.startsWith(QChar(0xFEFF)))
        return s.toUtf8();
    QString q = s;
    q.replace(u'"', u"\"\""_s);
    return '"' + q.toUtf8() + '"';
}

/// The topics of the header row; the error text, empty when every column names a topic once.
QString readHeader(const QStringList& header, QStringList* topics)
{
    QSet<QString> seen; // a list's contains() made 20,000 columns quadratic
    seen.reserve(header.size());
    for (qsizetype i = 0; i < header.size(); ++i) {
        const QString topic = header[i].trimmed();
        if (topic.isEmpty())
            return SuiteCsv::tr("column %1 of the header row has no topic name").arg(i + 1);
        if (topic.contains(QChar(0)))
            return SuiteCsv::tr("column %1 of the header row holds a NUL byte").arg(i + 1);
        if (StampCodec::parseTime(topic))
            return SuiteCsv::tr("the first row holds times, not topic names: is the header row missing?");
        if (seen.contains(topic))
            return SuiteCsv::tr("topic %1 appears twice in the header row").arg(topic);
        seen.insert(topic);
        *topics << topic;
    }
    return {};
}

/// The times of a row's cells; `missing` when a cell is empty. The row's problem, empty when none.
QString readTimes(const QStringList& cells, const QStringList& topics, std::vector<qint64>* times,
                  bool* missing)
{
    times->reserve(std::size_t(cells.size()));
    for (qsizetype i = 0; i < cells.size(); ++i) {
        const QString cell = cells[i].trimmed();
        if (cell.isEmpty()) {
            *missing = true;
            continue;
        }
        if (cell.contains(QChar(0)))
            return SuiteCsv::tr("column %1 (%2): a NUL byte in the cell").arg(i + 1).arg(topics[i]);
        const std::optional<qint64> t = StampCodec::parseTime(cell);
        if (t && !StampCodec::inRange(*t))
            return SuiteCsv::tr("column %1 (%2): %3 is %4")
                .arg(i + 1)
                .arg(topics[i], cell.left(40), StampCodec::rangeText());
        if (!t)
            return SuiteCsv::tr("column %1 (%2): \"%3\" is not a time in seconds")
                .arg(i + 1)
                .arg(topics[i], cell.left(40));
        times->push_back(*t);
    }
    return {};
}
} // namespace

std::optional<SuiteCsv::Data> SuiteCsv::read(const QString& path, QString* error, const Progress& progress)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) {
        if (error)
            *error = tr("%1: %2").arg(path, f.errorString());
        return std::nullopt;
    }
    return parse(f.readAll(), path, error, progress);
}

std::optional<SuiteCsv::Data> SuiteCsv::parse(const QByteArray& bytes, const QString& name, QString* error,
                                              const Progress& progress)
{
    const auto fail = [&](int line, const QString& why) -> std::optional<Data> {
        if (error)
            *error = u"%1:%2: %3"_s.arg(name).arg(line).arg(why);
        return std::nullopt;
    };
    QString text = QString::fromUtf8(bytes);
    if (text.startsWith(QChar(0xFEFF)))
        text.remove(0, 1);
    qsizetype pos = 0;
    int line = 1;
    bool ok = true;
    int span = 1;
    while (pos < text.size() && (text[pos] == u'\n' || text[pos] == u'\r')) {
        if (text[pos] == u'\n')
            ++line;
        ++pos;
    }
    if (pos >= text.size())
        return fail(line, tr("empty file: expected a header row of stamp topics"));
    Data data;
    const QStringList header = nextRecord(text, pos, ok, span);
    if (!ok)
        return fail(line, tr("unterminated quote in the header row"));
    if (const QString why = readHeader(header, &data.topics); !why.isEmpty())
        return fail(line, why);
    line += span;
    const auto problem = [&](int at, const QString& why) {
        ++data.malformed;
        if (data.problems.size() < kMaxProblems)
            data.problems << u"%1:%2: %3"_s.arg(name).arg(at).arg(why);
    };
    qint64 cellsSincePoll = 0;
    while (pos < text.size()) {
        // Polled by cells, not rows: one row of 20,000 columns is a lot of work already.
        cellsSincePoll += data.topics.size();
        if (progress && cellsSincePoll >= 100'000) {
            cellsSincePoll = 0;
            if (!progress(int(100 * pos / text.size())))
                return fail(line, tr("cancelled"));
        }
        const int at = line;
        const QStringList cells = nextRecord(text, pos, ok, span);
        line += span;
        if (cells.size() == 1 && cells.first().trimmed().isEmpty())
            continue; // blank line
        if (!ok) {
            problem(at, tr("unterminated quote"));
            break;
        }
        if (cells.size() != data.topics.size()) {
            problem(at, tr("%1 cells, the header has %2").arg(cells.size()).arg(data.topics.size()));
            continue;
        }
        std::vector<qint64> times;
        bool missing = false;
        const QString bad = readTimes(cells, data.topics, &times, &missing);
        if (!bad.isEmpty()) {
            problem(at, bad);
            continue;
        }
        if (missing) {
            ++data.incomplete;
            continue;
        }
        data.samples.push_back(std::move(times));
    }
    return data;
}

QByteArray SuiteCsv::header(const QStringList& topics)
{
    QByteArray out;
    for (qsizetype i = 0; i < topics.size(); ++i) {
        if (i)
            out += ',';
        out += csvCell(topics[i]);
    }
    return out + "\r\n";
}

QByteArray SuiteCsv::row(const std::vector<qint64>& times)
{
    QByteArray out;
    out.reserve(qsizetype(times.size()) * 22);
    for (std::size_t i = 0; i < times.size(); ++i) {
        if (i)
            out += ',';
        out += StampCodec::timeText(times[i]).toLatin1();
    }
    return out + "\r\n";
}

QByteArray SuiteCsv::write(const QStringList& topics, const std::vector<std::vector<qint64>>& samples)
{
    QByteArray out = header(topics);
    for (const auto& s : samples)
        out += row(s);
    return out;
}
