// SPDX-License-Identifier: MIT
#pragma once

#include <QList>
#include <QModelIndex>
#include <QObject>
#include <QTimer>

class QAbstractItemView;
class QHeaderView;
class QTableView;
class QTreeView;

/// Sizes a table's (or a tree's) columns to what they hold, within the view. When the view has
/// room for every column's content, each gets it (no text is cut that the window has room for) and
/// `fill` columns share what is over. Short of room, names come first: `fill` columns (and a
/// Stretch column) grow towards their content, then `fit` columns towards theirs within a share of
/// the view. A column drawn by NameDelegate is never made narrower than its names' last segments
/// (a scroll bar rather than a lost name). Refits 100 ms after the rows or the view's width change.
///
/// Once the user sizes one of its columns by hand (or WindowMemory restores the header), the widths
/// are the user's, but only where they are wide enough: figure columns still grow to what their
/// figures need (a figure is never elided, whatever was restored or dragged), name columns never
/// stay below their last segments, and room the columns leave empty goes to names that are cut.
class ColumnFitter : public QObject
{
    Q_OBJECT
public:
    explicit ColumnFitter(QTableView* view);
    explicit ColumnFitter(QTreeView* view);

    /// `column` (Interactive) takes the width its content needs, at most `share` of the view.
    void fit(int column, double share);
    /// These columns (Interactive) share equally the room the others leave.
    void fill(const QList<int>& columns);
    /// These columns (Interactive) hold values that change all the time (a topic's last payload):
    /// they take the room the names and the fitted columns' shares leave (what is over when the view
    /// has room for all), measured when the rows or the view change, not at every new value.
    /// Columns after them are reached by scrolling sideways: they take none of the room.
    void values(const QList<int>& columns);
    /// These columns (made Interactive here) take the width their figures need, as
    /// QHeaderView::ResizeToContents would, without its cost: that measures every row's text at
    /// every change of any cell (30 times a second on a live page). Here they are measured when
    /// the rows or the view change; while figures change, the changed cells that are shown are
    /// measured before the view paints them, and the columns grow at once (a figure that gains a
    /// digit is never drawn cut), but never shrink (figures that lose a digit do not make the
    /// columns twitch). The other columns share the room anew at most once a kGrowMs.
    void figures(const QList<int>& columns);
    static constexpr int kGrowMs = 1000;
    /// Fits now (the timer does it after changes).
    void apply();
    /// The width a column's title needs: its text, and a sort indicator where one is shown.
    static int titleWidth(const QHeaderView* header, int column);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    ColumnFitter(QAbstractItemView* view, QHeaderView* header);
    int floorOf(int column) const;
    /// The width a column's cells and title need.
    int needOf(int column) const;
    bool manages(int column) const;
    /// Sizes the figure columns to their content; with `growOnly`, only those that need more room.
    /// True when a width changed.
    bool fitFigures(bool growOnly);
    /// Grows the figure columns to the changed cells the viewport is about to paint (the rows
    /// shown, at most a viewport's worth). True when a width changed.
    bool growToShownChanges();
    /// Notes changed cells of the figure columns, measured when they are painted.
    void noteChanged(const QModelIndex& from, const QModelIndex& to);
    /// Every shown figure cell is measured at the next paint (rows moved, scrolled, expanded).
    void noteAllShownChanged();
    /// Sizes the fitted and fill columns in the room the others leave.
    void fitTheRest();
    /// The widths are the user's (sized by hand or restored): kept where they are wide enough.
    bool keepsWidths() const;
    /// Widens the name columns the user's widths cut: to their floors, then with the room the
    /// columns leave empty.
    void widenCutNames();
    QHeaderView* header() const;
    int width(int column) const;
    void setWidth(int column, int width);
    bool isHidden(int column) const;

    QAbstractItemView* m_view;
    const QObject* m_headerObject; ///< the header at construction, only to compare events' targets
    const QObject* m_viewport = nullptr;
    QList<std::pair<int, double>> m_fits;
    QList<int> m_fills;
    QList<int> m_values;
    QList<int> m_figures;
    QTimer m_timer;
    QTimer m_growTimer;
    /// Changed rows of the figure columns not painted yet: a parent, its rows and the columns.
    struct Changed
    {
        QModelIndex parent;
        int first, last, firstColumn, lastColumn;
    };
    QList<Changed> m_changed;
    bool m_allShownChanged = false; ///< rows moved or too many changes noted: every shown row
    bool m_grown = false; ///< figures grew at a paint: the other columns share the room anew
    bool m_fitting = false;
    bool m_userSized = false;
};
