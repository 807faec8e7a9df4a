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
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;

private:
    int m_severityRole;
};
