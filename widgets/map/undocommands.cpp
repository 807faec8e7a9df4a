// SPDX-License-Identifier: MIT
#include "undocommands.h"

#include "config/configdocument.h"

#include <algorithm>

namespace ConfigCommands {

InsertMappings::InsertMappings(ConfigDocument* doc, int row, const QList<Mapping>& mappings,
                               const QString& text)
    : QUndoCommand(text)
    , m_doc(doc)
    , m_row(row)
    , m_mappings(mappings)
{
    for (Mapping& m : m_mappings) {
        if (m.id == 0)
            m.id = Mapping::nextId();
    }
}

void InsertMappings::redo()
{
    m_doc->insertMappings(m_row, m_mappings);
}

void InsertMappings::undo()
{
    m_doc->removeMappings(ids());
}

QList<quint64> InsertMappings::ids() const
{
    QList<quint64> out;
    for (const Mapping& m : m_mappings)
        out << m.id;
    return out;
}

RemoveMappings::RemoveMappings(ConfigDocument* doc, const QList<quint64>& ids, const QString& text)
    : QUndoCommand(text)
    , m_doc(doc)
{
    for (quint64 id : ids) {
        const int row = doc->rowOf(id);
        if (row >= 0)
            m_removed.append({row, doc->mapping(row)});
    }
    std::sort(m_removed.begin(), m_removed.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
}

void RemoveMappings::redo()
{
    QList<quint64> ids;
    for (const auto& [row, m] : std::as_const(m_removed))
        ids << m.id;
    m_doc->removeMappings(ids);
}

void RemoveMappings::undo()
{
    // Ascending rows: each insert puts a mapping back where it was before the later ones.
    for (const auto& [row, m] : std::as_const(m_removed))
        m_doc->insertMappings(row, {m});
}

EditMappings::EditMappings(ConfigDocument* doc, const QList<Mapping>& before, const QList<Mapping>& after,
                           const QString& text)
    : QUndoCommand(text)
    , m_doc(doc)
    , m_before(before)
    , m_after(after)
{ }

void EditMappings::redo()
{
    for (const Mapping& m : std::as_const(m_after))
        m_doc->replaceMapping(m);
}

void EditMappings::undo()
{
    for (const Mapping& m : std::as_const(m_before))
        m_doc->replaceMapping(m);
}

EditBlock::EditBlock(ConfigDocument* doc, OptionScope scope, const OptionBlock& before,
                     const OptionBlock& after, const QString& text)
    : QUndoCommand(text)
    , m_doc(doc)
    , m_scope(scope)
    , m_before(before)
    , m_after(after)
{ }

void EditBlock::redo()
{
    m_doc->setBlock(m_scope, m_after);
}

void EditBlock::undo()
{
    m_doc->setBlock(m_scope, m_before);
}

} // namespace ConfigCommands
