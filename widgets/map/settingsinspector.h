// SPDX-License-Identifier: MIT
#pragma once

#include "config/bridgeconfig.h"

#include <QWidget>

class ConfigDocument;
class OptionForm;
class QUndoStack;

/// Edits the broker and client settings of a config.
class SettingsInspector : public QWidget
{
    Q_OBJECT
public:
    SettingsInspector(ConfigDocument* document, QUndoStack* undoStack, QWidget* parent = nullptr);
    OptionForm* form(OptionScope scope) const;
    void focusField(OptionScope scope, const QString& path);

private:
    void refresh();

    ConfigDocument* m_doc;
    QUndoStack* m_undo;
    OptionForm* m_broker;
    OptionForm* m_client;
};
