// SPDX-License-Identifier: MIT
#pragma once

#include "config/bridgeconfig.h"

#include <functional>
#include <QObject>

class ConfigDocument;
class QUndoStack;
class QWidget;

/// File handling of the config editor: new, open, save, save as, export in another layout,
/// generate the peer config, recent files, and asking before unsaved edits are lost.
/// The writing itself is ConfigDocument's (core); this class only asks and reports.
class ConfigFileController : public QObject
{
    Q_OBJECT
public:
    ConfigFileController(ConfigDocument* document, QUndoStack* undoStack, QWidget* dialogParent);

    /// How questions are asked; replaceable so that tests need no modal dialog.
    using Ask = std::function<bool(const QString& title, const QString& question)>;
    void setAsk(Ask ask) { m_ask = std::move(ask); }

    /// Opens a bridge config; what went wrong goes to `error` if given, else to a message box.
    bool openFile(const QString& path, QString* error = nullptr);
    /// Remembers a file of any kind among the recent ones (File › Open Recent).
    void addRecent(const QString& path);
    bool saveTo(const QString& path, ConfigLayout layout);
    bool exportTo(const QString& path, ConfigLayout layout);
    bool writePeer(const QString& path, const QString& clientId);
    QStringList recentFiles() const;

    bool newFile();
    bool open();
    bool save();
    bool saveAs();
    bool exportAs(ConfigLayout layout);
    bool generatePeer();
    /// Asks to save unsaved edits; false if the user cancels.
    bool maybeSave();

signals:
    void recentFilesChanged(const QStringList& files);
    void statusMessage(const QString& message);

private:
    void showError(const QString& title, const QString& message);
    static QString layoutFilter(ConfigLayout layout);

    ConfigDocument* m_doc;
    QUndoStack* m_undo;
    QWidget* m_parent;
    Ask m_ask;
};
