// SPDX-License-Identifier: MIT
#pragma once

#include <QIdentityProxyModel>

/// Adds an error/warning icon in the first column from a model's severity role (core models
/// carry no icons: core links no GUI module).
class SeverityIconProxy : public QIdentityProxyModel
{
    Q_OBJECT
public:
    SeverityIconProxy(int severityRole, QObject* parent = nullptr);
    /// Also a coloured dot in `column` from a MappingHealth state in `stateRole`.
    void setHealthColumn(int column, int stateRole);
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    static QIcon healthIcon(int state);

private:
    int m_severityRole;
    int m_healthColumn = -1;
    int m_healthRole = -1;
};
