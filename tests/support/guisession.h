// SPDX-License-Identifier: MIT
#pragma once

#include <QChartView>
#include <QGraphicsItem>
#include <QGraphicsTextItem>
#include <QSettings>
#include <QStringList>

/// What GUI tests that play sessions and read charts share.
namespace GuiSession {
/// Points the application's settings at `folder` (INI files) and empties it: the windows a test
/// opens one after another remember into it, as a user's sessions do into theirs.
inline void useSettingsFolder(const QString& folder)
{
    QSettings::setDefaultFormat(QSettings::IniFormat);
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, folder);
    QSettings().clear();
}

/// The texts a chart view draws (axis labels, titles, legend), as the scene holds them.
inline QStringList drawnTexts(QChartView* view)
{
    QStringList out;
    for (QGraphicsItem* item : view->scene()->items())
        if (auto* text = dynamic_cast<QGraphicsTextItem*>(item); text && text->isVisible())
            out << text->toPlainText();
        else if (auto* simple = dynamic_cast<QGraphicsSimpleTextItem*>(item); simple && simple->isVisible())
            out << simple->text();
    return out;
}
} // namespace GuiSession
