// SPDX-License-Identifier: MIT
#include "problemmodel.h"

#include "config/configdocument.h"

#include <algorithm>

using namespace Qt::StringLiterals;

ProblemModel::ProblemModel(ConfigDocument* document, QObject* parent)
    : QAbstractTableModel(parent)
    , m_document(document)
{
    connect(document, &ConfigDocument::problemsChanged, this, &ProblemModel::refresh);
    refresh();
}

void ProblemModel::refresh()
{
    QList<Problem> problems = m_document->problems();
    std::stable_sort(problems.begin(), problems.end(),
                     [](const Problem& a, const Problem& b) { return int(a.severity) > int(b.severity); });
    // The whole list is replaced at once: validation produces it anew on every edit.
    beginResetModel();
    m_problems = problems;
    m_errors = int(std::count_if(m_problems.cbegin(), m_problems.cend(),
                                 [](const Problem& p) { return p.severity == Severity::Error; }));
    m_warnings = int(std::count_if(m_problems.cbegin(), m_problems.cend(),
                                   [](const Problem& p) { return p.severity == Severity::Warning; }));
    endResetModel();
    emit countsChanged(m_errors, m_warnings);
}

QString ProblemModel::countText(int errors, int warnings)
{
    QStringList parts;
    if (errors > 0)
        parts << (errors == 1 ? tr("1 error") : tr("%1 errors").arg(errors));
    if (warnings > 0)
        parts << (warnings == 1 ? tr("1 warning") : tr("%1 warnings").arg(warnings));
    return parts.isEmpty() ? tr("no problems") : parts.join(u", "_s);
}

int ProblemModel::rowCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : int(m_problems.size());
}

int ProblemModel::columnCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant ProblemModel::data(const QModelIndex& index, int role) const
{
    if (!checkIndex(index, CheckIndexOption::IndexIsValid | CheckIndexOption::ParentIsInvalid))
        return {};
    const Problem& p = m_problems.at(index.row());
    switch (role) {
    case Qt::DisplayRole:
        if (index.column() == MessageColumn)
            return p.message;
        if (p.pos.isValid())
            return tr("line %1, column %2").arg(p.pos.line + 1).arg(p.pos.column + 1);
        return p.mappingId ? tr("new mapping") : QString();
    case Qt::ToolTipRole:
        return p.fix.isEmpty() ? p.message : p.message + u"\n→ "_s + p.fix;
    case MappingIdRole:
        return QVariant::fromValue(p.mappingId);
    case FieldRole:
        return p.field;
    case SeverityRole:
        return int(p.severity);
    case ScopeRole:
        return int(p.scope);
    case FixRole:
        return p.fix;
    }
    return {};
}

QVariant ProblemModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    return section == MessageColumn ? tr("Problem") : tr("Where");
}
