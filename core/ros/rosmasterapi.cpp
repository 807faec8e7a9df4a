// SPDX-License-Identifier: MIT
#include "rosmasterapi.h"

#include "base/ioappend.h"

#include <algorithm>
#include <QDeadlineTimer>
#include <QSet>
#include <QTcpSocket>
#include <QUrl>
#include <QXmlStreamReader>

using namespace Qt::StringLiterals;

RosMasterApi::RosMasterApi(const QString& masterUri, const QString& callerId)
    : m_uri(masterUri)
    , m_callerId(callerId)
{ }

QString RosMasterApi::defaultMasterUri()
{
    const QString env = qEnvironmentVariable("ROS_MASTER_URI");
    return env.isEmpty() ? u"http://localhost:11311/"_s : env;
}

namespace {

void encodeValue(QString& out, const QVariant& v)
{
    out += u"<value>"_s;
    switch (v.typeId()) {
    case QMetaType::Bool:
        out += u"<boolean>"_s + (v.toBool() ? u"1"_s : u"0"_s) + u"</boolean>"_s;
        break;
    case QMetaType::Int:
    case QMetaType::UInt:
    case QMetaType::LongLong:
        out += u"<i4>"_s + QString::number(v.toLongLong()) + u"</i4>"_s;
        break;
    case QMetaType::Double:
        out += u"<double>"_s + QString::number(v.toDouble(), 'g', 17) + u"</double>"_s;
        break;
    case QMetaType::QVariantList:
        out += u"<array><data>"_s;
        for (const QVariant& item : v.toList())
            encodeValue(out, item);
        out += u"</data></array>"_s;
        break;
    default:
        out += u"<string>"_s + v.toString().toHtmlEscaped() + u"</string>"_s;
    }
    out += u"</value>"_s;
}

struct XmlError
{
    QString message;
};

QVariant parseValue(QXmlStreamReader& xml);

// At a <value> start element: reads through its end element.
QVariant parseValue(QXmlStreamReader& xml)
{
    QVariant result;
    bool typed = false;
    QString text;
    while (!xml.atEnd()) {
        const auto token = xml.readNext();
        if (token == QXmlStreamReader::Characters) {
            text += xml.text();
        } else if (token == QXmlStreamReader::StartElement) {
            typed = true;
            const QString tag = xml.name().toString();
            if (tag == u"string"_s) {
                result = xml.readElementText();
            } else if (tag == u"int"_s || tag == u"i4"_s || tag == u"i8"_s) {
                bool ok = false;
                result = xml.readElementText().trimmed().toLongLong(&ok);
                if (!ok)
                    throw XmlError {RosMasterApi::tr("an integer that is none")};
            } else if (tag == u"boolean"_s) {
                result = xml.readElementText().trimmed() == u"1"_s;
            } else if (tag == u"double"_s) {
                result = xml.readElementText().trimmed().toDouble();
            } else if (tag == u"base64"_s) {
                result = QByteArray::fromBase64(xml.readElementText().toLatin1());
            } else if (tag == u"nil"_s) {
                xml.skipCurrentElement();
            } else if (tag == u"array"_s) {
                QVariantList list;
                while (xml.readNextStartElement()) { // <data>
                    while (xml.readNextStartElement()) { // <value>
                        if (xml.name() != u"value"_s)
                            throw XmlError {RosMasterApi::tr("unexpected <%1> in an array").arg(xml.name())};
                        list << parseValue(xml);
                    }
                }
                result = list;
            } else if (tag == u"struct"_s) {
                QVariantMap map;
                while (xml.readNextStartElement()) { // <member>
                    QString name;
                    QVariant value;
                    while (xml.readNextStartElement()) {
                        if (xml.name() == u"name"_s)
                            name = xml.readElementText();
                        else if (xml.name() == u"value"_s)
                            value = parseValue(xml);
                        else
                            xml.skipCurrentElement();
                    }
                    map.insert(name, value);
                }
                result = map;
            } else {
                throw XmlError {RosMasterApi::tr("unknown XML-RPC type <%1>").arg(tag)};
            }
        } else if (token == QXmlStreamReader::EndElement) {
            if (xml.name() == u"value"_s)
                return typed ? result : QVariant(text);
        }
    }
    throw XmlError {RosMasterApi::tr("the response ends inside a value")};
}

} // namespace

QByteArray RosMasterApi::encodeCall(const QString& method, const QVariantList& params)
{
    QString out = u"<?xml version=\"1.0\"?><methodCall><methodName>"_s + method.toHtmlEscaped()
        + u"</methodName><params>"_s;
    for (const QVariant& p : params) {
        out += u"<param>"_s;
        encodeValue(out, p);
        out += u"</param>"_s;
    }
    out += u"</params></methodCall>"_s;
    return out.toUtf8();
}

Result<QVariant> RosMasterApi::decodeResponse(const QByteArray& body)
{
    QXmlStreamReader xml(body);
    try {
        bool fault = false;
        while (!xml.atEnd()) {
            const auto token = xml.readNext();
            if (token != QXmlStreamReader::StartElement)
                continue;
            if (xml.name() == u"fault"_s)
                fault = true;
            if (xml.name() == u"value"_s) {
                const QVariant v = parseValue(xml);
                if (fault) {
                    const QVariantMap m = v.toMap();
                    return LocatedError {
                        tr("XML-RPC fault %1: %2")
                            .arg(m.value(u"faultCode"_s).toString(), m.value(u"faultString"_s).toString())};
                }
                return v;
            }
        }
        return LocatedError {xml.hasError() ? tr("malformed XML-RPC response: %1").arg(xml.errorString())
                                            : tr("the XML-RPC response holds no value")};
    } catch (const XmlError& e) {
        return LocatedError {tr("malformed XML-RPC response: %1").arg(e.message)};
    }
}

Result<QVariant> RosMasterApi::call(const QString& method, const QVariantList& params, int timeoutMs) const
{
    const Result<QByteArray> body = rawAnswer(method, params, timeoutMs);
    if (!body)
        return body.error();
    return valueOf(method, *body);
}

Result<QVariant> RosMasterApi::valueOf(const QString& method, const QByteArray& body)
{
    const Result<QVariantList> triple = tripleOf(method, body);
    if (!triple)
        return triple.error();
    if ((*triple)[0].toInt() != 1)
        return LocatedError {tr("the ROS master refused %1: %2").arg(method, (*triple)[1].toString())};
    return (*triple)[2];
}

Result<QVariantList> RosMasterApi::tripleOf(const QString& method, const QByteArray& body)
{
    const Result<QVariant> value = decodeResponse(body);
    if (!value)
        return value.error();
    const QVariantList triple = value->toList();
    if (triple.size() != 3)
        return LocatedError {tr("the ROS master's answer to %1 is not [code, status, value]").arg(method)};
    return triple;
}

Result<QVariantList> RosMasterApi::answer(const QString& method, const QVariantList& params,
                                          int timeoutMs) const
{
    const Result<QByteArray> body = rawAnswer(method, params, timeoutMs);
    if (!body)
        return body.error();
    return tripleOf(method, *body);
}

Result<QByteArray> RosMasterApi::rawAnswer(const QString& method, const QVariantList& params,
                                           int timeoutMs) const
{
    const QUrl url(m_uri);
    if (!url.isValid() || url.host().isEmpty())
        return LocatedError {tr("'%1' is not a ROS master URI (http://host:11311)").arg(m_uri)};
    const QDeadlineTimer deadline(timeoutMs);
    QTcpSocket socket;
    socket.setReadBufferSize(1 << 20); // what the socket takes from the kernel before we read it
    socket.connectToHost(url.host(), quint16(url.port(11311)));
    if (!socket.waitForConnected(int(deadline.remainingTime())))
        return LocatedError {tr("no ROS master at %1: %2").arg(m_uri, socket.errorString())};
    const QByteArray body = encodeCall(method, params);
    const QByteArray path = url.path().isEmpty() ? QByteArray("/") : url.path().toUtf8();
    QByteArray request = "POST " + path + " HTTP/1.0\r\nUser-Agent: bridgescope\r\nHost: "
        + url.host().toUtf8() + "\r\nContent-Type: text/xml\r\nContent-Length: "
        + QByteArray::number(body.size()) + "\r\n\r\n" + body;
    socket.write(request);
    QByteArray response;
    qsizetype headerEnd = -1;
    qsizetype contentLength = -1;
    while (true) {
        if (headerEnd < 0) {
            headerEnd = response.indexOf("\r\n\r\n");
            if (headerEnd >= 0) {
                const QByteArray headers = response.left(headerEnd).toLower();
                const qsizetype at = headers.indexOf("content-length:");
                if (at >= 0)
                    contentLength
                        = headers.mid(at + 15, headers.indexOf('\n', at) - at - 15).trimmed().toLongLong();
                if (contentLength > 0 && contentLength <= kMaxAnswerBytes)
                    response.reserve(headerEnd + 4 + contentLength); // one allocation, no growth copies
            }
        }
        if (headerEnd >= 0 && contentLength >= 0 && response.size() - headerEnd - 4 >= contentLength)
            break;
        if (socket.state() != QAbstractSocket::ConnectedState && socket.bytesAvailable() == 0)
            break;
        if (deadline.hasExpired())
            return LocatedError {
                tr("the ROS master at %1 did not answer within %2 ms").arg(m_uri).arg(timeoutMs)};
        if (!socket.waitForReadyRead(int(std::max<qint64>(1, deadline.remainingTime())))
            && socket.state() == QAbstractSocket::ConnectedState && deadline.hasExpired())
            return LocatedError {
                tr("the ROS master at %1 did not answer within %2 ms").arg(m_uri).arg(timeoutMs)};
        IoAppend::available(socket, response, kMaxAnswerBytes + 1);
        if (response.size() > kMaxAnswerBytes)
            return LocatedError {
                tr("the ROS master at %1 sent more than %2 MiB").arg(m_uri).arg(kMaxAnswerBytes >> 20)};
    }
    if (headerEnd < 0 || !response.startsWith("HTTP/1."))
        return LocatedError {tr("the ROS master at %1 sent no HTTP response").arg(m_uri)};
    const QByteArray status = response.left(response.indexOf('\r'));
    if (!status.contains(" 200"))
        return LocatedError {tr("the ROS master at %1 answered %2").arg(m_uri, QString::fromLatin1(status))};
    return response.mid(headerEnd + 4);
}

Result<TopicGraph> RosMasterApi::graph(int timeoutMs) const
{
    GraphAnswers none;
    const Result<std::optional<TopicGraph>> g = graphIfChanged(timeoutMs, &none);
    if (!g)
        return g.error();
    return **g;
}

Result<std::optional<TopicGraph>> RosMasterApi::graphIfChanged(int timeoutMs, GraphAnswers* previous) const
{
    const QDeadlineTimer deadline(timeoutMs);
    Result<QByteArray> stateBody = rawAnswer(u"getSystemState"_s, {m_callerId}, timeoutMs);
    if (!stateBody)
        return stateBody.error();
    Result<QByteArray> typesBody
        = rawAnswer(u"getTopicTypes"_s, {m_callerId}, int(std::max<qint64>(1, deadline.remainingTime())));
    if (!typesBody)
        return typesBody.error();
    if (*stateBody == previous->state && *typesBody == previous->types && !previous->state.isEmpty())
        return std::optional<TopicGraph>(); // the same bytes: the same graph, not parsed again
    const Result<QVariant> state = valueOf(u"getSystemState"_s, *stateBody);
    if (!state)
        return state.error();
    const Result<QVariant> types = valueOf(u"getTopicTypes"_s, *typesBody);
    if (!types)
        return types.error();
    previous->state = std::move(stateBody).value();
    previous->types = std::move(typesBody).value();
    return std::optional<TopicGraph>(graphOf(*state, *types));
}

TopicGraph RosMasterApi::graphOf(const QVariant& state, const QVariant& types)
{
    QHash<QString, TopicInfo> topics;
    QSet<QString> nodes;
    const QVariantList lists = state.toList();
    for (int which = 0; which < lists.size() && which < 3; ++which) {
        for (const QVariant& entry : lists[which].toList()) {
            const QVariantList pair = entry.toList();
            if (pair.size() != 2)
                continue;
            const QString name = pair[0].toString();
            QStringList members;
            for (const QVariant& n : pair[1].toList())
                members << n.toString();
            members.sort();
            for (const QString& n : std::as_const(members))
                nodes.insert(n);
            if (which == 2)
                continue; // services: their nodes count, they are no topics
            TopicInfo& t = topics[name];
            t.name = name;
            (which == 0 ? t.publishers : t.subscribers) = members;
        }
    }
    // The master remembers a topic's type after its last node left; only topics with a publisher
    // or subscriber right now are part of the graph.
    for (const QVariant& entry : types.toList()) {
        const QVariantList pair = entry.toList();
        if (pair.size() != 2)
            continue;
        const auto it = topics.find(pair[0].toString());
        if (it != topics.end())
            it->type = pair[1].toString();
    }
    TopicGraph g;
    g.topics = topics.values();
    std::sort(g.topics.begin(), g.topics.end(),
              [](const TopicInfo& a, const TopicInfo& b) { return a.name < b.name; });
    g.nodes = QStringList(nodes.cbegin(), nodes.cend());
    g.nodes.sort();
    return g;
}

Result<qint64> RosMasterApi::pid(int timeoutMs) const
{
    const Result<QVariant> v = call(u"getPid"_s, {m_callerId}, timeoutMs);
    if (!v)
        return v.error();
    return v->toLongLong();
}
