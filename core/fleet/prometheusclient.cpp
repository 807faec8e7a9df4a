// SPDX-License-Identifier: MIT
#include "prometheusclient.h"

#include <QNetworkAccessManager>
#include <QNetworkReply>
#include <QNetworkRequest>
#include <QTimer>
#include <QUrlQuery>

using namespace Qt::StringLiterals;

namespace {
QString mebibytes(qint64 bytes)
{
    return QString::number(double(bytes) / 1048576.0, 'g', 3);
}
} // namespace

PrometheusClient::PrometheusClient(QObject* parent)
    : QObject(parent)
    , m_network(new QNetworkAccessManager(this))
{
    m_network->setRedirectPolicy(QNetworkRequest::NoLessSafeRedirectPolicy);
}

PrometheusClient::~PrometheusClient()
{
    // The callbacks may point into the owner, which is going too: none is called from here.
    for (auto& [reply, pending] : m_replies) {
        reply->disconnect(this);
        reply->abort();
        reply->deleteLater();
    }
}

Result<QUrl> PrometheusClient::checkUrl(const QString& text)
{
    const QUrl url = QUrl::fromUserInput(text.trimmed().size() > 2048 ? QString() : text.trimmed());
    if (text.trimmed().isEmpty() || !url.isValid())
        return LocatedError {tr("not a URL: %1").arg(text.left(200))};
    if (url.scheme() != "http"_L1 && url.scheme() != "https"_L1)
        return LocatedError {
            tr("a Prometheus server is reached over http or https, not %1").arg(url.scheme())};
    if (url.host().isEmpty())
        return LocatedError {tr("the URL names no host: %1").arg(text.left(200))};
    if (!url.userInfo().isEmpty())
        return LocatedError {tr("the URL must not hold a user or password: give them beside it")};
    if (url.hasQuery() || url.hasFragment())
        return LocatedError {tr("the URL is the server's base, without a query: %1").arg(text.left(200))};
    QUrl base = url;
    QString path = base.path();
    while (path.endsWith(u'/'))
        path.chop(1);
    base.setPath(path);
    return base;
}

void PrometheusClient::setServer(const QUrl& base, const QString& user, const QString& password)
{
    abortAll();
    m_base = base;
    m_authorization = user.isEmpty() && password.isEmpty()
        ? QByteArray()
        : "Basic " + (user + u':' + password).toUtf8().toBase64();
}

QString PrometheusClient::quoted(const QString& value)
{
    QString out;
    out.reserve(value.size() + 2);
    out += u'"';
    for (QChar c : value) {
        if (c == u'\\' || c == u'"')
            out += u'\\';
        if (c == u'\n')
            out += "\\n"_L1;
        else
            out += c;
    }
    out += u'"';
    return out;
}

void PrometheusClient::query(const QString& promql, Callback done, double time)
{
    QList<std::pair<QString, QString>> params {{u"query"_s, promql}};
    if (time > 0)
        params.append({u"time"_s, QString::number(time, 'f', 3)});
    send(u"/api/v1/query"_s, params, std::move(done));
}

void PrometheusClient::queryRange(const QString& promql, double start, double end, double stepSeconds,
                                  Callback done)
{
    send(u"/api/v1/query_range"_s,
         {{u"query"_s, promql},
          {u"start"_s, QString::number(start, 'f', 3)},
          {u"end"_s, QString::number(end, 'f', 3)},
          {u"step"_s, QString::number(stepSeconds, 'f', 3)}},
         std::move(done));
}

void PrometheusClient::send(const QString& path, const QList<std::pair<QString, QString>>& params,
                            Callback done)
{
    if (!m_base.isValid()) {
        ++m_failures;
        PrometheusAnswer a;
        a.error = tr("no Prometheus server chosen");
        done(a);
        return;
    }
    QUrl url = m_base;
    url.setPath(m_base.path() + path);
    // POST with a form: long queries fit, and the query is not in a proxy's access log.
    QUrlQuery form;
    for (const auto& [key, value] : params)
        form.addQueryItem(key, QString::fromLatin1(QUrl::toPercentEncoding(value)));
    QNetworkRequest request(url);
    request.setHeader(QNetworkRequest::ContentTypeHeader, "application/x-www-form-urlencoded"_ba);
    request.setRawHeader("Accept", "application/json");
    if (!m_authorization.isEmpty())
        request.setRawHeader("Authorization", m_authorization);
    request.setTransferTimeout(m_timeoutMs);
    QNetworkReply* reply = m_network->post(request, form.query(QUrl::FullyEncoded).toUtf8());
    // Qt starts a POST's transfer in its next event (where it connects the reply to its network
    // thread), and a read buffer size set before is never passed there: set it after, queued.
    QMetaObject::invokeMethod(
        reply, [reply] { reply->setReadBufferSize(kReadAheadBytes); }, Qt::QueuedConnection);
    m_replies[reply] = Pending {std::move(done), {}};
    // The transfer timeout ends a silent transfer; this one a slow one that trickles.
    QTimer::singleShot(m_timeoutMs, reply, [this, reply] { finish(reply, {}, timedOut()); });
    connect(reply, &QNetworkReply::readyRead, this, [this, reply] { take(reply); });
    connect(reply, &QNetworkReply::finished, this, [this, reply] {
        if (!take(reply))
            return;
        const int status = reply->attribute(QNetworkRequest::HttpStatusCodeAttribute).toInt();
        QString error;
        if (reply->error() == QNetworkReply::OperationCanceledError)
            error = timedOut();
        else if (status == 401 || status == 403)
            error = tr("the server refused the credentials (HTTP %1)").arg(status);
        else if (reply->error() != QNetworkReply::NoError && status != 400 && status != 422 && status != 503)
            error = reply->errorString(); // 400, 422 and 503 carry the API's own error in JSON
        finish(reply, m_replies[reply].body, error);
    });
}

bool PrometheusClient::take(QNetworkReply* reply)
{
    auto it = m_replies.find(reply);
    if (it == m_replies.end())
        return false;
    // An answer that announces more than the bound is refused before its body is read.
    const QVariant announced = reply->header(QNetworkRequest::ContentLengthHeader);
    const qint64 incoming = reply->bytesAvailable();
    if (it->second.body.size() + incoming > m_maxBytes
        || (announced.isValid() && announced.toLongLong() > m_maxBytes)) {
        finish(reply, {}, tr("the answer is larger than %1 MiB: refused").arg(mebibytes(m_maxBytes)));
        return false;
    }
    if (m_inFlightBytes + incoming > m_maxInFlightBytes) {
        finish(reply, {},
               tr("the answers in flight are larger than %1 MiB together: refused")
                   .arg(mebibytes(m_maxInFlightBytes)));
        return false;
    }
    const QByteArray bytes = reply->readAll();
    it->second.body += bytes;
    m_inFlightBytes += bytes.size();
    return true;
}

QString PrometheusClient::timedOut() const
{
    return tr("no answer within %1 s").arg(m_timeoutMs / 1000.0, 0, 'g', 3);
}

void PrometheusClient::finish(QNetworkReply* reply, QByteArray body, const QString& error)
{
    auto it = m_replies.find(reply);
    if (it == m_replies.end())
        return;
    Callback done = std::move(it->second.done);
    m_inFlightBytes -= it->second.body.size();
    m_replies.erase(it);
    reply->disconnect(this);
    if (reply->isRunning())
        reply->abort();
    reply->deleteLater();
    PrometheusAnswer answer;
    if (error.isEmpty())
        answer = PrometheusAnswer::read(body, &m_labels);
    else
        answer.error = error;
    if (!answer.ok())
        ++m_failures;
    if (done)
        done(answer);
}

void PrometheusClient::abortAll()
{
    const auto replies = m_replies;
    for (const auto& [reply, pending] : replies)
        finish(reply, {}, tr("aborted"));
}
