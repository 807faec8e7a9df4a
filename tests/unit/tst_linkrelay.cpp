// SPDX-License-Identifier: MIT
// The experiment's link relay under a flood on loopback: a sender that writes as fast as the relay
// takes it, into a slow link (200 ms, 10 Mbit) or towards a peer that does not read. The relay
// holds at most its memory bound (the process's peak RSS proves it), counts the pauses of its
// reading, and delivers every byte once the peer reads again.
#include "experiment/linkrelay.h"
#include "peakrss.h"

#include <arpa/inet.h>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <netinet/in.h>
#include <QElapsedTimer>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTest>
#include <sys/socket.h>
#include <thread>
#include <unistd.h>

using namespace Qt::StringLiterals;

namespace {
constexpr qint64 kFloodBytes = 512LL * 1024 * 1024; ///< what the sender tries to get through
constexpr int kFloodSeconds = 4;
/// Beyond the relay's bound: chunks' allocation slack, socket buffers, the sender's buffer.
constexpr qint64 kSlackBytes = 24LL * 1024 * 1024;

/// Writes to 127.0.0.1:port from a thread of its own, with a blocking socket (no buffer of ours
/// grows), until kFloodBytes are taken or kFloodSeconds have passed.
class Flood
{
public:
    explicit Flood(quint16 port)
    {
        m_thread = std::thread([this, port] { run(port); });
    }
    ~Flood() { join(); }
    void join()
    {
        if (m_thread.joinable())
            m_thread.join();
    }
    bool done() const { return m_done.load(); }
    qint64 sent() const { return m_sent.load(); }

private:
    void run(quint16 port)
    {
        const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
        sockaddr_in address {};
        address.sin_family = AF_INET;
        address.sin_port = htons(port);
        address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
        const timeval timeout {0, 200'000};
        ::setsockopt(fd, SOL_SOCKET, SO_SNDTIMEO, &timeout, sizeof timeout);
        if (::connect(fd, reinterpret_cast<const sockaddr*>(&address), sizeof address) == 0) {
            const QByteArray chunk(1024 * 1024, 'x');
            const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(kFloodSeconds);
            while (m_sent.load() < kFloodBytes && std::chrono::steady_clock::now() < end) {
                const ssize_t n = ::send(fd, chunk.constData(), size_t(chunk.size()), MSG_NOSIGNAL);
                if (n > 0)
                    m_sent += n;
                else if (errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR)
                    break;
            }
        }
        ::close(fd);
        m_done = true;
    }

    std::thread m_thread;
    std::atomic<qint64> m_sent {0};
    std::atomic<bool> m_done {false};
};
} // namespace

class TestLinkRelay : public QObject
{
    Q_OBJECT
private slots:
    // Issue 43: `there_extra_ms` lengthens the way towards the broker only, so that a test can make
    // a path whose two ways differ by a known amount.
    void theWayThereCanTakeLongerThanTheWayBack()
    {
        QTcpServer target;
        QVERIFY(target.listen(QHostAddress::LocalHost));
        QTcpSocket* peer = nullptr;
        QElapsedTimer clock;
        qint64 arrivedThere = -1;
        connect(&target, &QTcpServer::newConnection, this, [&] {
            peer = target.nextPendingConnection();
            connect(peer, &QTcpSocket::readyRead, this, [&] {
                peer->readAll();
                arrivedThere = clock.nsecsElapsed();
                clock.restart();
                peer->write("back");
            });
        });
        LinkProfile profile;
        profile.delayMs = 5;
        profile.thereExtraMs = 30;
        Result<std::unique_ptr<LinkRelay>> started
            = LinkRelay::start(profile, u"127.0.0.1"_s, target.serverPort());
        QVERIFY2(started, qPrintable(started.error().toString()));
        const std::unique_ptr<LinkRelay> relay = std::move(started).value();
        QTcpSocket client;
        client.connectToHost(QHostAddress::LocalHost, relay->port());
        QVERIFY(client.waitForConnected(5000));
        QTRY_VERIFY(peer != nullptr);
        qint64 back = -1;
        connect(&client, &QTcpSocket::readyRead, this, [&] { back = clock.nsecsElapsed(); });
        clock.start();
        client.write("there");
        QTRY_VERIFY(back >= 0);
        qInfo("there %.1f ms, back %.1f ms", double(arrivedThere) / 1e6, double(back) / 1e6);
        QVERIFY2(arrivedThere >= 35'000'000 && arrivedThere < 60'000'000,
                 qPrintable(QString::number(arrivedThere)));
        QVERIFY2(back >= 5'000'000 && back < 30'000'000, qPrintable(QString::number(back)));
    }

    void aFloodHoldsTheMemoryBound_data()
    {
        QTest::addColumn<double>("delayMs");
        QTest::addColumn<double>("bandwidthMbit");
        QTest::addColumn<bool>("peerReads");
        QTest::newRow("200 ms, 10 Mbit") << 200.0 << 10.0 << true;
        QTest::newRow("a peer that does not read") << 0.0 << 0.0 << false;
    }

    void aFloodHoldsTheMemoryBound()
    {
        QFETCH(double, delayMs);
        QFETCH(double, bandwidthMbit);
        QFETCH(bool, peerReads);
        // The target: takes the connection, and reads everything only when `peerReads`.
        QTcpServer target;
        QVERIFY(target.listen(QHostAddress::LocalHost, 0));
        QTcpSocket* peer = nullptr;
        qint64 received = 0;
        bool reading = peerReads;
        const auto drain = [&] {
            if (peer && reading)
                received += peer->readAll().size();
        };
        connect(&target, &QTcpServer::newConnection, this, [&] {
            peer = target.nextPendingConnection();
            peer->setReadBufferSize(LinkRelay::kReadBufferBytes); // the test holds little of its own
            connect(peer, &QTcpSocket::readyRead, this, drain);
        });
        LinkProfile profile;
        profile.delayMs = delayMs;
        profile.bandwidthMbit = bandwidthMbit;
        Result<std::unique_ptr<LinkRelay>> started
            = LinkRelay::start(profile, u"127.0.0.1"_s, target.serverPort());
        QVERIFY2(started, qPrintable(started.error().toString()));
        std::unique_ptr<LinkRelay> relay = std::move(started).value();

        QVERIFY(PeakRss::reset());
        const qint64 before = PeakRss::of();
        QVERIFY(before > 0);
        Flood flood(relay->port());
        QVERIFY(QTest::qWaitFor([&] { return flood.done(); }, (kFloodSeconds + 5) * 1000));
        flood.join();
        const qint64 grown = PeakRss::of() - before;
        qInfo("sent %.1f MiB, peak RSS grew %.1f MiB, %llu read pauses", double(flood.sent()) / (1 << 20),
              double(grown) / (1 << 20), relay->readPauses());
        QVERIFY2(grown < LinkRelay::kMaxHeldBytes + kSlackBytes + PeakRss::kSanitizerSlack,
                 qPrintable(u"the peak RSS grew by %1 MiB"_s.arg(grown >> 20)));
        QVERIFY(relay->readPauses() > 0);
        QVERIFY(flood.sent() > LinkRelay::kMaxHeldBytes); // the bound was reached, not just approached

        if (peerReads)
            return; // 10 Mbit would take a minute to deliver it
        // Reading again, the peer gets every byte: the relay resumed.
        reading = true;
        drain();
        QVERIFY2(QTest::qWaitFor([&] { return received == flood.sent(); }, 15000),
                 qPrintable(u"%1 of %2 bytes arrived"_s.arg(received).arg(flood.sent())));
        QTRY_COMPARE(LinkRelay::heldBytes(), 0);
    }
};

QTEST_GUILESS_MAIN(TestLinkRelay)
#include "tst_linkrelay.moc"
