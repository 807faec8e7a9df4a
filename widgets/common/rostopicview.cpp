// SPDX-License-Identifier: MIT
#include "rostopicview.h"

#include "ros/rostopicmodel.h"
#include "widgets/common/viewsetup.h"

#include <QLineEdit>
#include <QSortFilterProxyModel>
#include <QTableView>
#include <QVBoxLayout>

RosTopicView::RosTopicView(QAbstractItemModel* source, const QString& placeholder, QWidget* parent)
    : QWidget(parent)
    , m_filter(new QLineEdit(this))
    , m_proxy(new QSortFilterProxyModel(this))
    , m_table(new QTableView(this))
{
    m_filter->setPlaceholderText(placeholder);
    m_filter->setClearButtonEnabled(true);
    m_proxy->setSourceModel(source);
    m_proxy->setSortRole(RosTopicModel::SortRole);
    m_proxy->setFilterCaseSensitivity(Qt::CaseInsensitive);
    m_proxy->setFilterKeyColumn(-1);
    m_table->setModel(m_proxy);
    ViewSetup::records(m_table, RosTopicModel::TopicColumn);
    m_table->setColumnWidth(RosTopicModel::TypeColumn, 130);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_filter);
    layout->addWidget(m_table, 1);
    connect(m_filter, &QLineEdit::textChanged, m_proxy, &QSortFilterProxyModel::setFilterFixedString);
}

void RosTopicView::showOnly(const QList<int>& columns)
{
    for (int c = 0; c < RosTopicModel::ColumnCount; ++c)
        m_table->setColumnHidden(c, !columns.contains(c));
}
