// SPDX-License-Identifier: MIT
#pragma once

#include "config/bridgeconfig.h"

#include <QUndoCommand>

class ConfigDocument;

/// Undoable edits of a ConfigDocument. Every change the user makes goes through one of these.
namespace ConfigCommands {

/// Adds mappings at a row.
class InsertMappings : public QUndoCommand
{
public:
    InsertMappings(ConfigDocument* doc, int row, const QList<Mapping>& mappings, const QString& text);
    void redo() override;
    void undo() override;
    QList<quint64> ids() const;

private:
    ConfigDocument* m_doc;
    int m_row;
    QList<Mapping> m_mappings;
};

/// Removes mappings; undo puts them back where they were.
class RemoveMappings : public QUndoCommand
{
public:
    RemoveMappings(ConfigDocument* doc, const QList<quint64>& ids, const QString& text);
    void redo() override;
    void undo() override;

private:
    ConfigDocument* m_doc;
    QList<std::pair<int, Mapping>> m_removed; ///< by ascending row
};

/// Replaces mappings by edited versions (one or many: a multi-selection edit is one step).
class EditMappings : public QUndoCommand
{
public:
    EditMappings(ConfigDocument* doc, const QList<Mapping>& before, const QList<Mapping>& after,
                 const QString& text);
    void redo() override;
    void undo() override;

private:
    ConfigDocument* m_doc;
    QList<Mapping> m_before;
    QList<Mapping> m_after;
};

/// Changes the broker or client settings.
class EditBlock : public QUndoCommand
{
public:
    EditBlock(ConfigDocument* doc, OptionScope scope, const OptionBlock& before, const OptionBlock& after,
              const QString& text);
    void redo() override;
    void undo() override;

private:
    ConfigDocument* m_doc;
    OptionScope m_scope;
    OptionBlock m_before;
    OptionBlock m_after;
};

} // namespace ConfigCommands
