// SPDX-License-Identifier: MIT
#include "ecdfsvg.h"

#include "text/niceticks.h"
#include "latency/ecdf.h"
#include "latency/latencyseries.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <limits>

using namespace Qt::StringLiterals;

namespace {
QString esc(const QString& s)
{
    return s.toHtmlEscaped();
}

QString num(double v)
{
    return QString::number(v, 'f', 2);
}
} // namespace

QString EcdfSvg::beyondMarks(const QList<Curve>& curves, double hi, double right, double top, double plotH)
{
    // Values beyond the axis' end: a dot at the end where the curve leaves, and a count.
    QString s;
    QStringList counts;
    for (const Curve& c : curves) {
        if (!c.series || c.series->count() == 0)
            continue;
        const qint64 beyond = Ecdf::countAbove(*c.series, hi);
        if (beyond == 0)
            continue;
        const double level = 1.0 - double(beyond) / double(c.series->count());
        s += u"<circle cx=\"%1\" cy=\"%2\" r=\"4.5\" fill=\"%3\"/>\n"_s.arg(
            num(right), num(top + (1.0 - level) * plotH), c.color);
        counts << tr("%1: %n beyond %2 ms", nullptr, int(std::min<qint64>(beyond, INT_MAX)))
                      .arg(c.label, QString::number(hi, 'g', 6));
    }
    for (qsizetype i = 0; i < counts.size(); ++i)
        s += u"<text x=\"%1\" y=\"%2\" text-anchor=\"end\" font-size=\"11\" fill=\"#444444\">%3</text>\n"_s
                 .arg(num(right - 8), num(top + plotH - 10 - 15.0 * double(counts.size() - 1 - i)),
                      esc(counts[i]));
    return s;
}

QList<double> EcdfSvg::ticks(double lo, double hi, int wanted)
{
    return NiceTicks::ticks(lo, hi, wanted);
}

QByteArray EcdfSvg::render(const QList<Curve>& curves, int width, int height, const QString& title)
{
    // The range over all curves up to a high quantile (Ecdf::shownRange: one outlier does not
    // stretch the axis), with ends on round ticks.
    double lo = std::numeric_limits<double>::infinity();
    double hi = -lo;
    for (const Curve& c : curves) {
        if (!c.series || c.series->count() == 0)
            continue;
        const auto [a, b] = Ecdf::shownRange(*c.series);
        lo = std::min(lo, a);
        hi = std::max(hi, b);
    }
    if (!(hi >= lo)) {
        lo = 0;
        hi = 1;
    }
    const NiceTicks::Axis axis = NiceTicks::axis(lo, hi);
    lo = axis.lo;
    hi = axis.hi;
    const QList<double> xTicks = NiceTicks::ticks(lo, hi);

    const int legendRows = int(curves.size() + 1) / 2;
    const double left = 56;
    const double right = 16;
    const double top = title.isEmpty() ? 20 : 38;
    const double bottom = 46 + 18.0 * legendRows;
    const double plotW = width - left - right;
    const double plotH = height - top - bottom;
    const auto x = [&](double ms) { return left + (ms - lo) / (hi - lo) * plotW; };
    const auto y = [&](double f) { return top + (1.0 - f) * plotH; };

    QString s;
    s += u"<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%1\" height=\"%2\" viewBox=\"0 0 %1 %2\" "
         "font-family=\"DejaVu Sans, Helvetica, Arial, sans-serif\" font-size=\"12\">\n"_s.arg(width)
             .arg(height);
    s += u"<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"_s;
    if (!title.isEmpty())
        s += u"<text x=\"%1\" y=\"20\" text-anchor=\"middle\" font-size=\"14\" font-weight=\"bold\">%2</text>\n"_s
                 .arg(num(width / 2.0), esc(title));
    // Grid and axes.
    s += u"<g stroke=\"#dddddd\" stroke-width=\"1\">\n"_s;
    for (double t : std::as_const(xTicks))
        s += u"<line x1=\"%1\" y1=\"%2\" x2=\"%1\" y2=\"%3\"/>\n"_s.arg(num(x(t)), num(top),
                                                                        num(top + plotH));
    for (int i = 0; i <= 5; ++i)
        s += u"<line x1=\"%1\" y1=\"%2\" x2=\"%3\" y2=\"%2\"/>\n"_s.arg(num(left), num(y(i / 5.0)),
                                                                        num(left + plotW));
    s += u"</g>\n"_s;
    s += u"<rect x=\"%1\" y=\"%2\" width=\"%3\" height=\"%4\" fill=\"none\" stroke=\"#444444\"/>\n"_s.arg(
        num(left), num(top), num(plotW), num(plotH));
    for (double t : std::as_const(xTicks))
        s += u"<text x=\"%1\" y=\"%2\" text-anchor=\"middle\">%3</text>\n"_s.arg(
            num(x(t)), num(top + plotH + 16), QString::number(t, 'f', axis.decimals));
    for (int i = 0; i <= 5; ++i)
        s += u"<text x=\"%1\" y=\"%2\" text-anchor=\"end\">%3</text>\n"_s.arg(
            num(left - 6), num(y(i / 5.0) + 4), QString::number(i / 5.0, 'f', 1));
    s += u"<text x=\"%1\" y=\"%2\" text-anchor=\"middle\">%3</text>\n"_s.arg(
        num(left + plotW / 2), num(top + plotH + 34), esc(tr("latency [ms]")));
    s += u"<text x=\"14\" y=\"%1\" text-anchor=\"middle\" transform=\"rotate(-90 14 %1)\">ECDF</text>\n"_s
             .arg(num(top + plotH / 2));

    // Curves, clipped to the plot.
    s += u"<defs><clipPath id=\"plot\"><rect x=\"%1\" y=\"%2\" width=\"%3\" height=\"%4\"/></clipPath></defs>\n"_s
             .arg(num(left), num(top), num(plotW), num(plotH));
    s += u"<g clip-path=\"url(#plot)\" fill=\"none\">\n"_s;
    for (const Curve& c : curves) {
        if (!c.series || c.series->count() == 0)
            continue;
        const QList<QPointF> points = Ecdf::reduced(*c.series, lo, hi, std::max(50, int(plotW)));
        QString path;
        for (const QPointF& p : points)
            path += num(x(p.x())) + u',' + num(y(p.y())) + u' ';
        s += u"<polyline stroke=\"%1\" stroke-width=\"1.8\" points=\"%2\"/>\n"_s.arg(c.color, path.trimmed());
        const double mean = c.series->meanMs();
        const double median = c.series->quantileMs(0.5);
        s += u"<line stroke=\"%1\" stroke-width=\"1.2\" stroke-dasharray=\"6,4\" x1=\"%2\" y1=\"%3\" "
             u"x2=\"%2\" "
             "y2=\"%4\"/>\n"_s.arg(c.color, num(x(mean)), num(y(0)), num(y(1)));
        s += u"<line stroke=\"%1\" stroke-width=\"1.2\" stroke-dasharray=\"1.5,3\" x1=\"%2\" y1=\"%3\" "
             u"x2=\"%2\" "
             "y2=\"%4\"/>\n"_s.arg(c.color, num(x(median)), num(y(0)), num(y(1)));
    }
    s += u"</g>\n"_s;
    s += beyondMarks(curves, hi, left + plotW, top, plotH);

    // Legend: two columns under the axis title.
    for (qsizetype i = 0; i < curves.size(); ++i) {
        const double lx = left + (i % 2) * plotW / 2;
        const double ly = top + plotH + 52 + 18.0 * double(i / 2);
        s += u"<line x1=\"%1\" y1=\"%2\" x2=\"%3\" y2=\"%2\" stroke=\"%4\" stroke-width=\"2.5\"/>\n"_s.arg(
            num(lx), num(ly - 4), num(lx + 20), curves[i].color);
        s += u"<text x=\"%1\" y=\"%2\">%3</text>\n"_s.arg(num(lx + 26), num(ly), esc(curves[i].label));
    }
    s += u"<text x=\"%1\" y=\"%2\" text-anchor=\"end\" fill=\"#666666\" font-size=\"10\">%3</text>\n"_s.arg(
        num(left + plotW), num(top - 5), esc(tr("dashed: mean · dotted: median")));
    s += u"</svg>\n"_s;
    return s.toUtf8();
}
