// SPDX-License-Identifier: MIT
// A dark palette reaches the charts (ECDF and rate) and the YAML preview, also when it changes
// while they are shown.
#include "app/gui/mainwindow.h"
#include "latency/latencyseriesset.h"
#include "viewhelpers.h"
#include "widgets/common/chartstyle.h"
#include "widgets/common/ecdfchart.h"
#include "widgets/common/ratechart.h"
#include "widgets/common/theme.h"
#include "widgets/map/mappage.h"
#include "widgets/map/yamlpreview.h"
#include "windowparts.h"

#include <QAbstractAxis>
#include <QApplication>
#include <QChart>
#include <QChartView>
#include <QMenu>
#include <QStyle>
#include <QTest>

using namespace Qt::StringLiterals;
using ViewHelpers::named;
using namespace WindowParts;

namespace {
QPalette darkPalette()
{
    QPalette p;
    p.setColor(QPalette::Window, QColor(0x2b, 0x2b, 0x2b));
    p.setColor(QPalette::WindowText, QColor(0xe8, 0xe8, 0xe8));
    p.setColor(QPalette::Base, QColor(0x1e, 0x1e, 0x1e));
    p.setColor(QPalette::Text, QColor(0xe8, 0xe8, 0xe8));
    p.setColor(QPalette::Mid, QColor(0x55, 0x55, 0x55));
    return p;
}

void verifyDark(QChart* chart, const QPalette& palette)
{
    QCOMPARE(chart->backgroundBrush().color(), palette.color(QPalette::Base));
    QCOMPARE(chart->titleBrush().color(), palette.color(QPalette::Text));
    QVERIFY(!chart->axes().isEmpty());
    for (QAbstractAxis* axis : chart->axes())
        QCOMPARE(axis->labelsBrush().color(), palette.color(QPalette::Text));
}
} // namespace

class TestDarkPalette : public QObject
{
    Q_OBJECT

private slots:
    void chartsFollowThePalette()
    {
        const QPalette light = QApplication::palette();
        QVERIFY(!ChartStyle::isDark(light));
        QApplication::setPalette(darkPalette());
        QVERIFY(ChartStyle::isDark(QApplication::palette()));
        {
            LatencySeriesSet set;
            set.add(u"total"_s, 40'000'000);
            EcdfChart ecdf;
            ecdf.setSource(&set);
            ecdf.setSeries({LatencySeriesSet::idOf(u"total"_s)});
            ecdf.refresh();
            verifyDark(ecdf.views().first()->chart(), darkPalette());
            RateChart rate;
            verifyDark(rate.chart(), darkPalette());
        }
        // Changed while shown: back to light.
        LatencySeriesSet set;
        EcdfChart ecdf;
        RateChart rate;
        ecdf.setSource(&set);
        ecdf.refresh();
        ecdf.show();
        rate.show();
        QApplication::setPalette(light);
        QCoreApplication::processEvents();
        QCOMPARE(ecdf.views().first()->chart()->backgroundBrush().color(), light.color(QPalette::Base));
        QCOMPARE(rate.chart()->backgroundBrush().color(), light.color(QPalette::Base));
    }

    // View > Theme (and --theme): a dark theme without the desktop's help, and back.
    void theDarkThemeDarkensWindowAndCharts()
    {
        const QPalette before = QApplication::palette();
        MainWindow w;
        QMenu* theme = nullptr;
        for (QMenu* m : w.findChildren<QMenu*>())
            if (m->title() == MainWindow::tr("&Theme"))
                theme = m;
        QVERIFY(theme);
        QCOMPARE(theme->actions().size(), 3);
        theme->actions().at(2)->trigger(); // Dark
        QCOMPARE(Theme::current(), u"dark"_s);
        QVERIFY(ChartStyle::isDark(QApplication::palette()));
        QCOMPARE(QApplication::style()->name().toLower(), u"fusion"_s);
        {
            LatencySeriesSet set;
            set.add(u"total"_s, 40'000'000);
            EcdfChart ecdf;
            ecdf.setSource(&set);
            ecdf.setSeries({LatencySeriesSet::idOf(u"total"_s)});
            ecdf.refresh();
            verifyDark(ecdf.views().first()->chart(), QApplication::palette());
        }
        theme->actions().at(1)->trigger(); // Light
        QVERIFY(!ChartStyle::isDark(QApplication::palette()));
        theme->actions().at(0)->trigger(); // System: what the desktop gave
        QCOMPARE(QApplication::palette().color(QPalette::Window), before.color(QPalette::Window));
        QVERIFY(!Theme::apply(u"purple"_s));
    }

    void theYamlPreviewFollowsThePalette()
    {
        MainWindow w;
        YamlPreview* preview = mapPage(w)->findChild<YamlPreview*>();
        QVERIFY(preview);
        QVERIFY(!preview->isDarkHighlighting());
        QApplication::setPalette(darkPalette());
        QCoreApplication::processEvents();
        QVERIFY(preview->isDarkHighlighting());
        QApplication::setPalette(QPalette());
    }
};

QTEST_MAIN(TestDarkPalette)
#include "tst_darkpalette.moc"
