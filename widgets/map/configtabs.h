// SPDX-License-Identifier: MIT
#pragma once

#include "config/mappinghealth.h"

#include <QHash>
#include <QTabBar>

class ConfigFileController;

/// A tab per open bridge config above the Map page: its file name (with a mark while it has
/// unsaved edits), a dot for the health of its mappings, and in the tooltip its path and what its
/// mappings do. Choosing a tab shows that config; closing one asks to save it first.
class ConfigTabs : public QTabBar
{
    Q_OBJECT
public:
    ConfigTabs(ConfigFileController* files, QWidget* parent = nullptr);

    /// The health of open config `i`'s mappings (the Map page evaluates every open config).
    void setHealth(int i, const QHash<quint64, MappingHealth>& health);
    /// A few words on what `health` says, e.g. "4 mappings: 3 carry data, 1 no bridge".
    static QString summary(const QHash<quint64, MappingHealth>& health);
    /// The state that stands for all of them: the worst one seen.
    static MappingHealth::State worst(const QHash<quint64, MappingHealth>& health);
    /// Says again what the open configs are (names, marks, which is shown).
    void refresh();

private:
    void describe(int i);

    ConfigFileController* m_files;
    QList<QHash<quint64, MappingHealth>> m_health;
    QList<int> m_iconState; ///< the state each tab's icon shows (-1: none, -2: not set yet)
    bool m_rebuilding = false;
};
