// SPDX-License-Identifier: MIT
#pragma once

#include "latency/pipeline.h"

#include <functional>
#include <QAbstractTableModel>
#include <QHash>

/// The pipeline as the user edits it: stamp topics in order (drag to reorder, drop topics in,
/// Delete to remove), each with its host (editable) and how many stamps it delivered.
///
/// Edits do not apply themselves: they come out as `edited(Pipeline)`, and the owner decides.
class PipelineModel : public QAbstractTableModel
{
    Q_OBJECT
public:
    enum Column { IndexColumn, TopicColumn, HostColumn, StampsColumn, ColumnCount };
    enum Role { TopicRole = Qt::UserRole + 1 };
    static QString rowMimeType() { return QStringLiteral("application/x-bridgescope-pipeline-rows"); }

    explicit PipelineModel(QObject* parent = nullptr);

    void setPipeline(const Pipeline& pipeline);
    const Pipeline& pipeline() const { return m_pipeline; }
    void setStampCounter(std::function<quint64(const QString&)> counter) { m_counter = std::move(counter); }
    /// Re-reads the stamp counts (one dataChanged for the column).
    void refreshCounts();

    /// The pipeline with `topics` inserted before `row` (-1: at the end); those already in it move.
    Pipeline withTopics(const QStringList& topics, int row) const;
    Pipeline withoutRows(QList<int> rows) const;
    Pipeline withRowMoved(int from, int to) const;

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    bool setData(const QModelIndex& index, const QVariant& value, int role = Qt::EditRole) override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;
    QStringList mimeTypes() const override;
    QMimeData* mimeData(const QModelIndexList& indexes) const override;
    Qt::DropActions supportedDropActions() const override { return Qt::CopyAction | Qt::MoveAction; }
    bool canDropMimeData(const QMimeData* data, Qt::DropAction action, int row, int column,
                         const QModelIndex& parent) const override;
    bool dropMimeData(const QMimeData* data, Qt::DropAction action, int row, int column,
                      const QModelIndex& parent) override;

signals:
    void edited(const Pipeline& pipeline);

private:
    QStringList droppedTopics(const QMimeData* data) const;

    Pipeline m_pipeline;
    std::function<quint64(const QString&)> m_counter;
};
