// SPDX-License-Identifier: MIT
#include "latency/pipelinelabels.h"

#include <QHash>

using namespace Qt::StringLiterals;

PipelineLabels::PipelineLabels(const QStringList& topics)
    : m_topics(topics)
{
    // Linear in the topics: labelling used to recompute the common prefix in every call and
    // compare every stage's label with every other's (cubic: 20,000 columns never finished).
    if (m_topics.size() < 2)
        return;
    const QString& first = m_topics.first();
    qsizetype common = first.size();
    for (const QString& other : std::as_const(m_topics)) {
        qsizetype i = 0;
        while (i < common && i < other.size() && other[i] == first[i])
            ++i;
        common = i;
    }
    // The longest common prefix ending in '/' (none when the topics share no character).
    m_prefix = common == 0 ? 0 : first.lastIndexOf(u'/', common - 1) + 1;

    // Between components, the components say it ("mqtt_interface_vehicle → mqtt_interface_cloud"),
    // unless another stage would read the same.
    const int stages = int(m_topics.size()) - 1;
    QStringList brief;
    brief.reserve(stages);
    QHash<QString, int> uses;
    for (int s = 0; s < stages; ++s) {
        const QString a = component(s);
        const QString b = component(s + 1);
        brief << (a == b ? longStageLabel(s) : tr("%1 → %2").arg(a, b));
        ++uses[brief.back()];
    }
    m_stageLabels.reserve(stages);
    for (int s = 0; s < stages; ++s)
        m_stageLabels << (uses.value(brief[s]) > 1 ? longStageLabel(s) : brief[s]);
}

QString PipelineLabels::shortTopic(int topicIndex) const
{
    if (topicIndex < 0 || topicIndex >= m_topics.size())
        return {};
    const QString& t = m_topics[topicIndex];
    const QString rest = t.mid(m_prefix);
    return rest.isEmpty() ? t : rest;
}

QString PipelineLabels::component(int topicIndex) const
{
    const QString t = shortTopic(topicIndex);
    const qsizetype slash = t.indexOf(u'/');
    return slash > 0 ? t.left(slash) : t;
}

QString PipelineLabels::longStageLabel(int stage) const
{
    const QString a = shortTopic(stage);
    const QString b = shortTopic(stage + 1);
    // Within one component ("x/data/in" -> "x/data/out"), name the component once.
    const qsizetype slashA = a.lastIndexOf(u'/');
    const qsizetype slashB = b.lastIndexOf(u'/');
    if (slashA > 0 && slashA == slashB && a.left(slashA) == b.left(slashB))
        return tr("%1 (%2 → %3)").arg(a.left(slashA), a.mid(slashA + 1), b.mid(slashB + 1));
    return tr("%1 → %2").arg(a, b);
}
