// SPDX-License-Identifier: MIT
// A dark palette reaches the charts (ECDF and rate) and the YAML preview, also when it changes
// while they are shown.
#include "app/gui/mainwindow.h"
#include "latency/latencyseriesset.h"
#include "widgets/common/chartstyle.h"
#include "widgets/common/ecdfchart.h"
#include "widgets/common/ratechart.h"
#include "widgets/map/mappage.h"
#include "widgets/map/yamlpreview.h"

#include <QAbstractAxis>
#include <QApplication>
#include <QChart>
#include <QChartView>
#include <QTest>

using namespace Qt::StringLiterals;

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

    void theYamlPreviewFollowsThePalette()
    {
        MainWindow w;
        YamlPreview* preview = w.mapPage()->findChild<YamlPreview*>();
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
