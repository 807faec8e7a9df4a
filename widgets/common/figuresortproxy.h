// SPDX-License-Identifier: MIT
#pragma once

#include <cmath>
#include <QSortFilterProxyModel>

/// Sorts figures by their numbers (the model's `valueRole`: a double or an int, NaN first),
/// everything else by its text: the link tables of the Links page, local and fleet.
class FigureSortProxy : public QSortFilterProxyModel
{
public:
    FigureSortProxy(int valueRole, QObject* parent)
        : QSortFilterProxyModel(parent)
        , m_valueRole(valueRole)
    { }

protected:
    bool lessThan(const QModelIndex& a, const QModelIndex& b) const override
    {
        const QVariant va = a.data(m_valueRole);
        const QVariant vb = b.data(m_valueRole);
        if (va.typeId() == QMetaType::Double || va.typeId() == QMetaType::Int) {
            const double x = va.toDouble();
            const double y = vb.toDouble();
            return (std::isnan(x) ? -1 : x) < (std::isnan(y) ? -1 : y);
        }
        return QSortFilterProxyModel::lessThan(a, b);
    }

private:
    int m_valueRole;
};
