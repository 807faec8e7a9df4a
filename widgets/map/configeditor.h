// SPDX-License-Identifier: MIT
#pragma once

#include "config/bridgeconfig.h"

#include <QWidget>

class ConfigDocument;
class MappingFilterProxy;
class MappingInspector;
class MappingModel;
class ProblemsPanel;
class QAction;
class QCheckBox;
class QComboBox;
class QLineEdit;
class QTabWidget;
class QTableView;
class QUndoStack;
class SettingsInspector;
class SeverityIconProxy;
class YamlPreview;

/// The bridge config editor: the mapping table with its filter across the width, below it an
/// inspector for the selected mappings and for broker/client settings, the YAML preview and the
/// problems panel.
class ConfigEditor : public QWidget
{
    Q_OBJECT
public:
    ConfigEditor(ConfigDocument* document, QUndoStack* undoStack, QWidget* parent = nullptr);

    QAction* addRos2MqttAction() const { return m_addOut; }
    QAction* addMqtt2RosAction() const { return m_addIn; }
    QAction* deleteAction() const { return m_delete; }
    QAction* duplicateAction() const { return m_duplicate; }

    QTableView* table() const { return m_table; }
    MappingModel* model() const { return m_model; }
    ProblemsPanel* problems() const { return m_problems; }
    QLineEdit* filterEdit() const { return m_filterEdit; }

    QList<quint64> selectedIds() const;
    /// Width of the inspector below the table (the rest goes to the problems beside it).
    void setInspectorWidth(int width);
    void selectMappings(const QList<quint64>& ids);
    /// Adds a mapping (topics proposed) and puts the cursor on its ROS topic.
    void addMapping(Direction direction);
    void deleteSelected();
    void duplicateSelected();

private:
    void createActions();
    QWidget* createMappingPane();
    void setUpTable();
    QWidget* createInspectorTabs();
    void showSettingsProblem(OptionScope scope, const QString& field);
    void showMappingProblem(quint64 id, const QString& field);
    void updateActions();
    /// Disables editing while the document is open read-only, and shows its text.
    void showReadOnly();
    QModelIndex viewIndex(quint64 id) const;

    ConfigDocument* m_doc;
    QUndoStack* m_undo;
    MappingModel* m_model;
    SeverityIconProxy* m_icons;
    MappingFilterProxy* m_filter;
    QTableView* m_table;
    QLineEdit* m_filterEdit;
    QComboBox* m_directionFilter;
    QCheckBox* m_onlyProblems;
    QTabWidget* m_tabs;
    class QSplitter* m_split;
    MappingInspector* m_inspector;
    SettingsInspector* m_settings;
    YamlPreview* m_preview;
    ProblemsPanel* m_problems;
    QAction* m_addOut;
    QAction* m_addIn;
    QAction* m_delete;
    QAction* m_duplicate;
};
