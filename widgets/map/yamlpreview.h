// SPDX-License-Identifier: MIT
#pragma once

#include "config/bridgeconfig.h"

#include <QWidget>

class ConfigDocument;
class QComboBox;
class QLabel;
class QPlainTextEdit;
class QTimer;

/// The YAML that saving would write, in a chosen layout, updated as the config changes.
class YamlPreview : public QWidget
{
    Q_OBJECT
public:
    explicit YamlPreview(ConfigDocument* document, QWidget* parent = nullptr);
    ConfigLayout layout() const;
    void setLayout(ConfigLayout layout);
    QString text() const;
    /// Recomputes now instead of after the short delay that batches quick edits.
    void refreshNow();

private:
    ConfigDocument* m_doc;
    QComboBox* m_layout;
    QLabel* m_note;
    QPlainTextEdit* m_text;
    QTimer* m_timer;
    bool m_stale = false;

protected:
    void showEvent(class QShowEvent* event) override;
    void changeEvent(QEvent* event) override; ///< a dark palette gets the dark highlighting

public:
    /// Whether the highlighting is the one for dark backgrounds (tests).
    bool isDarkHighlighting() const;

private:
    class YamlHighlighter* m_highlighter = nullptr;
};
