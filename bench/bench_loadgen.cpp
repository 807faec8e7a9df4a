// SPDX-License-Identifier: MIT
// Load generator for bench_discovery: publishes QoS 0 messages round-robin over many topics at a
// fixed rate for a bounded time, to a broker on loopback only.
//
// It speaks MQTT 3.1.1 itself over one TCP socket and writes the messages due in each 2 ms slice
// with one system call, so that the generator is not what limits the measurement (a client library
// that writes every message on its own tops out near 25,000 msg/s on one core of this machine).
//
//   bench_loadgen URL TOPICS RATE SECONDS [PAYLOAD_BYTES]
#include <arpa/inet.h>
#include <cstdio>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <QCoreApplication>
#include <QElapsedTimer>
#include <QThread>
#include <QUrl>
#include <sys/socket.h>
#include <unistd.h>

using namespace Qt::StringLiterals;

namespace {
void appendLength(QByteArray& out, int length)
{
    do {
        char byte = char(length % 128);
        length /= 128;
        if (length > 0)
            byte = char(byte | 0x80);
        out.append(byte);
    } while (length > 0);
}

void appendString(QByteArray& out, const QByteArray& s)
{
    out.append(char(s.size() >> 8));
    out.append(char(s.size() & 0xff));
    out.append(s);
}

bool writeAll(int fd, const QByteArray& data)
{
    qsizetype done = 0;
    while (done < data.size()) {
        const ssize_t n = ::send(fd, data.constData() + done, size_t(data.size() - done), MSG_NOSIGNAL);
        if (n <= 0)
            return false;
        done += n;
    }
    return true;
}
} // namespace

int main(int argc, char** argv)
{
    QCoreApplication app(argc, argv);
    const QStringList a = app.arguments();
    if (a.size() < 5) {
        std::fprintf(stderr, "usage: bench_loadgen URL TOPICS RATE SECONDS [PAYLOAD_BYTES]\n");
        return 2;
    }
    const QUrl url(a[1]);
    if (url.host() != u"127.0.0.1"_s && url.host() != u"localhost"_s) {
        std::fprintf(stderr, "bench_loadgen only loads brokers on 127.0.0.1\n");
        return 2;
    }
    const int topics = std::clamp(a[2].toInt(), 1, 100000);
    const double rate = std::clamp(a[3].toDouble(), 1.0, 500000.0);
    const double seconds = std::clamp(a[4].toDouble(), 0.1, 600.0); // bounded: a load test ends
    const int size = a.size() > 5 ? std::clamp(a[5].toInt(), 8, 1 << 20) : 32;

    // Pre-built PUBLISH packets, one per topic; only the sequence number in the payload changes.
    std::vector<QByteArray> headers;
    headers.reserve(size_t(topics));
    for (int i = 0; i < topics; ++i) {
        const QByteArray topic = u"fleet/vehicle_%1/sensor_%2"_s.arg(i / 100, 3, 10, QChar(u'0'))
                                     .arg(i % 100, 2, 10, QChar(u'0'))
                                     .toUtf8();
        QByteArray h;
        h.append(char(0x30));
        appendLength(h, 2 + int(topic.size()) + size);
        appendString(h, topic);
        headers.push_back(h);
    }

    const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in addr {};
    addr.sin_family = AF_INET;
    addr.sin_port = htons(quint16(url.port(1883)));
    addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (::connect(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr) != 0) {
        std::perror("connect");
        return 1;
    }
    QByteArray connectPacket;
    QByteArray body;
    appendString(body, "MQTT");
    body.append(char(4)); // MQTT 3.1.1
    body.append(char(2)); // clean session
    body.append(char(0)); // keep-alive, high byte
    body.append(char(120)); // keep-alive 120 s
    appendString(body, "bench-loadgen-" + QByteArray::number(::getpid()));
    connectPacket.append(char(0x10));
    appendLength(connectPacket, int(body.size()));
    connectPacket.append(body);
    char connack[4] = {};
    if (!writeAll(fd, connectPacket) || ::recv(fd, connack, 4, MSG_WAITALL) != 4 || connack[0] != 0x20
        || connack[3] != 0) {
        std::fprintf(stderr, "the broker did not accept the connection\n");
        return 1;
    }

    quint64 published = 0;
    QElapsedTimer clock;
    clock.start();
    QByteArray batch;
    while (true) {
        const double elapsed = double(clock.nsecsElapsed()) / 1e9;
        if (elapsed >= seconds)
            break;
        const quint64 due = quint64(elapsed * rate);
        batch.clear();
        while (published < due) {
            batch.append(headers[size_t(published % quint64(topics))]);
            const QByteArray seq = QByteArray::number(published);
            batch.append(seq);
            batch.append(QByteArray(std::max<qsizetype>(0, size - seq.size()), 'x'));
            ++published;
        }
        if (!batch.isEmpty() && !writeAll(fd, batch)) {
            std::fprintf(stderr, "the broker closed the connection\n");
            break;
        }
        QThread::usleep(2000);
    }
    writeAll(fd, QByteArray("\xe0\x00", 2)); // DISCONNECT
    ::close(fd);
    std::printf("%llu\n", static_cast<unsigned long long>(published));
    return published > 0 ? 0 : 1;
}
