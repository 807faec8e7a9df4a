// SPDX-License-Identifier: MIT
#pragma once

#include <QStringList>

class QCoreApplication;

/// Loads the translations for the user's language (German ships with Bridgescope).
void installTranslations(QCoreApplication& app);
/// Usage text of the program (GUI options and commands).
QString bridgescopeUsage();
/// Runs the GUI; `arguments` without the program name.
int runGui(int& argc, char** argv);
