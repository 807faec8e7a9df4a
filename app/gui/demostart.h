// SPDX-License-Identifier: MIT
#pragma once

#include "demo/demolab.h"

#include <functional>
#include <QString>

class MainWindow;

namespace DemoStart {
/// Starts the demo lab behind the shown window: the servers are launched and then polled on a
/// GUI-thread timer (a loopback connect each, never a wait), the bridges and nodes start once they
/// listen; a progress bar in the status bar says what it waits for meanwhile. `done` gets an empty
/// string when the lab runs (call show() then), else why it did not start.
void start(MainWindow& window, DemoLab& lab, const DemoLab::Options& options,
           const std::function<void(const QString& error)>& done);
/// Shows the running demo lab: its servers, its vehicle config, the Measure page with the paper's
/// Fig. 5 series; says so when the lab stops, and quits on Ctrl+C so that the lab cleans up.
void show(MainWindow& window, const DemoLab& lab);
} // namespace DemoStart
