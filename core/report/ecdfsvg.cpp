// SPDX-License-Identifier: MIT
#include "ecdfsvg.h"

#include "latency/ecdf.h"
#include "latency/latencyseries.h"

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

QList<double> EcdfSvg::ticks(double lo, double hi, int wanted)
{
    QList<double> out;
    if (!(hi > lo) || wanted < 2)
        return out;
    const double raw = (hi - lo) / double(wanted - 1);
    const double power = std::pow(10.0, std::floor(std::log10(raw)));
    double step = power;
    for (double f : {1.0, 2.0, 2.5, 5.0, 10.0}) {
        step = f * power;
        if (step >= raw)
            break;
    }
    for (double t = std::ceil(lo / step) * step; t <= hi + step * 1e-9; t += step)
        out << (std::abs(t) < step * 1e-9 ? 0.0 : t);
    return out;
}

QByteArray EcdfSvg::render(const QList<Curve>& curves, int width, int height, const QString& title)
{
    // Data range over all curves, with round ends.
    double lo = std::numeric_limits<double>::infinity();
    double hi = -lo;
    for (const Curve& c : curves) {
        if (!c.series || c.series->count() == 0)
            continue;
        lo = std::min(lo, c.series->toMs(c.series->sorted().min()));
        hi = std::max(hi, c.series->toMs(c.series->sorted().max()));
    }
    if (!(hi >= lo)) {
        lo = 0;
        hi = 1;
    }
    if (hi - lo < 1e-6) {
        lo -= 0.5;
        hi += 0.5;
    }
    QList<double> xTicks = ticks(lo, hi);
    const double step = xTicks.size() > 1 ? xTicks[1] - xTicks[0] : (hi - lo);
    lo = std::floor(lo / step) * step;
    hi = std::ceil(hi / step) * step;
    xTicks = ticks(lo, hi);

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
            num(x(t)), num(top + plotH + 16), QString::number(t, 'g', 6));
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
