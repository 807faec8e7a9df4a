// SPDX-License-Identifier: MIT
#pragma once

#include "config/bridgeconfig.h"
#include "config/mappinghealth.h"

#include <functional>
#include <QAbstractTableModel>

class ConfigDocument;

/// The mappings of a ConfigDocument as a table (both directions), updated row by row.
///
/// Edits made through setData() go to an edit handler, so that the GUI can route them through
/// its undo stack; without one they change the document directly.
class MappingModel : public QAbstractTableModel
{
    Q_OBJECT
public:
    enum Column {
        DirectionColumn,
        RosTopicColumn,
        MqttTopicColumn,
        OptionsColumn,
        HealthColumn,
        ColumnCount
    };
    enum Role {
        MappingIdRole = Qt::UserRole + 1,
        DirectionRole, ///< int(Direction)
        SeverityRole, ///< int(Severity) of the worst problem, or -1
        ProblemsRole, ///< QStringList of problem messages
        SortRole,
        HealthStateRole, ///< int(MappingHealth::State), -1 when nothing is known
    };
    using EditHandler = std::function<void(const Mapping& before, const Mapping& after)>;
    /// Handles dropped topics: on a mapping (`row` >= 0) or beside the mappings (`row` < 0).
    using DropHandler = std::function<bool(const QMimeData* data, int row)>;

    explicit MappingModel(ConfigDocument* document, QObject* parent = nullptr);

    void setEditHandler(EditHandler handler) { m_editHandler = std::move(handler); }
    void setDropHandler(DropHandler handler) { m_dropHandler = std::move(handler); }
    /// Live health of the mappings (from discovery), shown in the Health column.
    void setHealth(const QHash<quint64, MappingHealth>& health);
    const MappingHealth* health(quint64 id) const;
    ConfigDocument* document() const { return m_document; }
    QModelIndex indexOfMapping(quint64 id, int column = 0) const;

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;
    bool setData(const QModelIndex& index, const QVariant& value, int role = Qt::EditRole) override;
    QHash<int, QByteArray> roleNames() const override;
    QStringList mimeTypes() const override;
    Qt::DropActions supportedDropActions() const override;
    bool canDropMimeData(const QMimeData* data, Qt::DropAction action, int row, int column,
                         const QModelIndex& parent) const override;
    bool dropMimeData(const QMimeData* data, Qt::DropAction action, int row, int column,
                      const QModelIndex& parent) override;

    static QString directionText(Direction d);
    /// "primitive, stamped, qos 1, retained": the options that differ from mqtt_client's defaults.
    static QString optionsSummary(const Mapping& m);

private:
    void onProblemsChanged();

    ConfigDocument* m_document;
    EditHandler m_editHandler;
    DropHandler m_dropHandler;
    QHash<quint64, MappingHealth> m_health;
    QHash<quint64, int> m_shownSeverity; ///< what the view was last told, to signal only changes
};
