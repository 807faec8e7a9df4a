// SPDX-License-Identifier: MIT
#pragma once

#include "config/bridgeconfig.h"

#include <QWidget>

class ConfigDocument;
class QComboBox;
class QLabel;
class QPlainTextEdit;
class QTimer;

/// The YAML that saving would write, in a chosen layout, updated as the config changes; for a
/// file open read-only, its own text with its error marked.
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
    /// The words above the text (what saving keeps; for a read-only file, why and where).
    QString note() const;
    /// The line (zero-based) marked as the read-only file's error, or -1.
    int errorLine() const { return m_errorLine; }
    QPlainTextEdit* textView() const { return m_text; }

private:
    ConfigDocument* m_doc;
    QComboBox* m_layout;
    QLabel* m_note;
    QPlainTextEdit* m_text;
    QTimer* m_timer;
    bool m_stale = false;
    int m_errorLine = -1;
    /// A file open read-only: its text, with its error's line marked and said above.
    void showReadOnly();

protected:
    void showEvent(class QShowEvent* event) override;
    void changeEvent(QEvent* event) override; ///< a dark palette gets the dark highlighting

public:
    /// Whether the highlighting is the one for dark backgrounds (tests).
    bool isDarkHighlighting() const;

private:
    class YamlHighlighter* m_highlighter = nullptr;
};
