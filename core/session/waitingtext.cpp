// SPDX-License-Identifier: MIT
#include "waitingtext.h"

using namespace Qt::StringLiterals;

QString WaitingText::topicsText(const QStringList& topics)
{
    if (topics.isEmpty())
        return {};
    if (topics.size() == 1)
        return topics.first();
    // The prefix every topic shares, up to a '/', said once.
    const QString& first = topics.first();
    qsizetype common = first.size();
    for (const QString& t : topics) {
        qsizetype i = 0;
        while (i < common && i < t.size() && t[i] == first[i])
            ++i;
        common = i;
    }
    const qsizetype prefix = common == 0 ? 0 : first.lastIndexOf(u'/', common - 1) + 1;
    QStringList shown;
    for (qsizetype i = 0; i < topics.size() && i < kNamedTopics; ++i)
        shown << topics[i].mid(prefix);
    if (topics.size() > kNamedTopics)
        shown << tr("and %1 more").arg(topics.size() - kNamedTopics);
    return prefix > 0 ? tr("%1 topics under %2 (%3)").arg(topics.size()).arg(first.left(prefix), shown.join(u", "_s))
                      : tr("%1 topics (%2)").arg(topics.size()).arg(shown.join(u", "_s));
}

QString WaitingText::text(const QDateTime& now) const
{
    QString from;
    if (!broker.isEmpty() && !master.isEmpty())
        from = tr(" from the broker %1 and the ROS master %2").arg(broker, master);
    else if (!broker.isEmpty())
        from = tr(" from the broker %1").arg(broker);
    else if (!master.isEmpty())
        from = tr(" from the ROS master %1").arg(master);
    const QString on = topics.isEmpty() ? QString() : tr(" on %1").arg(topicsText(topics));
    return tr("nothing has arrived since %1 (%2 s): no %3 yet%4%5")
        .arg(since.toString(u"HH:mm:ss"_s))
        .arg(since.secsTo(now))
        .arg(what, on, from);
}
