// SPDX-License-Identifier: MIT
#pragma once

#include <QList>
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
    /// the rows or the view change, and at most once a kGrowMs while figures change, and then
    /// only grow (figures that shrink by a digit do not make the columns twitch).
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
    bool m_fitting = false;
    bool m_userSized = false;
};
