// SPDX-License-Identifier: MIT
#pragma once

#include "config/bridgeconfig.h"

#include <QWidget>

class ConfigDocument;
class OptionForm;
class QComboBox;
class QLabel;
class QLineEdit;
class QStackedWidget;
class QUndoStack;

/// Edits the selected mapping(s): direction, topics and every option. With several mappings
/// selected, an option set here is set on all of them in one undo step.
class MappingInspector : public QWidget
{
    Q_OBJECT
public:
    MappingInspector(ConfigDocument* document, QUndoStack* undoStack, QWidget* parent = nullptr);

    void setMappings(const QList<quint64>& ids);
    QList<quint64> mappings() const { return m_ids; }
    /// Puts the keyboard focus on an option (or a topic field) of the shown mapping.
    void focusField(const QString& path);

    OptionForm* form(Direction d) const { return d == Direction::Ros2Mqtt ? m_outForm : m_inForm; }

private:
    QWidget* createEditPage(QWidget* parent);
    void applyOption(OptionScope scope, const QString& path, const QString& text, bool unset);
    void followDocument();
    void refresh();
    QList<Mapping> selected() const;
    void applyToSelection(const QString& description, const std::function<void(Mapping&)>& change);
    void commitTopic(const QString& field, QLineEdit* edit);
    void setDirection(int index);

    ConfigDocument* m_doc;
    QUndoStack* m_undo;
    QList<quint64> m_ids;
    QStackedWidget* m_pages;
    QLabel* m_summary;
    QComboBox* m_direction;
    QLineEdit* m_rosTopic;
    QLineEdit* m_mqttTopic;
    QLabel* m_problems;
    QStackedWidget* m_forms;
    OptionForm* m_outForm;
    OptionForm* m_inForm;
    bool m_refreshing = false;
};
