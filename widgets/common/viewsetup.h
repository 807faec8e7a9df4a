// SPDX-License-Identifier: MIT
#pragma once

class QAbstractItemView;
class QTableView;
class QTreeView;

/// The look every item view of Bridgescope shares, set in one place.
namespace ViewSetup {
/// A table of records: whole rows selected, no row numbers, one line of text per row (long text
/// elided in the middle), sorted by `sortColumn` (ascending) when it is not negative.
void records(QTableView* view, int sortColumn = -1);
/// A tree of topics: rows of one height (fast with many rows), sorted by `sortColumn`.
void topicTree(QTreeView* view, int sortColumn);
/// Items dragged out as copies, several at once; drops onto the view are shown.
void dragsCopies(QAbstractItemView* view);
} // namespace ViewSetup
