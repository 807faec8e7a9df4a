// SPDX-License-Identifier: MIT
#pragma once

#include "base/result.h"

#include <QCoreApplication>
#include <QString>

/// A host reached over OpenSSH, from an experiment plan's `ssh://user@host[:port]`: the user
/// ([a-z_][a-z0-9_-]{0,31}), a DNS name or an IPv4/IPv6 literal, a port 1–65535. Never a password:
/// keys or an agent only.
struct RemoteHost
{
    Q_DECLARE_TR_FUNCTIONS(RemoteHost)
public:
    QString user;
    QString host; ///< a DNS name, or an IP literal without brackets
    quint16 port = 22;

    /// Parses `ssh://user@host[:port]` (IPv6 in brackets). Anything else is an error saying what
    /// is wrong; a URL with a password is refused without repeating it.
    static Result<RemoteHost> parse(const QString& url);
    /// ssh://user@host[:port], the port only when it is not 22.
    QString url() const;
    /// user@host as ssh's destination (an IPv6 literal without brackets).
    QString destination() const;

    friend bool operator==(const RemoteHost& a, const RemoteHost& b)
    {
        return a.user == b.user && a.host == b.host && a.port == b.port;
    }
};
