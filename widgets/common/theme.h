// SPDX-License-Identifier: MIT
#pragma once

#include <QStringList>

/// The window's colours: the desktop's (`system`), or Fusion with a light or a dark palette for
/// desktops whose Qt integration offers no dark theme (X11 without a platform theme, SSH, Xvfb).
/// Charts and the YAML preview follow whichever palette is in force (ChartStyle).
namespace Theme {
QStringList names(); ///< system, light, dark
/// Applies a theme to the application; false for a name that is none.
bool apply(const QString& name);
QString current();
} // namespace Theme
