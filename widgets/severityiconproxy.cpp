// SPDX-License-Identifier: MIT
#include "severityiconproxy.h"

#include "config/problem.h"

#include <QApplication>
#include <QIcon>
#include <QStyle>

SeverityIconProxy::SeverityIconProxy(int severityRole, QObject* parent)
    : QIdentityProxyModel(parent)
    , m_severityRole(severityRole)
{ }

QVariant SeverityIconProxy::data(const QModelIndex& index, int role) const
{
    if (role == Qt::DecorationRole && index.column() == 0) {
        bool ok = false;
        const int severity = QIdentityProxyModel::data(index, m_severityRole).toInt(&ok);
        if (!ok || severity < 0)
            return {};
        QStyle* style = QApplication::style();
        switch (Severity(severity)) {
        case Severity::Error:
            return style->standardIcon(QStyle::SP_MessageBoxCritical);
        case Severity::Warning:
            return style->standardIcon(QStyle::SP_MessageBoxWarning);
        case Severity::Info:
            return style->standardIcon(QStyle::SP_MessageBoxInformation);
        }
    }
    return QIdentityProxyModel::data(index, role);
}
