// SPDX-License-Identifier: MIT
#pragma once

#include "watch/watchrules.h"

#include <QDialog>

class QLabel;
class QPlainTextEdit;
class QPushButton;

/// The watch rules as YAML, edited in place: checked as it is typed (the error names its line),
/// applied only when valid, loaded from and saved to a file.
class RulesEditor : public QDialog
{
    Q_OBJECT
public:
    explicit RulesEditor(const WatchRules& rules, QWidget* parent = nullptr);

    /// The rules of the text, when it is valid.
    std::optional<WatchRules> rules() const { return m_rules; }

private:
    void check();
    void load();
    void save();

    QPlainTextEdit* m_text;
    QLabel* m_status;
    QPushButton* m_apply;
    std::optional<WatchRules> m_rules;
};
