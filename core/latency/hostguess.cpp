// SPDX-License-Identifier: MIT
#include "latency/hostguess.h"

#include <QRegularExpression>

using namespace Qt::StringLiterals;

namespace {
/// The host a name part stands for, or empty.
QString hostOfToken(QStringView token)
{
    static const QStringList vehicle {u"vehicle"_s, u"car"_s, u"robot"_s, u"ego"_s};
    static const QStringList cloud {u"cloud"_s, u"edge"_s, u"server"_s, u"backend"_s};
    for (const QString& v : vehicle)
        if (token.compare(v, Qt::CaseInsensitive) == 0)
            return u"vehicle"_s;
    for (const QString& c : cloud)
        if (token.compare(c, Qt::CaseInsensitive) == 0)
            return u"cloud"_s;
    return {};
}
} // namespace

QString HostGuess::ofName(const QString& topic)
{
    static const QRegularExpression split(u"[^A-Za-z0-9]+"_s);
    const QStringList tokens = topic.split(split, Qt::SkipEmptyParts);
    for (const QString& token : tokens)
        if (QString host = hostOfToken(token); !host.isEmpty())
            return host;
    return {};
}

QHash<QString, QString> HostGuess::ofTopics(const QStringList& topics)
{
    QStringList hosts;
    for (const QString& t : topics)
        hosts << ofName(t);
    // Unknown ones take the previous known host, or the next one at the start.
    QString previous;
    for (QString& h : hosts) {
        if (h.isEmpty())
            h = previous;
        else
            previous = h;
    }
    QString next;
    for (qsizetype i = hosts.size() - 1; i >= 0; --i) {
        if (hosts[i].isEmpty())
            hosts[i] = next;
        else
            next = hosts[i];
    }
    QHash<QString, QString> out;
    for (qsizetype i = 0; i < topics.size(); ++i)
        if (!hosts[i].isEmpty())
            out.insert(topics[i], hosts[i]);
    return out;
}
