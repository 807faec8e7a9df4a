// SPDX-License-Identifier: MIT
#pragma once

#include <QList>
#include <QObject>
#include <QTimer>

class QTableView;

/// Sizes a table's columns to what they hold, within the view: `fit` columns take the width their
/// content needs up to a share of the view, `fill` columns share what the others leave. A column
/// drawn by NameDelegate is never made narrower than its names' last segments (a scroll bar rather
/// than a lost name). Refits 100 ms after the rows or the view's width change, until the user sizes
/// one of its columns by hand (or WindowMemory restores the header): then the widths are the user's.
class ColumnFitter : public QObject
{
    Q_OBJECT
public:
    explicit ColumnFitter(QTableView* view);

    /// `column` (Interactive) takes the width its content needs, at most `share` of the view.
    void fit(int column, double share);
    /// These columns (Interactive) share equally the room the others leave.
    void fill(const QList<int>& columns);
    /// Fits now (the timer does it after changes).
    void apply();

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    int floorOf(int column) const;
    bool manages(int column) const;

    QTableView* m_view;
    const QObject* m_viewport = nullptr;
    QList<std::pair<int, double>> m_fits;
    QList<int> m_fills;
    QTimer m_timer;
    bool m_fitting = false;
    bool m_userSized = false;
};
