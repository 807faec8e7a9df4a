// SPDX-License-Identifier: MIT
#include "severityiconproxy.h"

#include "config/mappinghealth.h"
#include "config/problem.h"

#include <QApplication>
#include <QHash>
#include <QIcon>
#include <QPainter>
#include <QPixmap>
#include <QStyle>

SeverityIconProxy::SeverityIconProxy(int severityRole, QObject* parent)
    : QIdentityProxyModel(parent)
    , m_severityRole(severityRole)
{ }

void SeverityIconProxy::setHealthColumn(int column, int stateRole)
{
    m_healthColumn = column;
    m_healthRole = stateRole;
}

QIcon SeverityIconProxy::healthIcon(int state)
{
    static QHash<int, QIcon> cache;
    if (const auto it = cache.constFind(state); it != cache.cend())
        return *it;
    QColor colour;
    switch (MappingHealth::State(state)) {
    case MappingHealth::Healthy:
        colour = QColor(0x2e, 0x7d, 0x32);
        break;
    case MappingHealth::NoBridge:
        colour = QColor(0xe0, 0x8e, 0x00);
        break;
    case MappingHealth::TypeMismatch:
    case MappingHealth::QosMismatch:
        colour = QColor(0xb0, 0x00, 0x20);
        break;
    case MappingHealth::Idle:
    case MappingHealth::Missing:
        colour = QColor(0x9e, 0x9e, 0x9e);
        break;
    case MappingHealth::Unknown:
        return {};
    }
    QPixmap dot(12, 12);
    dot.fill(Qt::transparent);
    QPainter p(&dot);
    p.setRenderHint(QPainter::Antialiasing);
    p.setPen(colour.darker(130));
    if (state == MappingHealth::Missing)
        p.setBrush(Qt::NoBrush); // a ring: the topic is not there at all
    else
        p.setBrush(colour);
    p.drawEllipse(QRectF(1.5, 1.5, 9, 9));
    p.end();
    return cache.insert(state, QIcon(dot)).value();
}

QVariant SeverityIconProxy::data(const QModelIndex& index, int role) const
{
    if (role == Qt::DecorationRole && index.column() == m_healthColumn && m_healthColumn >= 0) {
        bool ok = false;
        const int state = QIdentityProxyModel::data(index, m_healthRole).toInt(&ok);
        return ok && state >= 0 ? QVariant(healthIcon(state)) : QVariant();
    }
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
