// SPDX-License-Identifier: MIT
#include "rostopicview.h"

#include "ros/rostopicmodel.h"
#include "widgets/common/namedelegate.h"
#include "widgets/common/viewsetup.h"

#include <algorithm>
#include <QEvent>
#include <QHeaderView>
#include <QLineEdit>
#include <QScopedValueRollback>
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
    m_topicDelegate = NameDelegate::install(m_table, RosTopicModel::TopicColumn);
    NameDelegate::install(m_table, RosTopicModel::TypeColumn);
    QHeaderView* header = m_table->horizontalHeader();
    header->setSectionResizeMode(QHeaderView::ResizeToContents);
    header->setSectionResizeMode(RosTopicModel::TopicColumn, QHeaderView::Interactive);
    header->setSectionResizeMode(RosTopicModel::TypeColumn, QHeaderView::Interactive);
    connect(header, &QHeaderView::sectionResized, this, [this](int column) {
        if (!m_fitting && (column == RosTopicModel::TopicColumn || column == RosTopicModel::TypeColumn))
            m_userSized = true; // by hand, or restored from the last session
    });
    m_fit.setSingleShot(true);
    m_fit.setInterval(100);
    connect(&m_fit, &QTimer::timeout, this, &RosTopicView::fitColumns);
    const auto refit = [this] { m_fit.start(); };
    connect(m_proxy, &QAbstractItemModel::rowsInserted, this, refit);
    connect(m_proxy, &QAbstractItemModel::modelReset, this, refit);
    connect(m_proxy, &QAbstractItemModel::layoutChanged, this, refit);
    m_table->viewport()->installEventFilter(this);
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

bool RosTopicView::eventFilter(QObject* watched, QEvent* event)
{
    if (watched == m_table->viewport() && event->type() == QEvent::Resize)
        m_fit.start();
    return QWidget::eventFilter(watched, event);
}

void RosTopicView::fitColumns()
{
    if (m_userSized)
        return;
    const QScopedValueRollback fitting(m_fitting, true);
    const int room = m_table->viewport()->width();
    const auto fit = [&](int column, double share) {
        if (m_table->isColumnHidden(column)
            || m_table->horizontalHeader()->sectionResizeMode(column) != QHeaderView::Interactive)
            return;
        const int most = std::max(80, int(room * share));
        m_table->setColumnWidth(
            column,
            std::clamp(static_cast<QAbstractItemView*>(m_table)->sizeHintForColumn(column), 60, most));
    };
    fit(RosTopicModel::TypeColumn, 0.25);
    fit(RosTopicModel::TopicColumn, 0.55);
}
