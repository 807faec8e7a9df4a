// SPDX-License-Identifier: MIT
#pragma once

#include <QList>
#include <QWidget>

class QAbstractItemModel;
class QLineEdit;
class QSortFilterProxyModel;
class QTableView;
class ColumnFitter;
class NameDelegate;

/// The ROS graph's topics as a filterable, sortable table: a filter line over a table of `source`
/// (a TopicTableModel, or a proxy of one), matched in every column, case-insensitive. The ROS side
/// of the Discover and Map pages.
///
/// Names are what people look for: the topic and type columns draw through NameDelegate (rows stay
/// told apart when narrow, full names in tooltips), and take the room their content needs, up to a
/// share of the table, until the user sizes a column (or the window's memory does).
class RosTopicView : public QWidget
{
    Q_OBJECT
public:
    RosTopicView(QAbstractItemModel* source, const QString& placeholder, QWidget* parent = nullptr);

    QLineEdit* filterEdit() const { return m_filter; }
    QSortFilterProxyModel* proxy() const { return m_proxy; }
    QTableView* table() const { return m_table; }
    /// Hides every column but these (TopicTableModel's column numbers).
    void showOnly(const QList<int>& columns);
    NameDelegate* topicDelegate() const { return m_topicDelegate; }

private:
    QLineEdit* m_filter;
    QSortFilterProxyModel* m_proxy;
    QTableView* m_table;
    NameDelegate* m_topicDelegate;
    ColumnFitter* m_fitter;
};
