// SPDX-License-Identifier: MIT
#pragma once

#include <QAbstractListModel>
#include <QHash>
#include <QStringList>
#include <vector>

class PipelineDiscovery;
class Pipeline;

/// Every stamp topic seen, with its count; the ones the pipeline does not use stand out.
/// Rows drag as topics (onto the pipeline).
class StampTopicModel : public QAbstractListModel
{
    Q_OBJECT
public:
    enum Role { TopicRole = Qt::UserRole + 1, InPipelineRole, MalformedRole };

    explicit StampTopicModel(QObject* parent = nullptr);
    /// `malformed`: stamps per topic that did not decode; a topic with only those is listed too.
    void update(const PipelineDiscovery& discovery, const Pipeline& pipeline,
                const QHash<QString, quint64>& malformed = {});

    int rowCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;
    QStringList mimeTypes() const override;
    QMimeData* mimeData(const QModelIndexList& indexes) const override;

private:
    struct Row
    {
        QString topic;
        quint64 stamps = 0;
        quint64 malformed = 0;
        bool inPipeline = false;
    };
    std::vector<Row> m_rows;
};
