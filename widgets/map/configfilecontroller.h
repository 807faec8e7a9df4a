// SPDX-License-Identifier: MIT
#pragma once

#include "config/bridgeconfig.h"
#include "config/configdocument.h"

#include <functional>
#include <QObject>

class QUndoStack;
class RecentFiles;
class QWidget;

/// File handling of the config editor: new, open, save, save as, export in another layout,
/// generate the peer config, and asking before unsaved edits are lost (what it opens and saves goes
/// among the recent files).
/// The writing itself is ConfigDocument's (core); this class only asks and reports.
///
/// Several configs are open at once (a lab has two ends: the vehicle's and the cloud's). They take
/// turns in the one ConfigDocument the Map page edits: the others wait as snapshots, with their
/// edits, until activate() brings one back. The undo history is the shown config's: it starts
/// anew when another is shown (its commands name the rows of the config they were made in).
class ConfigFileController : public QObject
{
    Q_OBJECT
public:
    /// Files opened and saved go among `recent`.
    ConfigFileController(ConfigDocument* document, QUndoStack* undoStack, RecentFiles* recent,
                         QWidget* dialogParent);

    /// How questions are asked; replaceable so that tests need no modal dialog.
    using Ask = std::function<bool(const QString& title, const QString& question)>;
    void setAsk(Ask ask) { m_ask = std::move(ask); }

    /// Opens a bridge config; one that reads but is broken or too large opens read-only, showing
    /// its text and its error. What kept a file from opening at all goes to `error` if given,
    /// else to a message box.
    bool openFile(const QString& path, QString* error = nullptr);
    bool saveTo(const QString& path, ConfigLayout layout);
    bool exportTo(const QString& path, ConfigLayout layout);
    bool writePeer(const QString& path, const QString& clientId);

    bool newFile();
    bool open();
    bool save();
    bool saveAs();
    bool exportAs(ConfigLayout layout);
    bool generatePeer();
    /// Asks to save unsaved edits of the shown config; false if the user cancels.
    bool maybeSave();
    /// Asks for every open config with unsaved edits; false if the user cancels one.
    bool maybeSaveAll();

    /// The open configs, in the order they were opened; one of them is in the document.
    int openCount() const { return int(m_open.size()); }
    int currentIndex() const { return m_current; }
    QString pathOf(int i) const;
    /// The file's name, or "untitled".
    QString nameOf(int i) const;
    bool isModified(int i) const;
    /// Open only to be read (ConfigDocument::openReadOnly()).
    bool isReadOnly(int i) const;
    BridgeConfig configOf(int i) const;
    /// Shows open config `i` in the document.
    void activate(int i);
    /// Closes open config `i` after asking to save it; false if the user cancels.
    bool closeConfig(int i);

signals:
    void statusMessage(const QString& message);
    /// A config was opened, closed or shown.
    void openConfigsChanged();

private:
    /// The shown config is an untitled one without a mapping or an edit: opening replaces it.
    bool currentIsBlank() const;
    /// Keeps the shown config as a snapshot and makes room for another, shown from now on.
    void stashCurrentForAnother();
    void showError(const QString& title, const QString& message);
    static QString layoutFilter(ConfigLayout layout);

    ConfigDocument* m_doc;
    QUndoStack* m_undo;
    RecentFiles* m_recent;
    QWidget* m_parent;
    Ask m_ask;
    QList<ConfigDocument::Snapshot> m_open; ///< m_open[m_current] is the document's, kept there
    int m_current = 0;
};
