// SPDX-License-Identifier: MIT
#include "remote/remotehost.h"

#include <QHostAddress>
#include <QRegularExpression>

using namespace Qt::Literals::StringLiterals;

namespace {

constexpr int s_maxUrlLength = 300;

bool isDnsName(const QString& host)
{
    // RFC 1123 labels: letters, digits and inner hyphens, at most 63 each, 253 in all. A name never
    // starts with '-', so it cannot be read as one of ssh's options.
    static const QRegularExpression name(
        uR"(^[A-Za-z0-9](?:[A-Za-z0-9-]{0,61}[A-Za-z0-9])?(?:\.[A-Za-z0-9](?:[A-Za-z0-9-]{0,61}[A-Za-z0-9])?)*$)"_s);
    static const QRegularExpression allNumeric(uR"(^[0-9.]+$)"_s);
    return host.size() <= 253 && name.match(host).hasMatch() && !allNumeric.match(host).hasMatch();
}

bool isIpv4(const QString& host)
{
    static const QRegularExpression dotted(uR"(^\d{1,3}(?:\.\d{1,3}){3}$)"_s);
    QHostAddress address;
    return dotted.match(host).hasMatch() && address.setAddress(host)
        && address.protocol() == QAbstractSocket::IPv4Protocol;
}

bool isIpv6(const QString& host)
{
    static const QRegularExpression chars(uR"(^[0-9A-Fa-f:.]+$)"_s);
    QHostAddress address;
    return chars.match(host).hasMatch() && address.setAddress(host)
        && address.protocol() == QAbstractSocket::IPv6Protocol;
}

} // namespace

Result<RemoteHost> RemoteHost::parse(const QString& url)
{
    const QString want = tr("want ssh://user@host or ssh://user@host:port");
    if (url.size() > s_maxUrlLength)
        return LocatedError {tr("a host URL longer than %1 characters").arg(s_maxUrlLength)};
    // Checked before anything is repeated in a message, whatever the scheme: a password never
    // appears in one.
    const qsizetype scheme = url.indexOf(u"://"_s);
    const QString authority = url.mid(scheme < 0 ? 0 : scheme + 3);
    const qsizetype lastAt = authority.lastIndexOf(u'@');
    if (lastAt >= 0 && authority.left(lastAt).contains(u':'))
        return LocatedError {tr("a password in a host URL is never accepted: use a key or an ssh agent "
                                "(ssh://user@host)")};
    if (!url.startsWith(u"ssh://"_s))
        return LocatedError {tr("\"%1\" is not an ssh:// URL: %2").arg(url, want)};
    QString rest = url.mid(6);
    const qsizetype at = rest.lastIndexOf(u'@');
    if (at < 0)
        return LocatedError {tr("\"%1\" names no user: %2").arg(url, want)};
    RemoteHost host;
    host.user = rest.left(at);
    static const QRegularExpression user(uR"(^[a-z_][a-z0-9_-]{0,31}$)"_s);
    if (!user.match(host.user).hasMatch())
        return LocatedError {tr("\"%1\" is not a user name (lower-case letters, digits, '_' and '-', "
                                "at most 32, not starting with a digit or '-')")
                                 .arg(host.user)};
    rest = rest.mid(at + 1);
    QString port;
    if (rest.startsWith(u'[')) {
        const qsizetype close = rest.indexOf(u']');
        if (close < 0)
            return LocatedError {tr("\"%1\": an IPv6 address without its closing ']'").arg(url)};
        host.host = rest.mid(1, close - 1);
        if (!isIpv6(host.host))
            return LocatedError {tr("\"%1\" is not an IPv6 address").arg(host.host)};
        rest = rest.mid(close + 1);
        if (!rest.isEmpty() && !rest.startsWith(u':'))
            return LocatedError {tr("\"%1\": nothing may follow the host but :port").arg(url)};
        port = rest.mid(1);
        if (rest.isEmpty())
            port.clear();
        else if (port.isEmpty())
            return LocatedError {tr("\"%1\": an empty port").arg(url)};
    } else {
        const qsizetype colon = rest.indexOf(u':');
        if (colon >= 0 && rest.indexOf(u':', colon + 1) >= 0)
            return LocatedError {
                tr("\"%1\": an IPv6 address goes in brackets (ssh://user@[::1]:22)").arg(url)};
        host.host = colon >= 0 ? rest.left(colon) : rest;
        if (colon >= 0) {
            port = rest.mid(colon + 1);
            if (port.isEmpty())
                return LocatedError {tr("\"%1\": an empty port").arg(url)};
        }
        if (host.host.isEmpty())
            return LocatedError {tr("\"%1\" names no host: %2").arg(url, want)};
        if (!isIpv4(host.host) && !isDnsName(host.host))
            return LocatedError {tr("\"%1\" is neither a host name nor an IP address (a path, a query or "
                                    "other characters are not allowed)")
                                     .arg(host.host)};
    }
    if (!port.isEmpty()) {
        static const QRegularExpression digits(uR"(^[0-9]{1,5}$)"_s);
        const int value = digits.match(port).hasMatch() ? port.toInt() : 0;
        if (value < 1 || value > 65535)
            return LocatedError {tr("\"%1\" is not a port (1 to 65535)").arg(port)};
        host.port = quint16(value);
    }
    return host;
}

QString RemoteHost::url() const
{
    const QString name = host.contains(u':') ? u'[' + host + u']' : host;
    return u"ssh://"_s + user + u'@' + name + (port == 22 ? QString() : u':' + QString::number(port));
}

QString RemoteHost::destination() const
{
    return user + u'@' + host;
}
