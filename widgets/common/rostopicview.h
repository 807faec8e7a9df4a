// SPDX-License-Identifier: MIT
#pragma once

#include <QList>
#include <QWidget>

class QAbstractItemModel;
class QLineEdit;
class QSortFilterProxyModel;
class QTableView;

/// The ROS graph's topics as a filterable, sortable table: a filter line over a table of `source`
/// (a RosTopicModel, or a proxy of one), matched in every column, case-insensitive. The ROS side
/// of the Discover and Map pages.
class RosTopicView : public QWidget
{
    Q_OBJECT
public:
    RosTopicView(QAbstractItemModel* source, const QString& placeholder, QWidget* parent = nullptr);

    QLineEdit* filterEdit() const { return m_filter; }
    QSortFilterProxyModel* proxy() const { return m_proxy; }
    QTableView* table() const { return m_table; }
    /// Hides every column but these (RosTopicModel's column numbers).
    void showOnly(const QList<int>& columns);

private:
    QLineEdit* m_filter;
    QSortFilterProxyModel* m_proxy;
    QTableView* m_table;
};
