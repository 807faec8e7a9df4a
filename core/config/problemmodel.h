// SPDX-License-Identifier: MIT
#pragma once

#include "config/problem.h"

#include <QAbstractTableModel>

class ConfigDocument;

/// The problems of a ConfigDocument: errors first, then warnings, each with where it is.
class ProblemModel : public QAbstractTableModel
{
    Q_OBJECT
public:
    enum Column { MessageColumn, LocationColumn, ColumnCount };
    enum Role {
        MappingIdRole = Qt::UserRole + 1,
        FieldRole, ///< option path the problem is about
        SeverityRole, ///< int(Severity)
        ScopeRole, ///< int(OptionScope), for settings problems
        FixRole,
    };

    explicit ProblemModel(ConfigDocument* document, QObject* parent = nullptr);

    const Problem& problem(int row) const { return m_problems.at(row); }
    int errorCount() const { return m_errors; }
    int warningCount() const { return m_warnings; }
    /// "no problems", "1 error", "2 errors, 1 warning", ...
    static QString countText(int errors, int warnings);

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

signals:
    void countsChanged(int errors, int warnings);

private:
    void refresh();

    ConfigDocument* m_document;
    QList<Problem> m_problems;
    int m_errors = 0;
    int m_warnings = 0;
};
