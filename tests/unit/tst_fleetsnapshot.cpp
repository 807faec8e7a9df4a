// SPDX-License-Identifier: MIT
// The fleet view's core without a Prometheus: PrometheusAnswer on hand-written and hostile answers,
// FleetSnapshotBuilder's mapping and judging, and PrometheusClient's bounds against a small HTTP
// server of the test's own that answers too much, too late or not at all.
#include "fleet/fleetsnapshot.h"
#include "fleet/fleetsource.h"
#include "fleet/prometheusclient.h"
#include "peakrss.h"

#include <limits>
#include <memory>
#include <QDateTime>
#include <QElapsedTimer>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSignalSpy>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTest>

using namespace Qt::StringLiterals;

namespace {
/// JSON written with single quotes (readable in C++ strings).
QByteArray j(const char* text)
{
    return QByteArray(text).replace('\'', '"');
}

using Labels = QList<std::pair<QString, QString>>;

QJsonObject metric(const Labels& labels)
{
    QJsonObject m;
    for (const auto& [k, v] : labels)
        m.insert(k, v);
    return m;
}

/// A vector answer of `series` (labels, value as Prometheus writes it), its label strings from
/// `pool` when given.
PrometheusAnswer vector(const QList<std::pair<Labels, QString>>& series, double time = 1000,
                        PrometheusLabelPool* pool = nullptr)
{
    QJsonArray result;
    for (const auto& [labels, value] : series)
        result.append(QJsonObject {{u"metric"_s, metric(labels)}, {u"value"_s, QJsonArray {time, value}}});
    const QJsonObject top {{u"status"_s, u"success"_s},
                           {u"data"_s, QJsonObject {{u"resultType"_s, u"vector"_s}, {u"result"_s, result}}}};
    return PrometheusAnswer::read(QJsonDocument(top).toJson(QJsonDocument::Compact), pool);
}

Labels link(const QString& host, const QString& name, const QString& side = {})
{
    Labels l {
        {u"host"_s, host}, {u"bridge"_s, u"bridge1"_s}, {u"link"_s, name}, {u"direction"_s, u"ros2mqtt"_s}};
    if (!side.isEmpty())
        l.append({u"side"_s, side});
    return l;
}

/// Answers for two hosts: "a" reporting with links "/x → x" (healthy), "/s → s" (stalled),
/// "/l → l" (losing 10 %), "/p → p" (p99 300 ms); "b" stopped reporting, its link "/y → y" known
/// from the hour.
QHash<QString, PrometheusAnswer> twoHosts(PrometheusLabelPool* pool = nullptr)
{
    const auto vector
        = [pool](const QList<std::pair<Labels, QString>>& series) { return ::vector(series, 1000, pool); };
    const QStringList names {u"/x → x"_s, u"/s → s"_s, u"/l → l"_s, u"/p → p"_s};
    QList<std::pair<Labels, QString>> state, rate, messages, recent, lost, recentLost, seen;
    for (const QString& n : names) {
        state.append({link(u"a"_s, n), u"0"_s});
        seen.append({link(u"a"_s, n), u"1"_s});
        rate.append({link(u"a"_s, n, u"source"_s), u"10"_s});
        rate.append({link(u"a"_s, n, u"destination"_s), n.startsWith(u"/s"_s) ? u"0"_s : u"10"_s});
        messages.append({link(u"a"_s, n, u"source"_s), u"1200"_s});
        messages.append({link(u"a"_s, n, u"destination"_s), u"1100"_s});
        recent.append({link(u"a"_s, n, u"source"_s), u"600"_s});
        recent.append({link(u"a"_s, n, u"destination"_s), n.startsWith(u"/s"_s) ? u"0"_s : u"600"_s});
        lost.append({link(u"a"_s, n), u"100"_s});
        recentLost.append({link(u"a"_s, n), n.startsWith(u"/l"_s) ? u"60"_s : u"0"_s});
    }
    QList<std::pair<Labels, QString>> links = state;
    links.append({link(u"b"_s, u"/y → y"_s), u"0"_s});
    QHash<QString, PrometheusAnswer> a;
    a[u"links"_s] = vector(links);
    a[u"state"_s] = vector(state);
    a[u"seen"_s] = vector(seen);
    a[u"rate"_s] = vector(rate);
    a[u"messages"_s] = vector(messages);
    a[u"bytes"_s] = vector({});
    a[u"lost"_s] = vector(lost);
    a[u"stalls"_s] = vector({});
    a[u"recent"_s] = vector(recent);
    a[u"recentLost"_s] = vector(recentLost);
    a[u"p50"_s] = vector({{link(u"a"_s, u"/p → p"_s), u"100"_s}, {link(u"a"_s, u"/x → x"_s), u"NaN"_s}});
    a[u"p99"_s] = vector({{link(u"a"_s, u"/p → p"_s), u"300"_s}, {link(u"a"_s, u"/x → x"_s), u"NaN"_s}});
    a[u"bridges"_s] = vector({{{{u"host"_s, u"a"_s}, {u"bridge"_s, u"bridge1"_s}}, u"1"_s}});
    a[u"info"_s] = vector({{{{u"host"_s, u"a"_s}, {u"version"_s, u"1.2.3"_s}}, u"1"_s}});
    a[u"lastSeen"_s] = vector({{{{u"host"_s, u"a"_s}}, u"1000"_s}, {{{u"host"_s, u"b"_s}}, u"900"_s}});
    return a;
}

const FleetLink* find(const FleetSnapshot& s, const QString& host, const QString& name)
{
    for (const FleetLink& l : s.links)
        if (l.host == host && l.link == name)
            return &l;
    return nullptr;
}

/// What a snapshot shows and judges of each link, a line a link.
QStringList printed(const FleetSnapshot& s)
{
    QStringList out;
    for (const FleetLink& l : s.links)
        out << u"%1 %2 %3 %4 src %5/%6 Hz dst %7/%8 Hz loss %9 p50 %10 p99 %11 lost %12 stalls %13 %14 %15"_s
                    .arg(l.host, l.link)
                    .arg(int(l.verdict.level))
                    .arg(l.verdict.detail)
                    .arg(l.figures.source.messages)
                    .arg(l.figures.source.rateHz)
                    .arg(l.figures.destination.messages)
                    .arg(l.figures.destination.rateHz)
                    .arg(l.figures.lossPercent)
                    .arg(l.figures.latencyP50Ms)
                    .arg(l.figures.latencyP99Ms)
                    .arg(l.figures.lost)
                    .arg(l.figures.stalls)
                    .arg(l.hostReporting)
                    .arg(l.reportedState)
                + u' ' + (l.verdict.unknown ? u"unknown"_s : u"known"_s);
    return out;
}

/// A one-shot HTTP server: answers each request with `head` and `body` (or nothing, when `silent`).
class TinyServer : public QTcpServer
{
public:
    QByteArray answer;
    bool silent = false;
    TinyServer()
    {
        connect(this, &QTcpServer::newConnection, this, [this] {
            while (QTcpSocket* s = nextPendingConnection()) {
                connect(s, &QTcpSocket::readyRead, s, [this, s] {
                    if (!s->readAll().contains("\r\n\r\n") || silent)
                        return;
                    s->write(answer);
                    s->disconnectFromHost();
                });
            }
        });
        listen(QHostAddress::LocalHost);
    }
    QUrl url() const { return QUrl(u"http://127.0.0.1:%1"_s.arg(serverPort())); }
};

/// The rows of the flood tests: a FloodServer that announces its length, and an endless one.
static void floodRows(const char* announced, const char* endless)
{
    QTest::addColumn<bool>("endless");
    QTest::newRow(announced) << false;
    QTest::newRow(endless) << true;
}

/// A hostile HTTP server: every request gets a body past any budget, 1 MiB at a time as the client
/// takes it: `kLength` bytes announced in Content-Length, or (endless) no length and no end.
/// With `keepAlive`, only the first connection floods, without Connection: close (it reads no second
/// request all the same), and every later one answers an empty vector.
class FloodServer : public QTcpServer
{
public:
    static constexpr qint64 kChunk = 1 << 20;
    static constexpr qint64 kLength = qint64(48) << 20;
    qint64 written = 0; ///< body bytes, all connections
    qint64 most = 0; ///< body bytes of the connection that took the most
    int connections = 0;
    explicit FloodServer(bool endless, bool keepAlive = false)
    {
        connect(this, &QTcpServer::newConnection, this, [this, endless, keepAlive] {
            while (QTcpSocket* s = nextPendingConnection()) {
                connect(s, &QTcpSocket::disconnected, s, &QObject::deleteLater);
                if (keepAlive && ++connections > 1) {
                    connect(s, &QTcpSocket::readyRead, s, [s] {
                        if (s->readAll().contains("\r\n\r\n"))
                            s->write(okAnswer());
                    });
                    continue;
                }
                auto sent = std::make_shared<qint64>(-1); // -1: not asked yet
                const auto feed = [this, s, sent, endless] {
                    while (*sent >= 0 && s->bytesToWrite() < kChunk && (endless || *sent < kLength)) {
                        s->write(m_chunk);
                        *sent += kChunk;
                        written += kChunk;
                        most = std::max(most, *sent);
                    }
                };
                connect(s, &QTcpSocket::readyRead, s, [s, sent, feed, endless, keepAlive] {
                    if (!s->readAll().contains("\r\n\r\n") || *sent >= 0)
                        return;
                    // One answer a connection (it reads no second request): Connection: close, so
                    // that the client does not send the next query on it (unless `keepAlive`).
                    s->write(
                        "HTTP/1.1 200 OK\r\nContent-Type: application/json\r\n"
                        + (keepAlive ? QByteArray() : "Connection: close\r\n"_ba)
                        + (endless ? QByteArray() : "Content-Length: " + QByteArray::number(kLength) + "\r\n")
                        + "\r\n");
                    *sent = 0;
                    feed();
                });
                connect(s, &QTcpSocket::bytesWritten, s, feed);
            }
        });
        listen(QHostAddress::LocalHost);
    }
    QUrl url() const { return QUrl(u"http://127.0.0.1:%1"_s.arg(serverPort())); }
    static QByteArray okAnswer()
    {
        const QByteArray body = R"({"status":"success","data":{"resultType":"vector","result":[]}})";
        return "HTTP/1.1 200 OK\r\nContent-Type: application/json\r\nContent-Length: "
            + QByteArray::number(body.size()) + "\r\n\r\n" + body;
    }

private:
    const QByteArray m_chunk = QByteArray(kChunk, ' ');
};

/// A Prometheus of one link: every query gets the link "/x → x" of host "a" (a source side, a
/// version) with the value `value`, and is counted.
class OneLinkServer : public QTcpServer
{
public:
    QByteArray value = "7";
    int requests = 0;
    OneLinkServer()
    {
        connect(this, &QTcpServer::newConnection, this, [this] {
            while (QTcpSocket* s = nextPendingConnection()) {
                auto request = std::make_shared<QByteArray>();
                connect(s, &QTcpSocket::readyRead, s, [this, s, request] {
                    *request += s->readAll();
                    const qsizetype end = request->indexOf("\r\n\r\n");
                    if (end < 0)
                        return;
                    ++requests;
                    request->clear();
                    const QByteArray body
                        = R"({"status":"success","data":{"resultType":"vector","result":[{"metric":{"host":"a",)"
                          R"("bridge":"b","link":"/x → x","direction":"ros2mqtt","side":"source","version":"1"},)"
                          R"("value":[1000,")"
                        + value + R"("]}]}})";
                    s->write("HTTP/1.1 200 OK\r\nContent-Type: application/json\r\nContent-Length: "
                             + QByteArray::number(body.size()) + "\r\n\r\n" + body);
                });
                connect(s, &QTcpSocket::disconnected, s, &QObject::deleteLater);
            }
        });
        listen(QHostAddress::LocalHost);
    }
    QUrl url() const { return QUrl(u"http://127.0.0.1:%1"_s.arg(serverPort())); }
};

QByteArray http(const QByteArray& body)
{
    return "HTTP/1.1 200 OK\r\nContent-Type: application/json\r\nContent-Length: "
        + QByteArray::number(body.size()) + "\r\nConnection: close\r\n\r\n" + body;
}

/// One refresh of `source` from the flood `server`: how much the peak RSS grew (-1: no refresh).
qint64 refreshFlooded(FleetSource& source, const FloodServer& server)
{
    source.client()->setTimeoutMs(60000); // the budget of bytes is under test, not the one of time
    if (!PeakRss::reset())
        return -1;
    const qint64 before = PeakRss::of();
    QSignalSpy refreshed(&source, &FleetSource::refreshed);
    source.refresh();
    if (!refreshed.wait(120000))
        return -1;
    const qint64 grew = PeakRss::of() - before;
    qInfo("%lld MiB sent, at most %lld MiB on one connection; peak RSS grew by %lld MiB",
          server.written >> 20, server.most >> 20, grew >> 20);
    return grew;
}

/// What a server can send on one connection past what the client read: the kernel's buffers at
/// their largest (the receive one grows under autotuning), the read-ahead of Qt's network thread
/// (PrometheusClient::kReadAheadBytes, twice: its buffer and the reply's) and the server's chunk.
qint64 sentPastWhatWasRead()
{
    const auto largest = [](const char* path) {
        QFile f(QString::fromLatin1(path));
        const QList<QByteArray> fields
            = f.open(QIODevice::ReadOnly) ? f.readAll().simplified().split(' ') : QList<QByteArray>();
        return fields.size() == 3 ? fields[2].toLongLong() : qint64(64) << 20;
    };
    return largest("/proc/sys/net/ipv4/tcp_rmem") + largest("/proc/sys/net/ipv4/tcp_wmem")
        + 2 * PrometheusClient::kReadAheadBytes + FloodServer::kChunk;
}

PrometheusAnswer ask(PrometheusClient& client)
{
    PrometheusAnswer answer;
    bool done = false;
    client.query(u"up"_s, [&](const PrometheusAnswer& a) {
        answer = a;
        done = true;
    });
    if (!QTest::qWaitFor([&] { return done; }, 20000))
        answer.error = u"test: no callback"_s;
    return answer;
}
} // namespace

class TestFleetSnapshot : public QObject
{
    Q_OBJECT
private slots:
    void readsVectorMatrixScalarAndErrors()
    {
        const PrometheusAnswer v
            = PrometheusAnswer::read(j("{'status':'success','data':{'resultType':'vector','result':[{'metric'"
                                       ":{'host':'a'},'value':[12.5,'3']}]}}"));
        QVERIFY(v.ok());
        QCOMPARE(v.series.size(), 1);
        QCOMPARE(v.series[0].label(u"host"_s), u"a"_s);
        QCOMPARE(v.series[0].points[0].time, 12.5);
        QCOMPARE(v.series[0].points[0].value, 3.0);
        const PrometheusAnswer m
            = PrometheusAnswer::read(j("{'status':'success','data':{'resultType':'matrix','result':[{'metric'"
                                       ":{},'values':[[1,'1'],[2,'NaN'],[3,'+Inf']]}]}}"));
        QVERIFY(m.ok());
        QCOMPARE(m.series[0].points.size(), 3);
        QVERIFY(std::isnan(m.series[0].points[1].value));
        QVERIFY(std::isinf(m.series[0].points[2].value));
        const PrometheusAnswer s = PrometheusAnswer::read(
            j("{'status':'success','data':{'resultType':'scalar','result':[5,'7']}}"));
        QCOMPARE(s.series[0].points[0].value, 7.0);
        const PrometheusAnswer e = PrometheusAnswer::read(
            j("{'status':'error','errorType':'bad_data','error':'parse error at char 3'}"));
        QVERIFY(!e.ok());
        QCOMPARE(e.error, u"the server refused the query: bad_data: parse error at char 3"_s);
    }

    /// Issue 44, point 5: the usual form is read straight from the bytes, and exactly as through a
    /// JSON document; any other form is left to the document.
    void theUsualFormIsReadAsTheGeneralReaderReadsIt_data()
    {
        QTest::addColumn<QByteArray>("json");
        QTest::addColumn<bool>("usual");
        QJsonArray result;
        const QList<std::pair<Labels, QString>> series {
            {link(u"a"_s, u"/x → x"_s, u"source"_s), u"10"_s},
            {link(u"a"_s, u"/ü → ü"_s, u"destination"_s), u"NaN"_s},
            {{}, u"-2.5e-3"_s}};
        for (const auto& [labels, value] : series)
            result.append(QJsonObject {{u"metric"_s, metric(labels)},
                                       {u"value"_s, QJsonArray {1732912345.125, value}}});
        const QJsonObject top {
            {u"status"_s, u"success"_s},
            {u"data"_s, QJsonObject {{u"resultType"_s, u"vector"_s}, {u"result"_s, result}}}};
        QTest::newRow("compact") << QJsonDocument(top).toJson(QJsonDocument::Compact) << true;
        QTest::newRow("indented") << QJsonDocument(top).toJson(QJsonDocument::Indented) << true;
        QTest::newRow("Prometheus's order")
            << j("{'status':'success','data':{'resultType':'matrix','result':["
                 "{'metric':{'host':'a'},'values':[[1,'1'],[2,'+Inf']]},"
                 "{'metric':{},'values':[]}]}}")
            << true;
        const auto vectorOf = [](const char* result) -> QByteArray {
            return j("{'status':'success','data':{'resultType':'vector','result':[") + j(result) + "]}}";
        };
        QTest::newRow("empty") << vectorOf("") << true;
        QTest::newRow("escape") << vectorOf("{'metric':{'host':'a\\'b'},'value':[1,'1']}") << false;
        QTest::newRow("warnings") << j("{'status':'success','warnings':['w'],'data':{'resultType':'vector',"
                                       "'result':[]}}")
                                  << false;
        QTest::newRow("bad value") << vectorOf(
            "{'metric':{},'value':[1,'1e999']},{'metric':{},'value':[1,'2']}")
                                   << false;
        QTest::newRow("kinds mixed") << vectorOf("{'metric':{},'values':[[1,'1']]}") << false;
        QTest::newRow("duplicate label") << vectorOf("{'metric':{'a':'1','a':'2'},'value':[1,'1']}") << false;
        QTest::newRow("error") << j("{'status':'error','errorType':'bad_data','error':'x'}") << false;
        QTest::newRow("garbage after") << QByteArray(vectorOf("") + " x") << false;
        QTest::newRow("not UTF-8") << vectorOf("{'metric':{'a':'\xff'},'value':[1,'1']}") << false;
        // Stop 57: whole numbers are read without the general conversion, and a time like the one
        // before is not read again; the results stay the document's.
        QTest::newRow("numbers") << vectorOf(
            "{'metric':{},'value':[1,'0']},{'metric':{},'value':[1,'-12']},"
            "{'metric':{},'value':[1.5,'123456789012345']},"
            "{'metric':{},'value':[1.5,'1234567890123456789']},"
            "{'metric':{},'value':[1,'-0']},{'metric':{},'value':[-2,'0.1']},"
            "{'metric':{},'value':[1e3,'1E2']},{'metric':{},'value':[1e3,'7']}")
                                 << true;
        QTest::newRow("leading zero")
            << vectorOf("{'metric':{},'value':[1,'1']},{'metric':{},'value':[1,'01']}") << false;
        QTest::newRow("a time like the last one") << vectorOf("{'metric':{},'value':[1,'1']},{'metric':{},"
                                                              "'value':[01,'1']}")
                                                  << false;
        // Stop 57: an object met again shares its labels; the same labels written otherwise are read.
        QTest::newRow("objects met again") << vectorOf(
            "{'metric':{'b':'2','a':'1'},'value':[1,'1']},{'metric':{'b':'2','a':'1'},'value':[1,'2']},"
            "{'metric':{ 'b':'2','a':'1'},'value':[1,'3']},{'metric':{'a':'1'},'value':[1,'4']}")
                                           << true;
        QTest::newRow("an object met again, then a duplicate")
            << vectorOf("{'metric':{'a':'1'},'value':[1,'1']},{'metric':{'a':'1','a':'1'},'value':[1,'2']}")
            << false;
    }

    void theUsualFormIsReadAsTheGeneralReaderReadsIt()
    {
        QFETCH(QByteArray, json);
        QFETCH(bool, usual);
        PrometheusAnswer fast;
        QCOMPARE(PrometheusAnswer::readUsual(json, &fast), usual);
        const PrometheusAnswer general = PrometheusAnswer::readGeneral(json);
        const PrometheusAnswer read = PrometheusAnswer::read(json);
        const auto print = [](const PrometheusAnswer& a) {
            QStringList lines {a.error, QString::number(a.badSamples), QString::number(a.droppedSeries),
                               QString::number(a.droppedPoints), a.warnings.join(u',')};
            for (const PrometheusAnswer::Series& s : a.series) {
                QStringList line;
                for (const auto& [name, value] : s.labels)
                    line << name + u'=' + value;
                line.sort();
                for (const PrometheusAnswer::Point& p : s.points)
                    line << QString::number(p.time, 'g', 17) + u'@' + QString::number(p.value, 'g', 17);
                lines << line.join(u' ');
            }
            return lines;
        };
        QCOMPARE(print(read), print(general));
        if (usual)
            QCOMPARE(print(fast), print(general));
        // With a pool, read twice: the second time every metric object is one met before.
        PrometheusLabelPool pool;
        for (int time = 0; time < 2; ++time) {
            PrometheusAnswer pooled;
            QCOMPARE(PrometheusAnswer::readUsual(json, &pooled, &pool), usual);
            if (usual)
                QCOMPARE(print(pooled), print(general));
            QCOMPARE(print(PrometheusAnswer::read(json, &pool)), print(general));
        }
    }

    /// Stop 57: the series of one metric object share one list of labels, within an answer and
    /// across the answers read with one pool; objects of other bytes have their own.
    void aMetricObjectMetAgainSharesItsLabels()
    {
        PrometheusLabelPool pool;
        const Labels labels = link(u"a"_s, u"/x → x"_s, u"source"_s);
        const PrometheusAnswer first = vector({{labels, u"1"_s}, {labels, u"2"_s}}, 1000, &pool);
        const PrometheusAnswer second
            = vector({{labels, u"3"_s}, {link(u"b"_s, u"/x → x"_s), u"4"_s}}, 1000, &pool);
        QCOMPARE(first.series.size(), 2);
        QCOMPARE(second.series.size(), 2);
        QVERIFY(first.series[0].labels.constData() == first.series[1].labels.constData());
        QVERIFY(first.series[0].labels.constData() == second.series[0].labels.constData());
        QVERIFY(first.series[0].labels.constData() != second.series[1].labels.constData());
        QCOMPARE(second.series[0].label(u"side"_s), u"source"_s);
        QCOMPARE(second.series[1].label(u"host"_s), u"b"_s);
        QCOMPARE(pool.lists(), 2);
        // Met again in the same order, each object after the first is the one that followed the
        // object before it last time; in another order, the hash finds the right ones.
        PrometheusLabelPool ordered;
        const QList<std::pair<Labels, QString>> three {{link(u"a"_s, u"/x → x"_s), u"1"_s},
                                                       {link(u"a"_s, u"/y → y"_s), u"2"_s},
                                                       {link(u"a"_s, u"/z → z"_s), u"3"_s}};
        vector(three, 1000, &ordered);
        const quint64 followed = ordered.followed();
        const PrometheusAnswer again = vector(three, 1000, &ordered);
        QCOMPARE(ordered.followed() - followed, quint64(2));
        QCOMPARE(again.series[2].label(u"link"_s), u"/z → z"_s);
        const PrometheusAnswer reordered = vector({three[2], three[0], three[1]}, 1000, &ordered);
        QCOMPARE(reordered.series[0].label(u"link"_s), u"/z → z"_s);
        QCOMPARE(reordered.series[1].label(u"link"_s), u"/x → x"_s);
        QCOMPARE(reordered.series[2].label(u"link"_s), u"/y → y"_s);
        QCOMPARE(ordered.lists(), 3);
        // Bounded with its strings: ever new objects never hold more than kMaxBytes.
        const QByteArray big(PrometheusAnswer::kMaxTextChars - 16, 'x');
        qsizetype most = 0;
        for (int i = 0; i * big.size() <= 2 * PrometheusLabelPool::kMaxBytes; ++i) {
            const QByteArray json = "{\"status\":\"success\",\"data\":{\"resultType\":\"vector\",\"result\":"
                                    "[{\"metric\":{\"a\":\""
                + QByteArray::number(i) + big + "\"},\"value\":[1,\"1\"]}]}}";
            QVERIFY(PrometheusAnswer::read(json, &pool).series.size() == 1);
            most = std::max(most, pool.lists());
        }
        QVERIFY2(most * 2 * big.size() <= PrometheusLabelPool::kMaxBytes, qPrintable(QString::number(most)));
    }

    void hostileAnswersAreCountedNotTrusted_data()
    {
        QTest::addColumn<QByteArray>("json");
        QTest::addColumn<bool>("ok");
        QTest::addColumn<int>("series");
        QTest::addColumn<int>("bad");
        QTest::newRow("not json") << QByteArray("<html>") << false << 0 << 0;
        QTest::newRow("array") << QByteArray("[1,2]") << false << 0 << 0;
        QTest::newRow("no status") << QByteArray(j("{'data':{}}")) << false << 0 << 0;
        QTest::newRow("result not array")
            << QByteArray(j("{'status':'success','data':{'resultType':'vector','result':7}}")) << false << 0
            << 0;
        QTest::newRow("unknown type")
            << QByteArray(j("{'status':'success','data':{'resultType':'string','result':[1,'x']}}")) << false
            << 0 << 0;
        QTest::newRow("value a number") << QByteArray(
            j("{'status':'success','data':{'resultType':'vector','result':[{'metric':{},'value':[1,3]}]}}"))
                                        << true << 0 << 1;
        QTest::newRow("value text") << QByteArray(j(
            "{'status':'success','data':{'resultType':'vector','result':[{'metric':{},'value':[1,'abc']}]}}"))
                                    << true << 0 << 1;
        QTest::newRow("huge number") << QByteArray(j("{'status':'success','data':{'resultType':'vector','"
                                                     "result':[{'metric':{},'value':[1,'1e999']}]}}"))
                                     << true << 0 << 1;
        QTest::newRow("label not string") << QByteArray(j("{'status':'success','data':{'resultType':'vector',"
                                                          "'result':[{'metric':{'a':1},'value':[1,'1']}]}}"))
                                          << true << 0 << 1;
        QTest::newRow("series not object")
            << QByteArray(j("{'status':'success','data':{'resultType':'vector','result':[null,'x',{'metric':{"
                            "},'value':[1,'2']}]}}"))
            << true << 1 << 2;
        QTest::newRow("matrix point short")
            << QByteArray(j("{'status':'success','data':{'resultType':'matrix','result':[{'metric':{},'"
                            "values':[[1],[2,'2'],'x']}]}}"))
            << true << 1 << 2;
        QTest::newRow("time nan") << QByteArray(j("{'status':'success','data':{'resultType':'vector','result'"
                                                  ":[{'metric':{},'value':['NaN','1']}]}}"))
                                  << true << 0 << 1;
    }
    void hostileAnswersAreCountedNotTrusted()
    {
        QFETCH(QByteArray, json);
        QFETCH(bool, ok);
        QFETCH(int, series);
        QFETCH(int, bad);
        const PrometheusAnswer a = PrometheusAnswer::read(json);
        QCOMPARE(a.ok(), ok);
        QCOMPARE(a.series.size(), series);
        QCOMPARE(a.badSamples, bad);
        if (!ok)
            QVERIFY(!a.error.isEmpty());
    }

    void seriesPastTheBoundAreCounted()
    {
        QByteArray json = j("{'status':'success','data':{'resultType':'vector','result':[");
        const qsizetype n = PrometheusAnswer::kMaxSeries + 7;
        for (qsizetype i = 0; i < n; ++i)
            json += (i ? "," : "") + QByteArray(j("{'metric':{'i':'")) + QByteArray::number(i)
                + j("'},'value':[1,'1']}");
        json += "]}}";
        const PrometheusAnswer a = PrometheusAnswer::read(json);
        QVERIFY(a.ok());
        QCOMPARE(a.series.size(), PrometheusAnswer::kMaxSeries);
        QCOMPARE(a.droppedSeries, 7);
    }

    void linkLabelsGiveTheTopics()
    {
        const LinkDef r = FleetSnapshotBuilder::linkDef(u"b"_s, u"/ros/t → mqtt/t"_s, u"ros2mqtt"_s);
        QCOMPARE(r.rosTopic, u"/ros/t"_s);
        QCOMPARE(r.mqttTopic, u"mqtt/t"_s);
        const LinkDef m = FleetSnapshotBuilder::linkDef(u"b"_s, u"mqtt/t → /ros/t"_s, u"mqtt2ros"_s);
        QCOMPARE(m.direction, Direction::Mqtt2Ros);
        QCOMPARE(m.rosTopic, u"/ros/t"_s);
        QCOMPARE(m.mqttTopic, u"mqtt/t"_s);
        QCOMPARE(m.name(), u"mqtt/t → /ros/t"_s);
        const LinkDef d = FleetSnapshotBuilder::linkDef(u"discovered"_s, u"only/mqtt"_s, u"ros2mqtt"_s);
        QVERIFY(d.discovered);
        QCOMPARE(d.mqttTopic, u"only/mqtt"_s);
    }

    void everyHostsLinksJudgedByTheLocalJudge()
    {
        QHash<QString, double> seen;
        WatchRules rules;
        rules.defaults[LinkRules::LatencyP99Ms] = Threshold {50, 200};
        const FleetSnapshot s = FleetSnapshotBuilder::build(twoHosts(), rules, 1000, &seen);
        QCOMPARE(s.links.size(), 5);
        QCOMPARE(s.hosts.size(), 2);
        QCOMPARE(s.hosts[0].name, u"a"_s);
        QVERIFY(s.hosts[0].reporting);
        QCOMPARE(s.hosts[0].version, u"1.2.3"_s);
        QVERIFY(!s.hosts[1].reporting);

        const FleetLink* x = find(s, u"a"_s, u"/x → x"_s);
        QVERIFY(x);
        QCOMPARE(x->figures.source.rateHz, 10.0);
        QCOMPARE(x->figures.source.messages, 1200u);
        QCOMPARE(x->figures.destination.messages, 1100u);
        QCOMPARE(x->figures.lost, 100u);
        QVERIFY(std::isnan(x->figures.latencyP99Ms));
        QCOMPARE(x->verdict.level, LinkLevel::Ok);
        QVERIFY(!x->verdict.unknown);
        QCOMPARE(x->def.rosTopic, u"/x"_s);

        const FleetLink* st = find(s, u"a"_s, u"/s → s"_s);
        QCOMPARE(st->verdict.level, LinkLevel::Alert);
        QCOMPARE(LinkJudge::reasonNames(st->verdict.reasons), QStringList {u"stall"_s});
        QVERIFY2(st->verdict.detail.startsWith(u"nothing arrived on s for "_s),
                 qPrintable(st->verdict.detail));

        const FleetLink* l = find(s, u"a"_s, u"/l → l"_s);
        QCOMPARE(l->figures.lossPercent, 10.0);
        QCOMPARE(l->verdict.level, LinkLevel::Alert);
        QCOMPARE(l->verdict.detail, u"10.0 % of the messages lost"_s);

        const FleetLink* p = find(s, u"a"_s, u"/p → p"_s);
        QCOMPARE(p->figures.latencyP99Ms, 300.0);
        QCOMPARE(p->figures.latencyP50Ms, 100.0);
        QCOMPARE(p->verdict.level, LinkLevel::Alert);
        QCOMPARE(p->verdict.detail, u"latency p99 300.0 ms"_s);

        const FleetLink* y = find(s, u"b"_s, u"/y → y"_s);
        QVERIFY(y);
        QVERIFY(!y->hostReporting);
        QVERIFY(y->verdict.unknown);
        QCOMPARE(y->verdict.level, LinkLevel::Ok);
        QCOMPARE(y->verdict.detail,
                 u"host stopped reporting since "_s
                     + QDateTime::fromSecsSinceEpoch(900).toString(u"HH:mm"_s));
        QCOMPARE(seen.value(u"a"_s), 1000.0);
        QCOMPARE(seen.value(u"b"_s), 900.0);
    }

    void aHostSeenBeforeThatVanishesStoppedReporting()
    {
        QHash<QString, double> seen;
        QHash<QString, PrometheusAnswer> answers = twoHosts();
        FleetSnapshotBuilder::build(answers, WatchRules(), 1000, &seen);
        // Host a's series are gone now (its watch stopped), and the server forgot the hour.
        answers[u"info"_s] = vector({});
        answers[u"state"_s] = vector({});
        answers[u"lastSeen"_s] = vector({});
        const FleetSnapshot s = FleetSnapshotBuilder::build(answers, WatchRules(), 1060, &seen);
        QCOMPARE(s.hosts.size(), 2);
        QVERIFY(!s.hosts[0].reporting);
        QCOMPARE(s.hosts[0].lastSeen, 1000.0);
        const FleetLink* x = find(s, u"a"_s, u"/x → x"_s);
        QVERIFY(x);
        QVERIFY(x->verdict.unknown);
        QVERIFY(x->verdict.detail.startsWith(u"host stopped reporting since "_s));
        for (const FleetLink& l : s.links)
            QVERIFY2(l.verdict.unknown, qPrintable(l.key()));
    }

    void linksNoLongerServedAreDroppedBridgeDownIsSaid()
    {
        QHash<QString, double> seen;
        QHash<QString, PrometheusAnswer> answers = twoHosts();
        answers[u"state"_s] = vector({{link(u"a"_s, u"/x → x"_s), u"0"_s}});
        answers[u"bridges"_s] = vector({{{{u"host"_s, u"a"_s}, {u"bridge"_s, u"bridge1"_s}}, u"0"_s}});
        const FleetSnapshot s = FleetSnapshotBuilder::build(answers, WatchRules(), 1000, &seen);
        QCOMPARE(s.links.size(), 2); // a's /x and b's /y
        const FleetLink* x = find(s, u"a"_s, u"/x → x"_s);
        QVERIFY(x->bridgeDown);
        QCOMPARE(x->verdict.level, LinkLevel::Alert);
        QCOMPARE(x->verdict.detail, u"the bridge bridge1 on a is down"_s);
    }

    void hostileFiguresNeverJudgeOk()
    {
        QHash<QString, double> seen;
        QHash<QString, PrometheusAnswer> answers = twoHosts();
        answers[u"recent"_s] = vector({{link(u"a"_s, u"/x → x"_s, u"source"_s), u"-5"_s},
                                       {link(u"a"_s, u"/x → x"_s, u"destination"_s), u"NaN"_s}});
        answers[u"messages"_s] = vector({{link(u"a"_s, u"/x → x"_s, u"source"_s), u"1e300"_s}});
        answers[u"seen"_s] = vector({{link(u"a"_s, u"/s → s"_s), u"0"_s}});
        const FleetSnapshot s = FleetSnapshotBuilder::build(answers, WatchRules(), 1000, &seen);
        const FleetLink* x = find(s, u"a"_s, u"/x → x"_s);
        QCOMPARE(x->figures.source.rateHz, 0.0);
        QCOMPARE(x->figures.destination.rateHz, 0.0);
        QVERIFY(x->figures.source.messages > 0);
        const FleetLink* st = find(s, u"a"_s, u"/s → s"_s);
        QVERIFY(st->verdict.unknown);
        QCOMPARE(st->verdict.detail, u"unknown (the watch on a cannot see both sides)"_s);
    }

    /// A link slower than one message in the watch's 5 s: its 5-s rate is 0, the minute's mean is
    /// not. The table shows the minute's mean, the window of the history's chart (it showed 0.0
    /// beside a chart of 0.5 Hz).
    void aSlowLinkShowsTheRateOfTheChartsWindow()
    {
        QHash<QString, double> seen;
        QHash<QString, PrometheusAnswer> answers = twoHosts();
        answers[u"rate"_s] = vector({{link(u"a"_s, u"/x → x"_s, u"source"_s), u"0"_s},
                                     {link(u"a"_s, u"/x → x"_s, u"destination"_s), u"0"_s}});
        answers[u"recent"_s] = vector({{link(u"a"_s, u"/x → x"_s, u"source"_s), u"30"_s},
                                       {link(u"a"_s, u"/x → x"_s, u"destination"_s), u"30"_s}});
        const FleetSnapshot s = FleetSnapshotBuilder::build(answers, WatchRules(), 1000, &seen);
        const FleetLink* x = find(s, u"a"_s, u"/x → x"_s);
        QCOMPARE(x->figures.source.rateHz, 0.5);
        QCOMPARE(x->figures.destination.rateHz, 0.5);
        // One window for both: the snapshot's increase and the history's rate.
        QCOMPARE(FleetSnapshotBuilder::rateRange(), u"[60s]"_s);
        bool recentInWindow = false;
        for (const auto& [name, promql] : FleetSnapshotBuilder::queries())
            recentInWindow |= name == "recent"_L1
                && promql.contains(u"increase(bridgescope_link_messages_total"_s
                                   + FleetSnapshotBuilder::rateRange() + u')');
        QVERIFY(recentInWindow);
    }

    /// A discovered link knows only its MQTT topic: it has no source side, so no source rate (NaN,
    /// shown "–"), never 0.
    void aDiscoveredLinkHasNoSourceRate()
    {
        QHash<QString, double> seen;
        QHash<QString, PrometheusAnswer> answers = twoHosts();
        const QString name = u"only/mqtt"_s;
        for (const QString& query : {u"links"_s, u"state"_s})
            answers[query].series.append(vector({{link(u"a"_s, name), u"0"_s}}).series);
        answers[u"rate"_s].series.append(vector({{link(u"a"_s, name, u"source"_s), u"0"_s},
                                                 {link(u"a"_s, name, u"destination"_s), u"2"_s}})
                                             .series);
        answers[u"recent"_s].series.append(vector({{link(u"a"_s, name, u"source"_s), u"0"_s},
                                                   {link(u"a"_s, name, u"destination"_s), u"120"_s}})
                                               .series);
        const FleetSnapshot s = FleetSnapshotBuilder::build(answers, WatchRules(), 1000, &seen);
        const FleetLink* d = find(s, u"a"_s, name);
        QVERIFY(d);
        QVERIFY(d->def.discovered);
        QVERIFY2(std::isnan(d->figures.source.rateHz), qPrintable(QString::number(d->figures.source.rateHz)));
        QCOMPARE(d->figures.destination.rateHz, 2.0);
    }

    void urlsAreCheckedSchemesRefused()
    {
        QCOMPARE(PrometheusClient::checkUrl(u"http://127.0.0.1:9090/"_s)->toString(),
                 u"http://127.0.0.1:9090"_s);
        QCOMPARE(PrometheusClient::checkUrl(u"https://lab/prometheus"_s)->toString(),
                 u"https://lab/prometheus"_s);
        QVERIFY(!PrometheusClient::checkUrl(u"ftp://lab:9090"_s).ok());
        QVERIFY(!PrometheusClient::checkUrl(u"file:///etc/passwd"_s).ok());
        QVERIFY(!PrometheusClient::checkUrl(u"http://user:secret@lab:9090"_s).ok());
        QVERIFY(!PrometheusClient::checkUrl(u"http://lab:9090/?x=1"_s).ok());
        QVERIFY(!PrometheusClient::checkUrl(u""_s).ok());
        QCOMPARE(PrometheusClient::quoted(u"a\"b\\c\nd"_s), u"\"a\\\"b\\\\c\\nd\""_s);
    }

    void anAnswerPastItsSizeIsRefused()
    {
        TinyServer server;
        QByteArray body = j("{'status':'success','data':{'resultType':'vector','result':[");
        body += QByteArray(4000, ' ') + "]}}";
        server.answer = http(body);
        PrometheusClient client;
        client.setServer(server.url());
        client.setMaxAnswerBytes(1000);
        const PrometheusAnswer a = ask(client);
        QVERIFY(!a.ok());
        QVERIFY2(a.error.startsWith(u"the answer is larger than"_s), qPrintable(a.error));
        client.setMaxAnswerBytes(PrometheusClient::kMaxAnswerBytes);
        const PrometheusAnswer b = ask(client);
        QVERIFY2(b.ok(), qPrintable(b.error));
        QCOMPARE(client.failures(), 1u);
    }

    /// A server that answers every query of a refresh with more than 32 MiB (announced, or endless):
    /// each answer is refused at its budget, counted, the refresh says so, and this process's
    /// memory stays bounded while the whole refresh is refused.
    void aHugeOrEndlessAnswerIsRefusedAtItsBudget_data() { floodRows("48 MiB announced", "endless"); }
    void aHugeOrEndlessAnswerIsRefusedAtItsBudget()
    {
        QFETCH(bool, endless);
        FloodServer server(endless);
        FleetSource source;
        source.setServer(server.url());
        // Each answer's budget is under test, not the one of all in flight (see below).
        source.client()->setMaxInFlightBytes(std::numeric_limits<qint64>::max());
        const qint64 grew = refreshFlooded(source, server);
        QVERIFY(grew >= 0);
        const qint64 queries = FleetSnapshotBuilder::queries().size();
        QCOMPARE(source.client()->failures(), quint64(queries));
        QCOMPARE(source.refreshes(), 1u);
        QVERIFY2(source.error().startsWith(u"cannot read the fleet from %1: "_s.arg(server.url().toString())),
                 qPrintable(source.error()));
        QVERIFY2(source.error().endsWith(u"the answer is larger than 32 MiB: refused"_s),
                 qPrintable(source.error()));
        QVERIFY(source.snapshot().links.isEmpty());
        // An endless answer is read up to its budget: at most `kParallel` budgets at a time (a
        // QByteArray grows by half again) and the buffers on the way. One that announces more
        // than its budget is refused before its body is read: the buffers only.
        constexpr qint64 kParallel = 6; // QNetworkAccessManager's connections to one host
        const qint64 buffers = qint64(32) << 20;
        const qint64 bound
            = endless ? kParallel * PrometheusClient::kMaxAnswerBytes * 3 / 2 + buffers : buffers;
        if (endless)
            QVERIFY2(server.most >= PrometheusClient::kMaxAnswerBytes,
                     "the budget was reached, not a short read");
        // A refused answer's connection is closed: the server cannot go on sending on it.
        QVERIFY2(server.most < PrometheusClient::kMaxAnswerBytes + sentPastWhatWasRead(),
                 qPrintable(u"%1 MiB sent on one connection"_s.arg(server.most >> 20)));
        QVERIFY2(grew < bound + PeakRss::kSanitizerSlack,
                 qPrintable(u"peak RSS grew by %1 MiB, bound %2 MiB"_s.arg(grew >> 20).arg(bound >> 20)));
    }

    /// Issue 44, fourth stop: a refresh's answers are read with one label pool, and a series finds
    /// its link by its strings' data. The snapshot is the one of answers read each on its own (the
    /// strings' text decides, the data only finds it sooner).
    void answersOfOnePoolGiveTheSnapshotOfSeparateOnes()
    {
        PrometheusLabelPool pool;
        const QHash<QString, PrometheusAnswer> pooled = twoHosts(&pool);
        const auto linkOf = [&](const QString& answer) -> const QString& {
            for (const PrometheusAnswer::Label& l : pooled[answer].series.constFirst().labels)
                if (l.first == "link"_L1)
                    return l.second;
            Q_UNREACHABLE();
        };
        QVERIFY2(linkOf(u"state"_s).constData() == linkOf(u"rate"_s).constData(),
                 "the answers share the link's string");
        QHash<QString, double> seen, seenPooled;
        const FleetSnapshot separate = FleetSnapshotBuilder::build(twoHosts(), WatchRules(), 1000, &seen);
        const FleetSnapshot shared = FleetSnapshotBuilder::build(pooled, WatchRules(), 1000, &seenPooled);
        QCOMPARE(separate.links.size(), 5);
        QCOMPARE(printed(shared), printed(separate));
    }

    /// Issue 44, fourth stop: the per-link answers carry only the series that say more than their
    /// absence (a loss or stall count above 0, a quantile that is a number, a link not seen), and
    /// the snapshot is the one of the whole answers.
    void seriesThatSayWhatTheirAbsenceSaysAreNotAsked()
    {
        QHash<QString, PrometheusAnswer> whole = twoHosts();
        whole[u"stalls"_s]
            = vector({{link(u"a"_s, u"/x → x"_s), u"0"_s}, {link(u"a"_s, u"/s → s"_s), u"2"_s}});
        whole[u"seen"_s].series.append(vector({{link(u"b"_s, u"/y → y"_s), u"0"_s}}).series);
        QHash<QString, PrometheusAnswer> asked = whole;
        const auto keep = [&](const QString& name, bool (*kept)(double)) {
            QList<PrometheusAnswer::Series>& series = asked[name].series;
            series.removeIf(
                [kept](const PrometheusAnswer::Series& x) { return !kept(x.points.constLast().value); });
        };
        for (const QString& count : {u"lost"_s, u"stalls"_s, u"recentLost"_s})
            keep(count, [](double v) { return v > 0; });
        for (const QString& quantile : {u"p50"_s, u"p99"_s})
            keep(quantile, [](double v) { return v >= 0; });
        keep(u"seen"_s, [](double v) { return v == 0; });
        QCOMPARE(asked[u"recentLost"_s].series.size(), 1);
        QCOMPARE(asked[u"seen"_s].series.size(), 1);
        QHash<QString, double> seen, seenAsked;
        QCOMPARE(printed(FleetSnapshotBuilder::build(asked, WatchRules(), 1000, &seenAsked)),
                 printed(FleetSnapshotBuilder::build(whole, WatchRules(), 1000, &seen)));
        // And the queries ask so.
        QHash<QString, QString> promql;
        for (const auto& [name, query] : FleetSnapshotBuilder::queries())
            promql.insert(name, query);
        for (const QString& count : {u"lost"_s, u"stalls"_s, u"recentLost"_s})
            QVERIFY2(promql[count].endsWith(u") > 0"_s), qPrintable(promql[count]));
        for (const QString& quantile : {u"p50"_s, u"p99"_s})
            QVERIFY2(promql[quantile].endsWith(u") >= 0"_s), qPrintable(promql[quantile]));
        QVERIFY2(promql[u"seen"_s].endsWith(u") == 0"_s), qPrintable(promql[u"seen"_s]));
        for (const QString& perSide : {u"rate"_s, u"recent"_s, u"messages"_s, u"bytes"_s})
            QVERIFY2(promql[perSide].endsWith(u')'), qPrintable(promql[perSide]));
    }

    void theLabelPoolSharesStringsWithinItsBound()
    {
        PrometheusLabelPool pool;
        const QString a = pool.intern("host");
        const QString b = pool.intern(QByteArray("host"));
        QCOMPARE(b, u"host"_s);
        QVERIFY(a.constData() == b.constData());
        QCOMPARE(pool.size(), 1);
        const QByteArray big(PrometheusAnswer::kMaxTextChars, 'x');
        for (qsizetype i = 0; i * big.size() <= PrometheusLabelPool::kMaxBytes; ++i)
            pool.intern(QByteArray(QByteArray::number(i) + big));
        QVERIFY2(pool.size() * big.size() <= PrometheusLabelPool::kMaxBytes,
                 qPrintable(QString::number(pool.size())));
        QCOMPARE(pool.intern("host"), u"host"_s);
    }

    /// Issue 44, fourth stop: the totals (`messages`, `bytes`) are asked at the first refresh and
    /// again once kTotalsSeconds old; a refresh between asks the other 13 queries and keeps the
    /// totals it has.
    void theTotalsAreAskedOnlyOnceTheyAreOld()
    {
        OneLinkServer server;
        FleetSource source;
        source.setServer(server.url());
        QSignalSpy refreshed(&source, &FleetSource::refreshed);
        const auto refresh = [&] {
            const int before = server.requests;
            source.refresh();
            if (!refreshed.wait(20000) || !source.error().isEmpty())
                return -1;
            return server.requests - before;
        };
        const int all = int(FleetSnapshotBuilder::queries().size());
        QCOMPARE(refresh(), all);
        QCOMPARE(source.snapshot().links.size(), 1);
        QCOMPARE(source.snapshot().links[0].figures.source.messages, 7u);
        QCOMPARE(source.snapshot().links[0].figures.source.bytes, 7u);
        QCOMPARE(source.snapshot().links[0].figures.lost, 7u);
        server.value = "9";
        QCOMPARE(refresh(), all - 2);
        QCOMPARE(source.snapshot().links[0].figures.lost, 9u); // the others are new
        QCOMPARE(source.snapshot().links[0].figures.source.messages, 7u); // the totals kept
        QCOMPARE(source.snapshot().links[0].figures.source.bytes, 7u);
        QVERIFY(source.snapshot().links[0].verdict.unknown == false);
        source.setTotalsSeconds(0);
        QCOMPARE(refresh(), all);
        QCOMPARE(source.snapshot().links[0].figures.source.messages, 9u);
        QCOMPARE(source.snapshot().links[0].figures.source.bytes, 9u);
    }

    /// The answers of a refresh in flight together are bounded, not only each: a server that
    /// floods every parallel query endlessly gets the refresh refused at the total budget, within
    /// it in memory.
    void theAnswersInFlightAreBoundedTogether()
    {
        FloodServer server(true);
        FleetSource source;
        source.setServer(server.url());
        constexpr qint64 kTotal = qint64(8) << 20;
        source.client()->setMaxInFlightBytes(kTotal);
        const qint64 grew = refreshFlooded(source, server);
        QVERIFY(grew >= 0);
        QCOMPARE(source.client()->failures(), quint64(FleetSnapshotBuilder::queries().size()));
        QVERIFY2(source.error().endsWith(u"the answers in flight are larger than 8 MiB together: refused"_s),
                 qPrintable(source.error()));
        QCOMPARE(source.client()->inFlightBytes(), 0);
        QCOMPARE(source.client()->inFlight(), 0);
        // Refused answers' connections are closed at once, not read on while their abort waits
        // (Qt's network thread read an endless one at 750 MB/s for a minute, without a read-ahead).
        QVERIFY2(server.most < kTotal + sentPastWhatWasRead(),
                 qPrintable(u"%1 MiB sent on one connection"_s.arg(server.most >> 20)));
        // The bodies held: the total budget (a QByteArray grows by half again), and the buffers.
        const qint64 bound = kTotal * 3 / 2 + (qint64(32) << 20);
        QVERIFY2(grew < bound + PeakRss::kSanitizerSlack,
                 qPrintable(u"peak RSS grew by %1 MiB, bound %2 MiB"_s.arg(grew >> 20).arg(bound >> 20)));
    }

    /// A refused answer's connection is not used again: the server kept it alive but reads no
    /// second request on it, and the next query is answered at once, not after its time budget.
    void theNextQueryDoesNotWaitOnARefusedAnswersConnection_data()
    {
        floodRows("refused by its announced length", "refused in the middle of its body");
    }
    void theNextQueryDoesNotWaitOnARefusedAnswersConnection()
    {
        QFETCH(bool, endless);
        FloodServer server(endless, true);
        PrometheusClient client;
        client.setServer(server.url());
        client.setMaxAnswerBytes(qint64(4) << 20);
        client.setTimeoutMs(60000);
        const PrometheusAnswer refused = ask(client);
        QVERIFY2(refused.error.startsWith(u"the answer is larger than 4 MiB"_s), qPrintable(refused.error));
        QElapsedTimer took;
        took.start();
        const PrometheusAnswer next = ask(client);
        QVERIFY2(next.ok(), qPrintable(next.error));
        QVERIFY2(took.elapsed() < 5000, qPrintable(u"the next query took %1 ms"_s.arg(took.elapsed())));
        QCOMPARE(server.connections, 2);
    }

    void aSilentServerTimesOutAnAbsentOneIsSaid()
    {
        TinyServer server;
        server.silent = true;
        PrometheusClient client;
        client.setServer(server.url());
        client.setTimeoutMs(300);
        const PrometheusAnswer a = ask(client);
        QCOMPARE(a.error, u"no answer within 0.3 s"_s);
        const quint16 port = server.serverPort();
        server.close();
        client.setServer(QUrl(u"http://127.0.0.1:%1"_s.arg(port)));
        const PrometheusAnswer b = ask(client);
        QVERIFY(!b.ok());
        QVERIFY2(b.error.contains(u"refused"_s), qPrintable(b.error));
    }

    void basicAuthIsSentOnlyInTheHeader()
    {
        QTcpServer server;
        QVERIFY(server.listen(QHostAddress::LocalHost));
        QByteArray request;
        connect(&server, &QTcpServer::newConnection, this, [&] {
            QTcpSocket* s = server.nextPendingConnection();
            connect(s, &QTcpSocket::readyRead, s, [&request, s] {
                request += s->readAll();
                if (request.contains("up") || request.contains("query="))
                    s->write(http(j("{'status':'success','data':{'resultType':'vector','result':[]}}")));
            });
        });
        PrometheusClient client;
        client.setServer(QUrl(u"http://127.0.0.1:%1"_s.arg(server.serverPort())), u"lab"_s, u"s3cret"_s);
        const PrometheusAnswer a = ask(client);
        QVERIFY2(a.ok(), qPrintable(a.error));
        const QByteArray header = "Authorization: Basic " + QByteArray("lab:s3cret").toBase64();
        QVERIFY(request.contains(header));
        QVERIFY(!request.contains("s3cret"));
        QVERIFY(request.startsWith("POST /api/v1/query "));
    }
};

QTEST_GUILESS_MAIN(TestFleetSnapshot)
#include "tst_fleetsnapshot.moc"
