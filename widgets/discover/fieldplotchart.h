// SPDX-License-Identifier: MIT
#pragma once

#include "session/fieldplotter.h"

#include <optional>
#include <QChartView>

class QLineSeries;
class QScatterSeries;
class QValueAxis;

/// Plotted fields over time: one line per field in its own colour (the list beside it is the
/// legend, names whole), the time axis in seconds. It follows the newest values over the buffer
/// until the user zooms (wheel, + and -) or pans (drag, Left and Right); a double-click or Home
/// follows again. Where nothing arrived for longer than the field's gap (PlotSegments) the line
/// breaks: each run of points is a line of its own.
class FieldPlotChart : public QChartView
{
    Q_OBJECT
public:
    /// Runs drawn as lines per field; older runs beyond them are drawn as dots, never joined.
    static constexpr int kMaxRuns = 100;

    explicit FieldPlotChart(QWidget* parent = nullptr);
    /// What to draw: every field's points, and the plotter's time now (where a live axis ends).
    void setSeries(const QList<PlotSeries>& series, double nowSeconds = 0);
    /// The seconds a live plot shows (the plotter's buffer).
    void setBufferSeconds(double seconds);
    /// Each field's first run, named "topic: field" in full.
    const QList<QLineSeries*>& lines() const { return m_lines; }
    /// Every run of field `field` drawn as a line, oldest first: two runs have a gap between them.
    QList<QLineSeries*> runs(int field) const;
    /// The colour of field `field`'s line.
    static QColor colour(int field);
    bool isFollowing() const { return m_following; }
    /// Follows the newest values over the whole buffer again.
    void follow();
    /// Shows `factor` times the seconds shown, keeping `anchor` (a time) where it is.
    void zoom(double factor, double anchor);
    /// Moves the time shown by `seconds` (negative: back).
    void pan(double seconds);

signals:
    void followingChanged(bool following);

protected:
    void changeEvent(QEvent* event) override; ///< a new palette recolours it
    void resizeEvent(QResizeEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void mouseDoubleClickEvent(QMouseEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;

private:
    struct Field
    {
        QList<QLineSeries*> runs; ///< runs[0] is m_lines' entry
        QScatterSeries* dots = nullptr; ///< single points, and runs beyond kMaxRuns
    };
    void redraw();
    void setFollowing(bool following);
    QLineSeries* addLine(int field);
    /// The time under a point of the view, or the middle of the shown time outside the plot.
    double timeAt(const QPointF& viewPos) const;

    QList<PlotSeries> m_series;
    double m_now = 0;
    double m_buffer = FieldPlotter::kDefaultSeconds;
    bool m_following = true;
    double m_left = 0; ///< the time shown when not following
    double m_right = 10;
    QList<Field> m_fields;
    QList<QLineSeries*> m_lines;
    QValueAxis* m_x;
    QValueAxis* m_y;
    std::optional<QPointF> m_dragFrom;
    double m_dragLeft = 0;
};
