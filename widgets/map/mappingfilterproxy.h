// SPDX-License-Identifier: MIT
#pragma once

#include <QSortFilterProxyModel>

/// Filters the mapping table by text (either topic), direction, and "only with problems".
class MappingFilterProxy : public QSortFilterProxyModel
{
    Q_OBJECT
public:
    enum DirectionFilter { AllDirections = -1 };
    explicit MappingFilterProxy(QObject* parent = nullptr);

    void setText(const QString& text);
    void setDirection(int direction); ///< int(Direction) or AllDirections
    void setOnlyProblems(bool only);

protected:
    bool filterAcceptsRow(int sourceRow, const QModelIndex& sourceParent) const override;

private:
    QString m_text;
    int m_direction = AllDirections;
    bool m_onlyProblems = false;
};
