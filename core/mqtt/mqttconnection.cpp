// SPDX-License-Identifier: MIT
#include "mqttconnection.h"

#include "text/exactutf8.h"
#include "base/logging.h"
#include "files/regularfile.h"
#include "yaml/secrets.h"
#include "base/wallclock.h"
#include "mqtt/pahooptions.h"

#include <atomic>
#include <chrono>
#include <mqtt/async_client.h>
#include <QDateTime>
#include <QFile>
#include <QPointer>
#include <QRandomGenerator>
#include <QSslConfiguration>
#include <QSslKey>
#include <QSslSocket>
#include <QTimer>
#include <QUrl>
#include <QUuid>

using namespace Qt::StringLiterals;

namespace {
// Why a CONNECT was refused, in words (MQTT 3.1.1 return codes and MQTT 5 reason codes).
QString refusalText(int code)
{
    switch (code) {
    case 1:
        return MqttConnection::tr("the broker does not speak this MQTT version");
    case 2:
        return MqttConnection::tr("the broker rejected the client id");
    case 3:
        return MqttConnection::tr("the broker is unavailable");
    case 4:
    case 0x86:
        return MqttConnection::tr("the broker refused the user name or password");
    case 5:
    case 0x87:
        return MqttConnection::tr("the client is not authorised to connect");
    default:
        return QString();
    }
}

bool isAuthFailure(int code)
{
    return code == 4 || code == 5 || code == 0x86 || code == 0x87;
}
} // namespace

// State shared with Paho's threads; it lives as long as the last callback that holds it.
// Paho threads never touch the MqttConnection: they post to `notifier`, a QObject that lives
// as long as this block, and the posted call looks the connection up on the GUI thread.
struct Shared
{
    EventBuffer<MqttMessage> buffer;
    std::atomic<quint64> received {0};
    std::atomic<quint64> bytes {0};
    std::atomic<int> connects {0};
    std::atomic<bool> alive {true};
    QObject* notifier = new QObject;
    QPointer<MqttConnection> owner; ///< read on the GUI thread only

    ~Shared() { notifier->deleteLater(); }

    /// Runs `f` with the connection on the GUI thread, if both still exist by then.
    /// The posted call holds the block weakly: were it the last owner, the block would die
    /// while Qt discards pending events under its post-event lock, and the deleteLater() in
    /// ~Shared would wait for that lock forever.
    template<typename F> void post(const std::shared_ptr<Shared>& self, F f)
    {
        QMetaObject::invokeMethod(
            notifier,
            [weak = std::weak_ptr<Shared>(self), f] {
                const std::shared_ptr<Shared> block = weak.lock();
                if (block && block->alive && block->owner)
                    f(block->owner.data());
            },
            Qt::QueuedConnection);
    }
};

struct MqttConnection::Private
{
    std::shared_ptr<Shared> shared = std::make_shared<Shared>();
    std::unique_ptr<mqtt::async_client> client;
    std::unique_ptr<mqtt::iaction_listener> listener;
    QTimer retry;
    int retrySeconds = 1;
};

namespace {
class ConnectListener : public mqtt::iaction_listener
{
public:
    ConnectListener(std::shared_ptr<Shared> shared, QString url)
        : m_shared(std::move(shared))
        , m_url(std::move(url))
    { }
    void on_success(const mqtt::token&) override { }
    void on_failure(const mqtt::token& tok) override
    {
        if (!m_shared->alive)
            return;
        const int code = tok.get_return_code();
        const int reason = int(tok.get_reason_code());
        QString why = refusalText(code > 0 ? code : reason);
        if (why.isEmpty() && code == -1)
            why = MqttConnection::tr("no broker answers at %1").arg(m_url);
        if (why.isEmpty())
            why = MqttConnection::tr("cannot connect to %1 (Paho error %2)").arg(m_url).arg(code);
        const bool auth = isAuthFailure(code) || isAuthFailure(reason);
        m_shared->post(m_shared, [why, auth](MqttConnection* c) {
            QMetaObject::invokeMethod(c, "onConnectFailed", Qt::DirectConnection, Q_ARG(QString, why),
                                      Q_ARG(bool, auth));
        });
    }

private:
    std::shared_ptr<Shared> m_shared;
    QString m_url;
};
} // namespace

MqttConnection::MqttConnection(QObject* parent)
    : QObject(parent)
    , d(std::make_unique<Private>())
{
    qRegisterMetaType<MqttConnection::State>();
    d->shared->owner = this;
    d->retry.setSingleShot(true);
    connect(&d->retry, &QTimer::timeout, this, &MqttConnection::startClient);
}

MqttConnection::~MqttConnection()
{
    close();
}

QString MqttConnection::stateText(State state)
{
    switch (state) {
    case State::Disconnected:
        return tr("disconnected");
    case State::Connecting:
        return tr("connecting");
    case State::Connected:
        return tr("connected");
    case State::Reconnecting:
        return tr("reconnecting");
    case State::Failed:
        return tr("failed");
    }
    return QString();
}

void MqttConnection::setState(State state, const QString& detail)
{
    if (state == m_state && detail == m_detail)
        return;
    m_state = state;
    m_detail = detail;
    qCDebug(lcMqtt).noquote() << Secrets::urlWithoutCredentials(m_profile.url) << stateText(state) << detail;
    emit stateChanged(state, detail);
}

void MqttConnection::open(const MqttProfile& profile)
{
    close();
    m_profile = profile;
    if (const Status valid = profile.validate(); !valid) {
        setState(State::Failed, valid.error().toString());
        return;
    }
    d->retrySeconds = 1;
    startClient();
}

void MqttConnection::close()
{
    d->retry.stop();
    if (d->client) {
        // Callbacks still to come see `alive == false` and do nothing; the shared state outlives
        // them. (Paho refuses to change callbacks while it connects, so they stay set.)
        d->shared->alive = false;
        try {
            if (d->client->is_connected())
                d->client->disconnect(0);
        } catch (const mqtt::exception&) { }
        d->client.reset();
        // A fresh shared block for the next connection; counters carry over.
        auto next = std::make_shared<Shared>();
        next->owner = this;
        next->received = d->shared->received.load();
        next->bytes = d->shared->bytes.load();
        next->connects = d->shared->connects.load();
        d->shared = next;
    }
    if (m_state != State::Failed)
        setState(State::Disconnected, QString());
}

void MqttConnection::scheduleRetry(const QString& why)
{
    setState(State::Reconnecting, tr("%1; retrying in %2 s").arg(why).arg(d->retrySeconds));
    d->retry.start(d->retrySeconds * 1000);
    d->retrySeconds = std::min(d->retrySeconds * 2, PahoOptions::kMaxRetrySeconds);
}

void MqttConnection::startClient()
{
    const MqttProfile& p = m_profile;
    std::shared_ptr<Shared> shared = d->shared;
    shared->alive = true;
    const std::string clientId = PahoOptions::clientId(p);
    try {
        if (!d->client) {
            mqtt::create_options createOpts(p.mqttVersion == 5 ? MQTTVERSION_5 : MQTTVERSION_3_1_1);
            // Publications wait in Paho's queue until its thread sends them; its default of 100
            // refuses a burst (clearing the retained messages of a subtree).
            createOpts.set_max_buffered_messages(kMaxQueuedPublications);
            d->client = std::make_unique<mqtt::async_client>(p.pahoUri().toStdString(), clientId, createOpts,
                                                             nullptr);
            const std::vector<std::string> filters = [&] {
                std::vector<std::string> f;
                for (const QString& s : p.filters)
                    f.push_back(s.toStdString());
                if (p.brokerStatistics)
                    f.push_back("$SYS/#");
                return f;
            }();
            mqtt::async_client* client = d->client.get();
            d->client->set_message_callback([shared](mqtt::const_message_ptr msg) {
                if (!shared->alive)
                    return;
                MqttMessage m;
                m.topic = exactUtf8(msg->get_topic());
                const mqtt::binary_ref& data = msg->get_payload_ref();
                m.payload = QByteArray(data.data(), qsizetype(data.size()));
                m.receivedNs = wallClockNs();
                m.qos = quint8(msg->get_qos());
                m.retained = msg->is_retained();
                const std::size_t size = std::size_t(m.payload.size());
                shared->received.fetch_add(1, std::memory_order_relaxed);
                shared->bytes.fetch_add(size, std::memory_order_relaxed);
                shared->buffer.push(std::move(m), size + 64);
            });
            d->client->set_connected_handler([shared, client, filters](const std::string&) {
                if (!shared->alive)
                    return;
                shared->connects.fetch_add(1);
                try {
                    // Subscribed again on every (re)connect: a clean session forgets them.
                    client->subscribe(mqtt::string_collection::create(filters),
                                      std::vector<int>(filters.size(), 0));
                } catch (const mqtt::exception&) { }
                shared->post(shared, [](MqttConnection* c) {
                    QMetaObject::invokeMethod(c, "onConnected", Qt::DirectConnection);
                });
            });
            d->client->set_connection_lost_handler([shared, client](const std::string& cause) {
                if (!shared->alive)
                    return;
                PahoOptions::reconnectNow(*client);
                const QString why = cause.empty() ? tr("connection lost") : QString::fromStdString(cause);
                shared->post(shared, [why](MqttConnection* c) {
                    QMetaObject::invokeMethod(c, "onConnectionLost", Qt::DirectConnection,
                                              Q_ARG(QString, why));
                });
            });
        }
        auto builder = PahoOptions::connectOptions(p);
        qCDebug(lcMqtt).noquote() << "connecting to" << Secrets::urlWithoutCredentials(p.url) << "as"
                                  << QString::fromStdString(clientId) << "subscribing"
                                  << p.filters.join(u' ');
        // TLS failures are diagnosed with QSslSocket (diagnoseTls): Paho's ssl error handler is unsafe.
        setState(d->shared->connects > 0 ? State::Reconnecting : State::Connecting, p.url);
        d->listener = std::make_unique<ConnectListener>(shared, p.url);
        d->client->connect(builder.finalize(), nullptr, *d->listener);
    } catch (const mqtt::exception& e) {
        d->client.reset();
        setState(State::Failed, tr("cannot connect to %1: %2").arg(p.url, QString::fromStdString(e.what())));
    }
}

void MqttConnection::onConnected()
{
    d->retrySeconds = 1;
    setState(State::Connected, QString());
}

void MqttConnection::onConnectionLost(const QString& why)
{
    setState(State::Reconnecting, tr("%1; reconnecting").arg(why));
}

void MqttConnection::onConnectFailed(const QString& why, bool authFailure)
{
    if (authFailure) {
        d->retry.stop();
        setState(State::Failed, why);
        return;
    }
    if (m_profile.isTls() && d->retrySeconds == 1) {
        diagnoseTls(why);
        return;
    }
    scheduleRetry(why);
}

// Paho says little about a failed TLS handshake; a handshake of our own with the same files says
// what is wrong (unknown CA, expired certificate, wrong host name, no client certificate, ...).
void MqttConnection::diagnoseTls(const QString& fallback)
{
    const QUrl url(m_profile.pahoUri());
    auto* socket = new QSslSocket(this);
    QSslConfiguration conf = QSslConfiguration::defaultConfiguration();
    if (!m_profile.caFile.isEmpty())
        conf.setCaCertificates(QSslCertificate::fromPath(m_profile.caFile));
    if (!m_profile.certFile.isEmpty()) {
        conf.setLocalCertificate(QSslCertificate::fromPath(m_profile.certFile).value(0));
        // A key is a few KiB: a regular file of at most 1 MiB (not a FIFO, not /dev/zero).
        if (const Result<QByteArray> read = RegularFile::read(m_profile.keyFile, 1024 * 1024)) {
            const QByteArray& pem = *read;
            QSslKey key(pem, QSsl::Rsa, QSsl::Pem, QSsl::PrivateKey, m_profile.keyPassword.toUtf8());
            if (key.isNull())
                key = QSslKey(pem, QSsl::Ec, QSsl::Pem, QSsl::PrivateKey, m_profile.keyPassword.toUtf8());
            conf.setPrivateKey(key);
        }
    }
    conf.setPeerVerifyMode(m_profile.verifyServer ? QSslSocket::VerifyPeer : QSslSocket::VerifyNone);
    socket->setSslConfiguration(conf);
    auto problems = std::make_shared<QStringList>();
    auto finish = [this, socket, problems, fallback](const QString& extra) {
        if (!socket->property("done").toBool()) {
            socket->setProperty("done", true);
            QStringList all = *problems;
            if (!extra.isEmpty() && !all.contains(extra))
                all << extra;
            socket->abort();
            socket->deleteLater();
            scheduleRetry(all.isEmpty() ? fallback : tr("TLS failed: %1").arg(all.join(u"; "_s)));
        }
    };
    connect(socket, &QSslSocket::sslErrors, this, [problems](const QList<QSslError>& errors) {
        for (const QSslError& e : errors)
            *problems << e.errorString();
    });
    connect(socket, &QSslSocket::errorOccurred, this, [socket, finish] { finish(socket->errorString()); });
    connect(socket, &QSslSocket::encrypted, this, [finish, fallback] { finish(QString()); });
    connect(socket, &QSslSocket::disconnected, this, [finish] { finish(QString()); });
    QTimer::singleShot(3000, socket, [finish] { finish(QString()); });
    socket->connectToHostEncrypted(url.host(), quint16(url.port(8883)));
}

std::vector<MqttMessage> MqttConnection::takeMessages()
{
    return d->shared->buffer.take();
}

quint64 MqttConnection::received() const
{
    return d->shared->received.load();
}

quint64 MqttConnection::receivedBytes() const
{
    return d->shared->bytes.load();
}

quint64 MqttConnection::dropped() const
{
    return d->shared->buffer.dropped();
}

int MqttConnection::connects() const
{
    return d->shared->connects.load();
}

bool MqttConnection::publish(const QString& topic, const QByteArray& payload, int qos, bool retained,
                             QString* error)
{
    if (!d->client || !d->client->is_connected()) {
        if (error)
            *error = tr("not connected to the broker");
        return false;
    }
    try {
        d->client->publish(topic.toStdString(), payload.constData(), std::size_t(payload.size()), qos,
                           retained);
        return true;
    } catch (const mqtt::exception& e) {
        if (error)
            *error = QString::fromStdString(e.what());
        return false;
    }
}

QString MqttConnection::pahoVersion()
{
    const uint32_t v = mqtt::VERSION; // 0xMMmmpp00
    return QStringLiteral("%1.%2.%3").arg(v >> 24).arg((v >> 16) & 0xff).arg((v >> 8) & 0xff);
}
