// SPDX-License-Identifier: MIT
#pragma once

#include <QList>

class QAbstractItemView;
class QSplitter;
class QTableView;
class QTreeView;
class QWidget;

/// The look every item view of Bridgescope shares, set in one place.
namespace ViewSetup {
/// A table of records: whole rows selected, no row numbers, one line of text per row (long text
/// elided in the middle), sorted by `sortColumn` (ascending) when it is not negative.
void records(QTableView* view, int sortColumn = -1);
/// A tree of topics: rows of one height (fast with many rows), sorted by `sortColumn`.
void topicTree(QTreeView* view, int sortColumn);
/// True when `page` is not shown while its window is: another page of the window is. Such a page
/// does no drawing work (its figures are drawn when it is shown); a page that is not in a shown
/// window (a test's) goes on as shown.
bool hiddenInShownWindow(const QWidget* page);
/// Items dragged out as copies, several at once; drops onto the view are shown.
void dragsCopies(QAbstractItemView* view);
/// The splitter's panes get these sizes, scaled to the room it has, when it is first shown: sizes
/// set before that are skewed by the first layout (a page not yet shown has no width). A splitter
/// whose sizes WindowMemory restores keeps those.
void initialSizes(QSplitter* splitter, const QList<int>& sizes);
/// Set on a splitter or header whose sizes come from the last session: initialSizes and
/// ColumnFitter leave it alone.
inline constexpr char RestoredProperty[] = "bridgescopeRestored";
} // namespace ViewSetup
