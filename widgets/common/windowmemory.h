// SPDX-License-Identifier: MIT
#pragma once

#include <QString>

class QObject;
class QSettings;
class QWidget;

/// How the user left a window, kept across sessions: splitter sizes, column widths, order and
/// sort of every table and tree, the page of every tab widget, the text of the filter fields
/// (line edits named "…Filter"). Each is keyed by its widget's path below the window (object
/// names, or class and position for unnamed widgets), so every view keeps its own.
///
/// Columns come back once their view has its columns (a model filled later), and only when their
/// count is the one saved: a view that changed between versions starts with its defaults.
namespace WindowMemory {
void save(const QWidget* root, QSettings& settings, const QString& group);
void restore(QWidget* root, QSettings& settings, const QString& group);
/// "pages/QSplitter#1/rosTopics": the path of `object` below `root`.
QString keyOf(const QObject* object, const QObject* root);
} // namespace WindowMemory
