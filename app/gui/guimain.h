// SPDX-License-Identifier: MIT
#pragma once

#include <QStringList>

class QCoreApplication;

/// Loads the translations for the user's language (German ships with Bridgescope).
void installTranslations(QCoreApplication& app);
/// Usage text of the program (GUI options and commands).
QString bridgescopeUsage();
/// Checks the window's command line (the program's arguments, its name first) without opening
/// anything: -1 when it is good, otherwise the exit status after saying what is wrong.
int checkGuiArguments(const QStringList& arguments);
/// Runs the GUI; `arguments` without the program name.
int runGui(int& argc, char** argv);
