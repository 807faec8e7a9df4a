// SPDX-License-Identifier: MIT
#pragma once

#include "viewhelpers.h"
#include "widgets/experiment/experimentpage.h"
#include "widgets/map/mappage.h"
#include "widgets/reports/reportspage.h"

#include <QUndoStack>

/// The main window's parts that only tests reach, found by the object names the window gives them
/// or, for the map page (a name would move its saved layout), as the window's one MapPage
/// (the window has no getters for them, issue 42).
namespace WindowParts {
using namespace Qt::StringLiterals;
inline MapPage* mapPage(const QObject& window)
{
    return ViewHelpers::only<MapPage>(window);
}
inline ReportsPage* reportsPage(const QObject& window)
{
    return ViewHelpers::named<ReportsPage>(window, u"reportsPage"_s);
}
inline ExperimentPage* experimentPage(const QObject& window)
{
    return ViewHelpers::named<ExperimentPage>(window, u"experimentPage"_s);
}
inline QUndoStack* undoStack(const QObject& window)
{
    return ViewHelpers::named<QUndoStack>(window, u"undoStack"_s);
}
} // namespace WindowParts
