// SPDX-License-Identifier: MIT
// What `watch --metrics` serves: both exposition formats, checked by Prometheus' own promtool and
// by the rules of OpenMetrics; the format a scraper's Accept header asks for; and the HTTP server
// against bad, oversized, idle and many clients on loopback.
#include "resulttext.h"
#include "testservers.h"
#include "watch/metricsserver.h"

#include <arpa/inet.h>
#include <atomic>
#include <deque>
#include <netinet/in.h>
#include <QElapsedTimer>
#include <QProcess>
#include <QRegularExpression>
#include <QSet>
#include <QTcpSocket>
#include <QTest>
#include <sys/socket.h>
#include <thread>
#include <unistd.h>

using namespace Qt::StringLiterals;

namespace {
MetricsSnapshot twoLinks()
{
    using MetricsExposition::label;
    MetricsSnapshot s;
    s.ownLabels = label("host", "vehicle-3") + ',' + label("site", "garage");
    s.version = "9.9.9";
    MetricsSnapshot::Link a;
    a.labels = s.ownLabels + ',' + label("bridge", "vehicle") + ',' + label("link", "/a → a") + ','
        + label("direction", "ros2mqtt");
    a.stage = label("stage", "bridge");
    a.sourceMessages = 120;
    a.destinationMessages = 118;
    a.sourceBytes = 12e9; // beyond 32 bits
    a.destinationBytes = 11.8e9;
    a.lost = 2;
    a.seqGaps = 2;
    a.hasSeqGaps = true;
    a.sourceRate = 9.75;
    a.destinationRate = 9.5;
    a.state = 1;
    a.hasLatency = true;
    a.buckets[2] = 1; // <= 0.5 ms
    a.buckets[6] = 2; // <= 10 ms
    a.latencyCount = 4; // one above 10 s
    a.latencySum = 11.02;
    s.links.push_back(a);
    MetricsSnapshot::Link b;
    // A hostile topic name: quotes, a backslash, a newline and UTF-8 stay one label value.
    b.labels = s.ownLabels + ',' + label("bridge", "lab") + ',' + label("link", "b → /b\"\\\n/ü") + ','
        + label("direction", "mqtt2ros");
    s.links.push_back(b);
    s.bridges.push_back({s.ownLabels + ',' + label("bridge", "vehicle"), true});
    return s;
}

QByteArray body(const QByteArray& answer)
{
    const qsizetype at = answer.indexOf("\r\n\r\n");
    return at < 0 ? QByteArray() : answer.mid(at + 4);
}
} // namespace

class TestMetricsServer : public QObject
{
    Q_OBJECT
private slots:
    void textFormatPassesPromtool()
    {
        const QByteArray text = MetricsExposition::write(twoLinks(), MetricsFormat::Text);
        QProcess promtool;
        promtool.start(u"promtool"_s, {u"check"_s, u"metrics"_s});
        QVERIFY2(promtool.waitForStarted(5000), "promtool (Debian package prometheus) is needed");
        promtool.write(text);
        promtool.closeWriteChannel();
        QVERIFY(promtool.waitForFinished(30000));
        const QString said
            = QString::fromUtf8(promtool.readAllStandardOutput() + promtool.readAllStandardError());
        QVERIFY2(promtool.exitCode() == 0, qPrintable(said + u"\n"_s + QString::fromUtf8(text)));

        QVERIFY(text.contains("# TYPE bridgescope_link_messages_total counter\n"));
        QVERIFY(text.contains(
            "bridgescope_link_messages_total{host=\"vehicle-3\",site=\"garage\",bridge=\"vehicle\","
            "link=\"/a → a\",direction=\"ros2mqtt\",side=\"source\"} 120\n"));
        QVERIFY(text.contains(",side=\"source\"} 12000000000\n"));
        QVERIFY(text.contains("bridgescope_link_rate_hz{") && text.contains("} 9.75\n"));
        QVERIFY(text.contains("link=\"b → /b\\\"\\\\\\n/ü\""));
        // Cumulative buckets from 0.1 ms; +Inf is the count. The stage only on the histogram.
        QVERIFY(text.contains("direction=\"ros2mqtt\",stage=\"bridge\",le=\"0.0001\"} 0\n"));
        QVERIFY(text.contains(",le=\"0.00025\"} 0\n"));
        QVERIFY(text.contains(",le=\"0.0005\"} 1\n"));
        QVERIFY(text.contains(",le=\"0.005\"} 1\n"));
        QVERIFY(text.contains(",le=\"0.01\"} 3\n"));
        QVERIFY(text.contains(",le=\"10.0\"} 3\n"));
        QVERIFY(text.contains(",le=\"+Inf\"} 4\n"));
        QVERIFY(text.contains("bridgescope_link_latency_seconds_sum{") && text.contains("} 11.02\n"));
        // Only the link with gaps has the gap counter; the link without stamps has no histogram.
        QCOMPARE(text.count("bridgescope_link_seq_gaps_total{"), 1);
        QCOMPARE(text.count("bridgescope_link_latency_seconds_count{"), 1);
        QVERIFY(text.contains(
            "bridgescope_bridge_up{host=\"vehicle-3\",site=\"garage\",bridge=\"vehicle\"} 1\n"));
        QCOMPARE(text.count("stage="), 17 + 2);
        // The watch's own figures carry its labels too, and the info says which watch it is.
        QVERIFY(text.contains(
            "bridgescope_watch_info{host=\"vehicle-3\",site=\"garage\",version=\"9.9.9\"} 1\n"));
        QVERIFY(text.contains("bridgescope_metrics_truncated{host=\"vehicle-3\",site=\"garage\"} 0\n"));
        QVERIFY(!text.contains("# EOF"));
    }

    // OpenMetrics 1.0: a counter family is named without _total and its samples with it, samples of a
    // family stand together, every line is a comment or a sample, and # EOF ends it.
    void openMetricsFollowsItsRules()
    {
        const QByteArray om = MetricsExposition::write(twoLinks(), MetricsFormat::OpenMetrics);
        QVERIFY(om.endsWith("\n# EOF\n"));
        QVERIFY(om.contains("# TYPE bridgescope_link_messages counter\n"));
        QVERIFY(om.contains("# TYPE bridgescope_link_latency_seconds histogram\n"));
        QVERIFY(om.contains("bridgescope_link_messages_total{"));
        const QList<QByteArray> lines = om.split('\n');
        QHash<QByteArray, QByteArray> typeOf;
        QSet<QByteArray> closed; // families whose samples have ended
        QByteArray current;
        static const QRegularExpression sampleLine(
            u"^([a-z_]+)(\\{([a-z_]+=\"([^\"\\\\]|\\\\.)*\",?)*\\})? (-?[0-9.e+]+|NaN|\\+Inf)$"_s);
        for (const QByteArray& line : lines) {
            if (line.isEmpty() || line == "# EOF")
                continue;
            if (line.startsWith("# TYPE ")) {
                const QList<QByteArray> parts = line.split(' ');
                typeOf.insert(parts[2], parts[3]);
                QVERIFY2(!parts[2].endsWith("_total"), line.constData());
                continue;
            }
            if (line.startsWith("# HELP "))
                continue;
            QVERIFY2(sampleLine.match(QString::fromUtf8(line)).hasMatch(), line.constData());
            const QByteArray name = line.left(line.indexOf(line.contains('{') ? '{' : ' '));
            QByteArray family;
            for (auto it = typeOf.cbegin(); it != typeOf.cend(); ++it)
                if (name == it.key()
                    || (name.startsWith(QByteArray(it.key() + '_')) && it.key().size() > family.size()))
                    family = it.key();
            QVERIFY2(!family.isEmpty(), line.constData());
            if (typeOf.value(family) == "counter")
                QVERIFY2(name == family + "_total", line.constData());
            if (family != current) {
                QVERIFY2(!closed.contains(family), family.constData());
                if (!current.isEmpty())
                    closed.insert(current);
                current = family;
            }
        }
        // 12 of the links and bridges (bridgescope_link_seen since issue 40, the observed hop latency
        // and its lost since issue 45), 5 of the answer and the history budgets, 3 of the announced
        // ones, the watch's info (issue 44)
        QCOMPARE(typeOf.size(), 21);
    }

    void theScraperChoosesTheFormat()
    {
        using MetricsExposition::negotiate;
        // What Prometheus 2.x sends by default.
        QCOMPARE(negotiate("application/openmetrics-text;version=1.0.0,application/openmetrics-text;"
                           "version=0.0.1;q=0.75,text/plain;version=0.0.4;q=0.5,*/*;q=0.1"),
                 MetricsFormat::OpenMetrics);
        QCOMPARE(negotiate(""), MetricsFormat::Text);
        QCOMPARE(negotiate("text/plain"), MetricsFormat::Text);
        QCOMPARE(negotiate("*/*"), MetricsFormat::Text);
        QCOMPARE(negotiate("text/plain;q=0.9, application/openmetrics-text;q=0.5"), MetricsFormat::Text);
        QCOMPARE(negotiate("application/openmetrics-text;version=0.0.1"), MetricsFormat::Text);
        QCOMPARE(negotiate("application/openmetrics-text;q=0"), MetricsFormat::Text);
        QCOMPARE(negotiate(QByteArray(100000, ';')), MetricsFormat::Text);
    }

    void hostAndPort()
    {
        Result<MetricsServer::Endpoint> e = MetricsServer::parseHostPort(u"127.0.0.1:9464"_s);
        QVERIFY(e);
        QCOMPARE(e->address, QHostAddress(QHostAddress::LocalHost));
        QCOMPARE(e->port, quint16(9464));
        e = MetricsServer::parseHostPort(u"[::1]:0"_s);
        QVERIFY(e);
        QCOMPARE(e->address, QHostAddress(QHostAddress::LocalHostIPv6));
        e = MetricsServer::parseHostPort(u":9464"_s);
        QVERIFY(e);
        QCOMPARE(e->address, QHostAddress(QHostAddress::Any));
        QString error;
        for (const QString& bad :
             {u"9464"_s, u"127.0.0.1:"_s, u"127.0.0.1:70000"_s, u"example.org:80"_s, u"127.0.0.1:-1"_s})
            QVERIFY2(!noted(MetricsServer::parseHostPort(bad), &error) && error.contains(bad),
                     qPrintable(bad));
        QVERIFY(!noted(MetricsServer::listen(u"256.0.0.1:0"_s), &error));
        // A port in use is said, not a crash.
        const std::unique_ptr<MetricsServer> first
            = noted(MetricsServer::listen(u"127.0.0.1:0"_s), &error).value_or(nullptr);
        QVERIFY2(first, qPrintable(error));
        QVERIFY(!noted(MetricsServer::listen(u"127.0.0.1:%1"_s.arg(first->port())), &error));
        QVERIFY2(error.contains(u"cannot serve metrics"_s), qPrintable(error));
    }

    void servesOverHttp()
    {
        QString error;
        const std::unique_ptr<MetricsServer> server
            = noted(MetricsServer::listen(u"127.0.0.1:0"_s), &error).value_or(nullptr);
        QVERIFY2(server, qPrintable(error));
        const quint16 port = server->port();
        QVERIFY(port > 0);
        // Before anything is published: an empty exposition, not an error.
        QByteArray answer = TestServers::httpRequest(port, "GET /metrics HTTP/1.1\r\nHost: x\r\n\r\n");
        QVERIFY2(answer.startsWith("HTTP/1.1 200 OK\r\n"), answer.constData());
        QVERIFY(body(answer).contains("# TYPE bridgescope_link_messages_total counter"));

        server->publish(std::make_shared<MetricsSnapshot>(twoLinks()));
        answer
            = TestServers::httpRequest(port,
                                       "GET /metrics?x=1 HTTP/1.1\r\nAccept: application/openmetrics-text; "
                                       "version=1.0.0\r\n\r\n");
        QVERIFY(
            answer.contains("Content-Type: application/openmetrics-text; version=1.0.0; charset=utf-8\r\n"));
        QCOMPARE(body(answer), MetricsExposition::write(twoLinks(), MetricsFormat::OpenMetrics));
        const QByteArray text = TestServers::httpRequest(port, "GET /metrics HTTP/1.0\r\n\r\n");
        QVERIFY(text.contains("Content-Type: text/plain; version=0.0.4; charset=utf-8\r\n"));
        const QByteArray length = "Content-Length: "
            + QByteArray::number(MetricsExposition::write(twoLinks(), MetricsFormat::Text).size()) + "\r\n";
        QVERIFY(text.contains(length));
        const QByteArray head = TestServers::httpRequest(port, "HEAD /metrics HTTP/1.1\r\n\r\n");
        QVERIFY(head.startsWith("HTTP/1.1 200") && body(head).isEmpty());
        QVERIFY(TestServers::httpRequest(port, "GET / HTTP/1.1\r\n\r\n").contains("/metrics"));

        QVERIFY(TestServers::httpRequest(port, "GET /other HTTP/1.1\r\n\r\n").startsWith("HTTP/1.1 404"));
        QVERIFY(TestServers::httpRequest(port, "POST /metrics HTTP/1.1\r\n\r\n").startsWith("HTTP/1.1 405"));
        QVERIFY(TestServers::httpRequest(port, "nonsense\r\n\r\n").startsWith("HTTP/1.1 400"));
        QVERIFY(TestServers::httpRequest(port, "GET /metrics SMTP\r\n\r\n").startsWith("HTTP/1.1 400"));
        QVERIFY(TestServers::httpRequest(port,
                                         "GET /metrics HTTP/1.1\r\nX: " + QByteArray(20000, 'a') + "\r\n\r\n")
                    .startsWith("HTTP/1.1 431"));
        QVERIFY(TestServers::httpRequest(port, QByteArray(100000, '\0')).startsWith("HTTP/1.1 431"));
        QCOMPARE(server->served(), quint64(4)); // the scrapes of /metrics
    }

    /// Lines may end in a bare LF (RFC 9112 allows it), a blank line may come first, and the target may
    /// be an absolute URI (a proxy's, some scrapers'): all are answered, not left waiting or 404.
    void leniantHeadsAreAnswered()
    {
        QString error;
        const std::unique_ptr<MetricsServer> server
            = noted(MetricsServer::listen(u"127.0.0.1:0"_s), &error).value_or(nullptr);
        QVERIFY2(server, qPrintable(error));
        server->publish(std::make_shared<MetricsSnapshot>(twoLinks()));
        const QByteArray want = MetricsExposition::write(twoLinks(), MetricsFormat::Text);
        const QByteArray port = QByteArray::number(server->port());
        const QList<QByteArray> requests {"GET /metrics HTTP/1.1\nHost: x\n\n",
                                          "GET /metrics HTTP/1.0\n\n",
                                          "GET /metrics HTTP/1.1\r\nHost: x\n\r\n",
                                          "\r\nGET /metrics HTTP/1.1\r\n\r\n",
                                          "GET http://127.0.0.1:" + port
                                              + "/metrics HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n",
                                          "GET HTTP://[::1]:" + port + "/metrics?x=1 HTTP/1.1\r\n\r\n"};
        // Answered, not left waiting: a head the server did not take for complete would get no answer
        // (httpRequest gives up after 5 s of silence), and the whole answer is checked.
        for (const QByteArray& request : requests) {
            QElapsedTimer t;
            t.start();
            const QByteArray answer = TestServers::httpRequest(server->port(), request);
            QVERIFY2(answer.startsWith("HTTP/1.1 200 OK\r\n"), request.constData());
            QCOMPARE(body(answer), want);
            qInfo("answered in %lld ms", t.elapsed());
        }
        QVERIFY(TestServers::httpRequest(server->port(), "GET http://h:1/other HTTP/1.1\n\n")
                    .startsWith("HTTP/1.1 404"));
        QVERIFY(TestServers::httpRequest(server->port(), "GET http://h:1 HTTP/1.1\n\n").contains("/metrics"));
        QCOMPARE(server->served(), quint64(6));
    }

    /// Label values are cut, and an answer stays within its bytes however many links there are: 10,000
    /// links named with 2,000 characters made answers of 190 MB. What is left out is said.
    void answersStayWithinTheirBudget()
    {
        using MetricsExposition::label;
        MetricsSnapshot s;
        for (int i = 0; i < 10000; ++i) {
            MetricsSnapshot::Link l;
            const QByteArray name = QByteArray::number(i) + '/' + QByteArray(2000, 'n');
            l.labels = label("config", "discovered") + ',' + label("client", "") + ','
                + label("direction", "ros2mqtt") + ',' + label("topic", '/' + name) + ','
                + label("mqtt_topic", name);
            l.hasLatency = i % 2 == 0;
            s.links.push_back(l);
        }
        const QByteArray cut = label("topic", QByteArray(2000, 'n'));
        QVERIFY(cut.size() <= MetricsExposition::kMaxLabelValueBytes + 8);
        QVERIFY(cut.contains("\xe2\x80\xa6")); // the mark
        QVERIFY(cut != label("topic", QByteArray(2000, 'n') + 'x')); // still distinct
        const QByteArray umlauts = label("topic", 'x' + QByteArray("\xc3\xbc").repeated(200));
        QCOMPARE(umlauts.size(), cut.size() - 1); // not cut inside a character
        QVERIFY(!QString::fromUtf8(umlauts).contains(QChar::ReplacementCharacter));
        QElapsedTimer t;
        t.start();
        const QByteArray text = MetricsExposition::write(s, MetricsFormat::Text, 3);
        qInfo("10,000 links of 2,000 characters written in %lld ms", t.elapsed());
        QVERIFY2(text.size() <= MetricsExposition::kMaxAnswerBytes, qPrintable(QString::number(text.size())));
        QVERIFY(text.size() > MetricsExposition::kMaxAnswerBytes / 2); // as many as fit, not few
        QVERIFY(text.contains("\nbridgescope_metrics_truncated 1\n"));
        const QByteArray key = "\nbridgescope_metrics_omitted ";
        const qsizetype at = text.indexOf(key) + key.size();
        const double omitted = text.mid(at, text.indexOf('\n', at) - at).toDouble();
        QVERIFY2(omitted > 0 && omitted < 10000, qPrintable(QString::number(omitted)));
        QVERIFY(text.contains("\nbridgescope_metrics_dropped_clients_total 3\n"));
        QVERIFY(MetricsExposition::write(twoLinks(), MetricsFormat::OpenMetrics)
                    .contains("\nbridgescope_metrics_truncated{host=\"vehicle-3\",site=\"garage\"} 0\n"));
    }

    /// Clients that ask and never read hold their answers in the server's memory: past the budget,
    /// the oldest of them are closed, and a scrape is still answered at once.
    void nonReadersAreDroppedPastTheBudget()
    {
        QString error;
        const std::unique_ptr<MetricsServer> server
            = noted(MetricsServer::listen(u"127.0.0.1:0"_s), &error).value_or(nullptr);
        QVERIFY2(server, qPrintable(error));
        MetricsSnapshot s;
        for (int i = 0; i < 9000; ++i) {
            MetricsSnapshot::Link l;
            l.labels = MetricsExposition::label("topic", QByteArray::number(i) + QByteArray(250, 'n'));
            l.hasLatency = true;
            s.links.push_back(l);
        }
        server->publish(std::make_shared<MetricsSnapshot>(s));
        const qsizetype answerBytes = MetricsExposition::write(s, MetricsFormat::Text).size();
        QVERIFY2(answerBytes > 8 * 1024 * 1024, qPrintable(QString::number(answerBytes)));
        std::vector<std::unique_ptr<QTcpSocket>> greedy;
        for (int i = 0; i < 24; ++i) {
            greedy.push_back(std::make_unique<QTcpSocket>());
            greedy.back()->setReadBufferSize(1); // reads (almost) nothing
            greedy.back()->connectToHost(u"127.0.0.1"_s, server->port());
            QVERIFY(greedy.back()->waitForConnected(3000));
            greedy.back()->write("GET /metrics HTTP/1.1\r\n\r\n");
            QVERIFY(greedy.back()->waitForBytesWritten(3000));
        }
        QTRY_VERIFY2_WITH_TIMEOUT(server->served() == 24, qPrintable(QString::number(server->served())),
                                  20000);
        QTRY_VERIFY_WITH_TIMEOUT(server->dropped() > 0, 10000);
        const quint64 served = server->served();
        const quint64 droppedBefore = server->dropped();
        QElapsedTimer t;
        t.start();
        // Answered whole while the 24 hold their answers (httpRequest gives up after 5 s of silence).
        const QByteArray answer = TestServers::httpRequest(server->port(), "GET /metrics HTTP/1.1\r\n\r\n");
        qInfo("a scrape among 24 clients that do not read answered in %lld ms", t.elapsed());
        QVERIFY(answer.startsWith("HTTP/1.1 200"));
        // The same snapshot, and the server's own count of the clients it dropped when it made the
        // answer (making room for it may drop one more), with no new snapshot published: the server
        // says its drops in every answer itself.
        const QByteArray key = "\nbridgescope_metrics_dropped_clients_total ";
        const QByteArray text = body(answer);
        const qsizetype at = text.indexOf(key) + key.size();
        QVERIFY(at >= key.size());
        const quint64 said = text.mid(at, text.indexOf('\n', at) - at).toULongLong();
        QVERIFY2(said >= droppedBefore && said <= server->dropped() && said > 0,
                 qPrintable(
                     u"%1 said, %2 before, %3 after"_s.arg(said).arg(droppedBefore).arg(server->dropped())));
        QCOMPARE(text.size(), MetricsExposition::write(s, MetricsFormat::Text, said).size());
        QCOMPARE(server->served(), served + 1);
    }

    /// Bursts of connections that send nothing, every 10 ms, while a scraper scrapes: every scrape is
    /// answered (the idle ones make room among themselves, the scraper's asked first).
    void idleBurstsDoNotStarveScrapes()
    {
        QString error;
        const std::unique_ptr<MetricsServer> server
            = noted(MetricsServer::listen(u"127.0.0.1:0"_s), &error).value_or(nullptr);
        QVERIFY2(server, qPrintable(error));
        server->publish(std::make_shared<MetricsSnapshot>(twoLinks()));
        const quint16 port = server->port();
        std::atomic<bool> stop {false};
        std::atomic<int> opened {0};
        std::thread burster([&] {
            sockaddr_in to {};
            to.sin_family = AF_INET;
            to.sin_port = htons(port);
            to.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
            std::deque<std::vector<int>> bursts;
            const auto closeAll = [](const std::vector<int>& fds) {
                for (int fd : fds) {
                    const linger reset {1, 0}; // RST: no TIME_WAIT left behind
                    ::setsockopt(fd, SOL_SOCKET, SO_LINGER, &reset, sizeof reset);
                    ::close(fd);
                }
            };
            while (!stop) {
                std::vector<int> burst;
                for (int i = 0; i < 100; ++i) {
                    const int fd = ::socket(AF_INET, SOCK_STREAM | SOCK_NONBLOCK, 0);
                    if (fd < 0)
                        break;
                    ::connect(fd, reinterpret_cast<const sockaddr*>(&to), sizeof to);
                    burst.push_back(fd);
                }
                opened += int(burst.size());
                bursts.push_back(std::move(burst));
                if (bursts.size() > 3) {
                    closeAll(bursts.front());
                    bursts.pop_front();
                }
                std::this_thread::sleep_for(std::chrono::milliseconds(10));
            }
            for (const auto& b : bursts)
                closeAll(b);
        });
        int scrapes = 0, answered = 0;
        QElapsedTimer t;
        t.start();
        QStringList failures;
        // Scrapes through 3,000 idle connections in their bursts, and at least ten scrapes, however
        // long they take (a loaded or sanitized build scrapes slower: the property is that every
        // scrape is answered); two minutes at most.
        while ((opened <= 3000 || scrapes < 10) && t.elapsed() < 120000) {
            const QByteArray answer = TestServers::httpRequest(port, "GET /metrics HTTP/1.1\r\n\r\n");
            ++scrapes;
            if (answer.startsWith("HTTP/1.1 200") && body(answer).endsWith("\n"))
                ++answered;
            else
                failures << QString::fromUtf8(answer.left(40));
            QTest::qWait(20);
        }
        stop = true;
        burster.join();
        QVERIFY2(opened > 3000, qPrintable(QString::number(opened)));
        QVERIFY(server->rejected() > 1000);
        QVERIFY2(
            scrapes >= 10 && answered == scrapes,
            qPrintable(u"%1 of %2 answered: %3"_s.arg(answered).arg(scrapes).arg(failures.join(u" | "_s))));
    }

    // Clients that connect and never ask hold no slot for ever: more than kMaxClients of them push
    // out the oldest, and a scrape still gets its answer at once.
    void idleClientsDoNotLockOutTheScraper()
    {
        QString error;
        const std::unique_ptr<MetricsServer> server
            = noted(MetricsServer::listen(u"127.0.0.1:0"_s), &error).value_or(nullptr);
        QVERIFY2(server, qPrintable(error));
        server->publish(std::make_shared<MetricsSnapshot>(twoLinks()));
        std::vector<std::unique_ptr<QTcpSocket>> idle;
        for (int i = 0; i < MetricsServer::kMaxClients + 8; ++i) {
            idle.push_back(std::make_unique<QTcpSocket>());
            idle.back()->connectToHost(u"127.0.0.1"_s, server->port());
            QVERIFY(idle.back()->waitForConnected(3000));
        }
        QTRY_VERIFY(server->rejected() >= 8);
        QElapsedTimer t;
        t.start();
        // Answered whole (httpRequest gives up after 5 s of silence).
        const QByteArray answer = TestServers::httpRequest(server->port(), "GET /metrics HTTP/1.1\r\n\r\n");
        qInfo("a scrape among %d idle clients answered in %lld ms", MetricsServer::kMaxClients + 8,
              t.elapsed());
        QVERIFY(answer.startsWith("HTTP/1.1 200"));
        QVERIFY(body(answer).endsWith("\n"));
        // every link's figures (the server's own counters have moved since)
        for (const QByteArray& line : MetricsExposition::write(twoLinks(), MetricsFormat::Text).split('\n'))
            if (line.startsWith("bridgescope_link_"))
                QVERIFY2(body(answer).contains(QByteArray(line + '\n')), line.constData());
        // The oldest were closed by the server.
        QTRY_VERIFY(idle.front()->state() == QAbstractSocket::UnconnectedState
                    || idle.front()->waitForDisconnected(100));
    }
};

QTEST_GUILESS_MAIN(TestMetricsServer)
#include "tst_metricsserver.moc"
