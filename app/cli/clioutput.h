// SPDX-License-Identifier: MIT
#pragma once

#include <QString>

/// Plain text to the terminal, without going through the Qt message handler.
namespace CliOutput {
void out(const QString& text); ///< a line to stdout
void err(const QString& text); ///< a line to stderr
} // namespace CliOutput
