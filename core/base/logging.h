// SPDX-License-Identifier: MIT
#pragma once

#include <QLoggingCategory>
#include <QStringList>

// One logging category per layer that talks to the outside world. Debug messages are off by
// default; `--verbose` turns on every `bridgescope.*` category, QT_LOGGING_RULES any subset
// (`QT_LOGGING_RULES="bridgescope.mqtt.debug=true"`), and it overrides --verbose. Messages never
// carry credentials: URLs go through Secrets::urlWithoutCredentials() first.
Q_DECLARE_LOGGING_CATEGORY(lcConfig) ///< bridgescope.config: files read and written
Q_DECLARE_LOGGING_CATEGORY(lcMqtt) ///< bridgescope.mqtt: connections, reconnects, subscriptions
Q_DECLARE_LOGGING_CATEGORY(lcRos) ///< bridgescope.ros: the node, the master, subscriptions
Q_DECLARE_LOGGING_CATEGORY(lcRos2) ///< bridgescope.ros2: the DDS participant, discovery, raw subscriptions
Q_DECLARE_LOGGING_CATEGORY(lcRecord) ///< bridgescope.record: run files and the recorder
Q_DECLARE_LOGGING_CATEGORY(lcReport) ///< bridgescope.report: inputs loaded, the bag helper
Q_DECLARE_LOGGING_CATEGORY(lcBridge) ///< bridgescope.bridge: the reference bridge's mappings
Q_DECLARE_LOGGING_CATEGORY(lcSession) ///< bridgescope.session: live and measure sessions
Q_DECLARE_LOGGING_CATEGORY(lcDemo) ///< bridgescope.demo: the demo lab's processes
Q_DECLARE_LOGGING_CATEGORY(lcWatch) ///< bridgescope.watch: links watched, their events

namespace Logging {
/// The category names, for --help and the tests.
QStringList categoryNames();
/// Debug messages of every bridgescope category on (QT_LOGGING_RULES still decides last), and a
/// message pattern with time and category unless QT_MESSAGE_PATTERN is set.
void enableVerbose();
/// Removes every "--verbose" from `argv` (before a lone "--"); true when there was one.
bool takeVerboseFlag(int* argc, char** argv);
} // namespace Logging
