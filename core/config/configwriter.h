// SPDX-License-Identifier: MIT
#pragma once

#include "config/bridgeconfig.h"

#include <QCoreApplication>
#include <QStringList>

/// Writes a whole config in one of the three layouts (no comments: see ConfigPatcher for edits
/// that keep a file's comments).
class ConfigWriter
{
    Q_DECLARE_TR_FUNCTIONS(ConfigWriter)
public:
    /// The config as YAML text in the given layout. `notes` receives what the layout cannot
    /// express (e.g. options mqtt_bridge has no equivalent for); `dropped` (or `notes` when null)
    /// the unknown content that has no place in the written text.
    static QString write(const BridgeConfig& config, ConfigLayout layout, QStringList* notes = nullptr,
                         QStringList* dropped = nullptr);
    /// The YAML text of one mapping in the ROS 1 list layout (one item of ros2mqtt/mqtt2ros),
    /// without the leading "- ".
    static QString ros1MappingItem(const Mapping& mapping);
    /// The YAML text of one mapping's settings in the ROS 2 layout (below its topic key).
    static QString ros2MappingBlock(const Mapping& mapping);
    /// The YAML text of a block's options (as written in `layout`), or of the part of it below
    /// the key path `below`; lines start at column 0.
    static QString blockText(OptionScope scope, const OptionBlock& block, ConfigLayout layout,
                             const QStringList& below = {});
    /// An option value as the YAML scalar to write for the layout.
    static QString scalarFor(OptionScope scope, const QString& path, const QString& text,
                             ConfigLayout layout);
};
