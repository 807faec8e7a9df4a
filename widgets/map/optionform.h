// SPDX-License-Identifier: MIT
#pragma once

#include "config/bridgeconfig.h"
#include "config/problem.h"

#include <QHash>
#include <QWidget>

class QLabel;

/// A form for the options of one scope (broker, client, ros2mqtt or mqtt2ros), built from the
/// option schema: booleans and enums as combo boxes that can also say "default", everything else
/// as line edits whose placeholder shows mqtt_client's default.
///
/// It shows one block or several at once (a multi-selection); a value that differs between them
/// shows as "(mixed)", and an edit applies to all of them.
class OptionForm : public QWidget
{
    Q_OBJECT
public:
    OptionForm(OptionScope scope, const QStringList& excludedPaths, QWidget* parent = nullptr);

    void setBlocks(const QList<OptionBlock>& blocks);
    /// Marks the options these problems are about.
    void setProblems(const QList<Problem>& problems);
    QWidget* editor(const QString& path) const;
    void focusOption(const QString& path);
    OptionScope scope() const { return m_scope; }

signals:
    /// The user changed an option. `unset`: remove it, so that mqtt_client's default applies.
    void optionEdited(const QString& path, const QString& text, bool unset);

private:
    struct Row
    {
        const OptionSpec* spec = nullptr;
        QWidget* editor = nullptr;
        QLabel* marker = nullptr;
        QString shown; ///< the value the editor was last filled with
        bool mixed = false;
    };
    void buildRow(const OptionSpec& spec, QWidget* parent, class QFormLayout* layout);
    void fill(Row& row, const QString& value, bool mixed, bool isSet);
    void commitLineEdit(const QString& path);
    void commitCombo(const QString& path);

    OptionScope m_scope;
    QHash<QString, Row> m_rows;
    bool m_filling = false;
};
