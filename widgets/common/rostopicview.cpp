// SPDX-License-Identifier: MIT
#include "rostopicview.h"

#include "topics/topictablemodel.h"
#include "widgets/common/columnfitter.h"
#include "widgets/common/namedelegate.h"
#include "widgets/common/viewsetup.h"

#include <QHeaderView>
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
    m_proxy->setSortRole(TopicTableModel::SortRole);
    m_proxy->setFilterCaseSensitivity(Qt::CaseInsensitive);
    m_proxy->setFilterKeyColumn(-1);
    m_table->setModel(m_proxy);
    ViewSetup::records(m_table, TopicTableModel::TopicColumn);
    m_topicDelegate = NameDelegate::install(m_table, TopicTableModel::TopicColumn);
    NameDelegate::install(m_table, TopicTableModel::TypeColumn);
    m_fitter = new ColumnFitter(m_table);
    QList<int> figures;
    for (int c = 0; c < TopicTableModel::ColumnCount; ++c)
        if (c != TopicTableModel::TopicColumn && c != TopicTableModel::TypeColumn)
            figures << c;
    m_fitter->figures(figures); // rates change every second: measured then, not at every cell
    m_fitter->fit(TopicTableModel::TypeColumn, 0.25);
    m_fitter->fit(TopicTableModel::TopicColumn, 0.55);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_filter);
    layout->addWidget(m_table, 1);
    connect(m_filter, &QLineEdit::textChanged, m_proxy, &QSortFilterProxyModel::setFilterFixedString);
}

void RosTopicView::showOnly(const QList<int>& columns)
{
    for (int c = 0; c < TopicTableModel::ColumnCount; ++c)
        m_table->setColumnHidden(c, !columns.contains(c));
}
