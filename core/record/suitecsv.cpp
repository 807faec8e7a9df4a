// SPDX-License-Identifier: MIT
#include "suitecsv.h"

#include "files/regularfile.h"
#include "record/readbudgets.h"
#include "wire/stampcodec.h"

#include <limits>
#include <QDeadlineTimer>
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

namespace {
/// Reads the CSV as its bytes come, one record at a time: never the whole file as text, so that
/// what it holds is the samples taken (within the budgets) and one row (issue 41).
class Parser
{
public:
    Parser(const QString& name, const SuiteCsv::Limits& limits, const SuiteCsv::Progress& progress,
           qint64 totalBytes)
        : m_name(name)
        , m_limits(limits)
        , m_progress(progress)
        , m_total(std::max<qint64>(totalBytes, 1))
        , m_deadline(std::chrono::seconds(limits.maxSeconds))
    { }

    /// Takes the next bytes of the file; false when the read stopped (see finish()).
    bool feed(const char* bytes, qsizetype size)
    {
        if (!m_why.isEmpty())
            return false;
        m_fed += size;
        m_pending.append(bytes, size);
        if (!takeRecords(false))
            return false;
        return poll();
    }
    /// The file's end: its last record, then the data or the error.
    Result<SuiteCsv::Data> finish()
    {
        if (m_why.isEmpty())
            takeRecords(true);
        if (m_why.isEmpty() && !m_header)
            stop(m_line, SuiteCsv::tr("empty file: expected a header row of stamp topics"));
        if (!m_why.isEmpty())
            return LocatedError {m_why};
        return std::move(m_data);
    }

private:
    bool stop(qint64 line, const QString& why)
    {
        m_why = u"%1:%2: %3"_s.arg(m_name).arg(line).arg(why);
        return false;
    }
    /// Progress, Ctrl+C and the deadline: between chunks and every 100,000 cells.
    bool poll()
    {
        if (RegularFile::stopRequested() || (m_progress && !m_progress(int(100 * m_fed / m_total))))
            return stop(m_line, SuiteCsv::tr("cancelled"));
        if (m_deadline.hasExpired())
            return stop(m_line,
                        SuiteCsv::tr("refused: reading it takes more than %1 s").arg(m_limits.maxSeconds));
        return true;
    }

    /// Cuts the complete records out of m_pending (at the end of the file, the last one too), in
    /// RFC 4180's quoting as nextRecord() reads it: a record ends at a line break outside quotes.
    bool takeRecords(bool atEnd)
    {
        const char* p = m_pending.constData();
        const qsizetype n = m_pending.size();
        qsizetype begin = 0;
        qsizetype i = m_scan;
        while (i < n) {
            const char c = p[i];
            if (m_quoted) {
                if (c == '"') {
                    if (i + 1 >= n && !atEnd)
                        break; // is it a doubled quote? the next chunk says
                    if (i + 1 < n && p[i + 1] == '"') {
                        i += 2;
                        continue;
                    }
                    m_quoted = false;
                }
                m_cellEmpty = false;
                ++i;
                continue;
            }
            if (c == '"' && m_cellEmpty) {
                m_quoted = true;
            } else if (c == ',') {
                m_cellEmpty = true;
            } else if (c == '\r' || c == '\n') {
                if (c == '\r' && i + 1 >= n && !atEnd)
                    break; // CR LF cut between two chunks
                const qsizetype terminator = c == '\r' && i + 1 < n && p[i + 1] == '\n' ? 2 : 1;
                if (!takeRecord(QByteArrayView(p + begin, i - begin), p[i + terminator - 1] == '\n'))
                    return false;
                i += terminator;
                begin = i;
                m_cellEmpty = true;
                continue;
            } else {
                m_cellEmpty = false;
            }
            ++i;
        }
        if (i - begin > m_limits.maxRowBytes)
            return stop(
                m_line,
                SuiteCsv::tr("refused: a row of more than %1 MiB").arg(m_limits.maxRowBytes / (1024 * 1024)));
        if (atEnd && begin < n) {
            i = n;
            if (!takeRecord(QByteArrayView(p + begin, n - begin), false))
                return false;
            begin = n;
        }
        m_pending.remove(0, begin);
        m_scan = i - begin;
        return true;
    }

    /// One record (without its line break); `newline`: its break was (or ended with) a LF.
    bool takeRecord(QByteArrayView bytes, bool newline)
    {
        if (bytes.size() > m_limits.maxRowBytes)
            return stop(
                m_line,
                SuiteCsv::tr("refused: a row of more than %1 MiB").arg(m_limits.maxRowBytes / (1024 * 1024)));
        if (!m_started) {
            if (bytes.startsWith("\xEF\xBB\xBF"))
                bytes = bytes.sliced(3); // the byte order mark
            m_started = true;
        }
        if (!m_header) {
            if (bytes.isEmpty()) { // blank lines before the header
                m_line += newline ? 1 : 0;
                return true;
            }
            return takeHeader(bytes);
        }
        if ((m_cells += m_data.topics.size()) > m_limits.maxCells)
            return stop(
                m_line,
                SuiteCsv::tr("refused: it has more than %1 cells (the most a measurement file may have)")
                    .arg(m_limits.maxCells));
        const QString text = QString::fromUtf8(bytes);
        qsizetype pos = 0;
        bool ok = true;
        int span = 1;
        const qint64 at = m_line;
        const QStringList cells = nextRecord(text, pos, ok, span);
        m_line += span;
        if ((m_sincePoll += m_data.topics.size()) >= 100'000) {
            // Polled by cells, not rows: one row of 20,000 columns is a lot of work already.
            m_sincePoll = 0;
            if (!poll())
                return false;
        }
        if (cells.size() == 1 && cells.first().trimmed().isEmpty())
            return true; // blank line
        if (!ok) {
            problem(at, SuiteCsv::tr("unterminated quote"));
            return true; // only the file's last record can be one
        }
        if (cells.size() != m_data.topics.size()) {
            problem(at,
                    SuiteCsv::tr("%1 cells, the header has %2").arg(cells.size()).arg(m_data.topics.size()));
            return true;
        }
        std::vector<qint64> times;
        bool missing = false;
        const QString bad = readTimes(cells, m_data.topics, &times, &missing);
        if (!bad.isEmpty())
            problem(at, bad);
        else if (missing)
            ++m_data.incomplete;
        else
            m_data.samples.push_back(std::move(times));
        return true;
    }

    bool takeHeader(QByteArrayView bytes)
    {
        const QString text = QString::fromUtf8(bytes);
        qsizetype pos = 0;
        bool ok = true;
        int span = 1;
        const QStringList header = nextRecord(text, pos, ok, span);
        if (!ok)
            return stop(m_line, SuiteCsv::tr("unterminated quote in the header row"));
        if (const QString why = readHeader(header, &m_data.topics); !why.isEmpty())
            return stop(m_line, why);
        m_header = true;
        m_line += span;
        return true;
    }

    void problem(qint64 at, const QString& why)
    {
        ++m_data.malformed;
        if (m_data.problems.size() < kMaxProblems)
            m_data.problems << u"%1:%2: %3"_s.arg(m_name).arg(at).arg(why);
    }

    const QString m_name;
    const SuiteCsv::Limits m_limits;
    const SuiteCsv::Progress m_progress;
    const qint64 m_total;
    QDeadlineTimer m_deadline;
    QByteArray m_pending; ///< bytes of the record being read
    qsizetype m_scan = 0; ///< how far m_pending was scanned (quoting state below)
    bool m_quoted = false;
    bool m_cellEmpty = true;
    bool m_started = false;
    bool m_header = false;
    qint64 m_line = 1;
    qint64 m_fed = 0;
    qint64 m_cells = 0;
    qint64 m_sincePoll = 0;
    QString m_why;
    SuiteCsv::Data m_data;
};

constexpr qsizetype kChunkBytes = 1024 * 1024;
} // namespace

Result<SuiteCsv::Data> SuiteCsv::read(const QString& path, const Progress& progress, const Limits& limits)
{
    // A regular file (a FIFO or /dev/zero is refused), read in chunks up to its size at the open.
    Result<RegularFile::Opened> f = RegularFile::open(path, std::numeric_limits<qint64>::max());
    if (!f)
        return LocatedError {tr("%1: %2").arg(path, f.error().toString())};
    Parser parser(path, limits, progress, f->size);
    QByteArray chunk(kChunkBytes, Qt::Uninitialized);
    for (qint64 left = f->size; left > 0;) {
        const qint64 got = f->file->read(chunk.data(), std::min<qint64>(left, kChunkBytes));
        if (got < 0)
            return LocatedError {tr("%1: %2").arg(path, f->file->errorString())};
        if (got == 0)
            break; // the file became shorter
        left -= got;
        if (!parser.feed(chunk.constData(), qsizetype(got)))
            break;
    }
    return parser.finish();
}

Result<SuiteCsv::Data> SuiteCsv::parse(const QByteArray& bytes, const QString& name, const Progress& progress,
                                       const Limits& limits)
{
    Parser parser(name, limits, progress, bytes.size());
    parser.feed(bytes.constData(), bytes.size());
    return parser.finish();
}

Result<SuiteCsv::Data> SuiteCsv::parseInSlices(const QByteArray& bytes, const QString& name,
                                               const std::vector<qsizetype>& slices, const Limits& limits)
{
    Parser parser(name, limits, {}, bytes.size());
    qsizetype at = 0;
    for (std::size_t i = 0; at < bytes.size(); ++i) {
        const qsizetype n = slices.empty() ? bytes.size() : std::max<qsizetype>(1, slices[i % slices.size()]);
        const qsizetype take = std::min(n, bytes.size() - at);
        if (!parser.feed(bytes.constData() + at, take))
            break;
        at += take;
    }
    return parser.finish();
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
