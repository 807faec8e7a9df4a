// SPDX-License-Identifier: MIT
#include "problemspanel.h"

#include "config/problemmodel.h"
#include "widgets/common/severityiconproxy.h"

#include <QHeaderView>
#include <QLabel>
#include <QTreeView>
#include <QVBoxLayout>

ProblemsPanel::ProblemsPanel(ConfigDocument* document, QWidget* parent)
    : QWidget(parent)
    , m_model(new ProblemModel(document, this))
{
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    m_title = new QLabel(this);
    layout->addWidget(m_title);
    m_view = new QTreeView(this);
    m_view->setObjectName(QStringLiteral("problemsView"));
    m_view->setRootIsDecorated(false);
    m_view->setUniformRowHeights(true);
    m_view->setAlternatingRowColors(true);
    auto* proxy = new SeverityIconProxy(ProblemModel::SeverityRole, this);
    proxy->setSourceModel(m_model);
    m_view->setModel(proxy);
    m_view->header()->setStretchLastSection(false);
    m_view->header()->setSectionResizeMode(ProblemModel::MessageColumn, QHeaderView::Stretch);
    m_view->header()->setSectionResizeMode(ProblemModel::LocationColumn, QHeaderView::ResizeToContents);
    layout->addWidget(m_view);
    m_title->setBuddy(m_view);

    auto updateTitle = [this](int errors, int warnings) {
        m_title->setText(tr("&Problems: %1").arg(ProblemModel::countText(errors, warnings)));
    };
    connect(m_model, &ProblemModel::countsChanged, this, updateTitle);
    updateTitle(m_model->errorCount(), m_model->warningCount());
    connect(m_view, &QTreeView::activated, this, [this](const QModelIndex& index) {
        const auto id = index.data(ProblemModel::MappingIdRole).value<quint64>();
        const QString field = index.data(ProblemModel::FieldRole).toString();
        if (id)
            emit mappingProblemActivated(id, field);
        else
            emit settingsProblemActivated(OptionScope(index.data(ProblemModel::ScopeRole).toInt()), field);
    });
}
