// SPDX-License-Identifier: MIT
#pragma once

#include "config/bridgeconfig.h"
#include "config/configreader.h"

#include <optional>
#include <QByteArray>
#include <QString>

/// Saves edits into the text a config was read from, touching only the lines that changed, so
/// comments, key order, anchors and formatting of everything else stay as the user wrote them.
///
/// It works on the ROS 1 and ROS 2 mqtt_client layouts. Whatever it cannot edit in place (flow
/// collections, block scalars, anchored values, a changed unknown key) makes it give up and
/// return nothing: the caller then writes the whole file and tells the user that comments go.
/// Every patched text is read back and compared with the wanted config before it is returned.
class ConfigPatcher
{
public:
    /// `baseline` is what `text` was read as (with its source positions), `wanted` the edited
    /// config (mappings matched to the baseline by id).
    /// `readBack` receives what the patched text reads as (its verification), so that a caller
    /// adopting the saved text need not parse it again.
    static std::optional<QByteArray> patch(const QByteArray& text, const BridgeConfig& baseline,
                                           const BridgeConfig& wanted, QString* whyNot = nullptr,
                                           ConfigReadResult* readBack = nullptr);
};
