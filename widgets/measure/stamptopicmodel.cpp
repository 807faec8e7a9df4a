// SPDX-License-Identifier: MIT
#include "stamptopicmodel.h"

#include "text/topicmime.h"
#include "latency/pipeline.h"
#include "latency/pipelinediscovery.h"

#include <algorithm>
#include <QSet>

namespace {
constexpr std::size_t kMaxOnlyBad = 100;
}

StampTopicModel::StampTopicModel(QObject* parent)
    : QAbstractListModel(parent)
{ }

void StampTopicModel::update(const PipelineDiscovery& discovery, const Pipeline& pipeline,
                             const QHash<QString, quint64>& malformed)
{
    QStringList topics = discovery.topics();
    // Topics whose every stamp was bad come last, so that they are seen at all: the worst
    // kMaxOnlyBad of them (a broker can hold any number of such topics).
    const QSet<QString> known(topics.cbegin(), topics.cend());
    std::vector<std::pair<quint64, QString>> onlyBad;
    for (auto it = malformed.cbegin(); it != malformed.cend(); ++it)
        if (!known.contains(it.key()))
            onlyBad.emplace_back(it.value(), it.key());
    const std::size_t shown = std::min(onlyBad.size(), kMaxOnlyBad);
    std::partial_sort(onlyBad.begin(), onlyBad.begin() + qsizetype(shown), onlyBad.end(),
                      [](const auto& a, const auto& b) { return a.first != b.first ? a.first > b.first : a.second < b.second; });
    for (std::size_t i = 0; i < shown; ++i)
        topics << onlyBad[i].second;
    if (topics.size() > qsizetype(m_rows.size())) {
        beginInsertRows({}, int(m_rows.size()), int(topics.size()) - 1);
        for (qsizetype i = qsizetype(m_rows.size()); i < topics.size(); ++i)
            m_rows.push_back({topics[i], 0, false});
        endInsertRows();
    } else if (topics.size() < qsizetype(m_rows.size())) {
        beginResetModel();
        m_rows.clear();
        for (const QString& t : topics)
            m_rows.push_back({t, 0, false});
        endResetModel();
    }
    // Only the rows that changed are said: a view repaints (and a NameDelegate re-reads every
    // name) for each row it is told of.
    int first = -1;
    int last = -1;
    for (std::size_t i = 0; i < m_rows.size(); ++i) {
        Row r = m_rows[i];
        r.topic = topics[qsizetype(i)]; // a ROS spelling may have replaced the MQTT one
        r.stamps = discovery.stampCount(r.topic);
        r.malformed = malformed.value(r.topic);
        r.inPipeline = pipeline.indexOf(r.topic) >= 0;
        const Row& old = m_rows[i];
        if (r.topic == old.topic && r.stamps == old.stamps && r.malformed == old.malformed
            && r.inPipeline == old.inPipeline)
            continue;
        m_rows[i] = std::move(r);
        first = first < 0 ? int(i) : first;
        last = int(i);
    }
    if (first >= 0)
        emit dataChanged(index(first), index(last));
}

int StampTopicModel::rowCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : int(m_rows.size());
}

QVariant StampTopicModel::data(const QModelIndex& index, int role) const
{
    if (!checkIndex(index, CheckIndexOption::IndexIsValid | CheckIndexOption::ParentIsInvalid))
        return {};
    const Row& r = m_rows[std::size_t(index.row())];
    switch (role) {
    case Qt::DisplayRole:
        return r.malformed ? tr("%1  (%2, %3 malformed)").arg(r.topic).arg(r.stamps).arg(r.malformed)
                           : tr("%1  (%2)").arg(r.topic).arg(r.stamps);
    case Qt::ToolTipRole:
        if (r.malformed && !r.stamps)
            return tr("%1: %2 messages, none a stamp this tool reads (see the counts below the chart)")
                .arg(r.topic)
                .arg(r.malformed);
        return r.inPipeline ? tr("%1: in the pipeline").arg(r.topic)
                            : tr("%1: not in the pipeline; drag it there or press Enter").arg(r.topic);
    case TopicRole:
        return r.topic;
    case InPipelineRole:
        return r.inPipeline;
    case MalformedRole:
        return r.malformed;
    default:
        return {};
    }
}

Qt::ItemFlags StampTopicModel::flags(const QModelIndex& index) const
{
    return QAbstractListModel::flags(index) | (index.isValid() ? Qt::ItemIsDragEnabled : Qt::NoItemFlags);
}

QStringList StampTopicModel::mimeTypes() const
{
    return {TopicMime::rosType(), TopicMime::mqttType()};
}

QMimeData* StampTopicModel::mimeData(const QModelIndexList& indexes) const
{
    QList<TopicMime::Topic> ros;
    QList<TopicMime::Topic> mqtt;
    for (const QModelIndex& i : indexes) {
        const QString& t = m_rows[std::size_t(i.row())].topic;
        (t.startsWith(u'/') ? ros : mqtt) << TopicMime::Topic {t, QString()};
    }
    return TopicMime::encode(ros.isEmpty() ? TopicMime::mqttType() : TopicMime::rosType(),
                             ros.isEmpty() ? mqtt : ros + mqtt);
}
