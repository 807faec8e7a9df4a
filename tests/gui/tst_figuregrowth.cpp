// SPDX-License-Identifier: MIT
// A figure is never drawn cut, not even for a moment: on the Discover page at 1280x800, topics of a
// real mosquitto whose messages, rates and bytes gain digits (9 → 10, 999 → 1000, 9.9 → 10.0 KB)
// show every figure whole in every paint of the MQTT tree, without waiting for the columns to
// follow (ColumnFitter::kGrowMs).
#include "app/gui/mainwindow.h"
#include "models/mqtttopictree.h"
#include "mqtt/mqttconnection.h"
#include "mqtt/mqttprofile.h"
#include "testservers.h"
#include "viewaudit.h"
#include "viewhelpers.h"
#include "widgets/discover/discoverpage.h"

#include <functional>
#include <QLabel>
#include <QStandardPaths>
#include <QTest>
#include <QTimer>
#include <QTreeView>

using namespace Qt::StringLiterals;
using ViewHelpers::named;

namespace {
/// Audits a view's figures right after each paint of its viewport, with the widths that paint
/// used: the paint is passed on from here (through the filters installed before this one), then
/// audited.
class PaintAudit : public QObject
{
public:
    explicit PaintAudit(QAbstractItemView* view)
        : m_view(view)
    {
        view->viewport()->installEventFilter(this);
    }
    int paints = 0;
    std::function<void()> afterPaint;
    QStringList problems; ///< the first few cut figures seen, with the paint they were seen in

protected:
    bool eventFilter(QObject* watched, QEvent* event) override
    {
        if (event->type() != QEvent::Paint || m_passing)
            return false;
        m_passing = true;
        QCoreApplication::sendEvent(watched, event);
        m_passing = false;
        ++paints;
        if (afterPaint)
            afterPaint();
        if (problems.size() < 5)
            for (const QString& p : ViewAudit::elidedFigures(m_view))
                problems << u"paint %1: %2"_s.arg(paints).arg(p);
        return true;
    }

private:
    QAbstractItemView* m_view;
    bool m_passing = false;
};
} // namespace

class TestFigureGrowth : public QObject
{
    Q_OBJECT
private:
    TestServers m_servers;

private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QVERIFY(m_servers.startMosquitto());
    }

    void growingFiguresAreNeverPaintedCut()
    {
        MainWindow w;
        w.resize(1280, 800);
        w.pages()->setCurrentWidget(w.discoverPage());
        DiscoverPage* page = w.discoverPage();
        page->connectBroker(MqttProfile::fromUrl(m_servers.brokerUrl()));
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QTRY_COMPARE(w.size(), QSize(1280, 800));
        QTRY_VERIFY_WITH_TIMEOUT(named<QLabel>(*page, u"mqttState"_s)->text().contains(u"connected"_s),
                                 10000);
        QTreeView* tree = page->mqttView();
        PaintAudit audit(tree);

        MqttConnection publisher;
        publisher.open(MqttProfile::fromUrl(m_servers.brokerUrl()));
        QTRY_VERIFY(publisher.state() == MqttConnection::State::Connected);
        // Bursts every 20 ms, 100 bytes a message (not a figure): each topic's messages pass 9,
        // 99 and 999, its bytes 9.9 KB and 99.9 KB, its rate 9.9 and 99 within a few seconds,
        // faster than ColumnFitter::kGrowMs.
        const QByteArray payload(100, 'x');
        const QStringList topics {u"growing"_s, u"faster"_s};
        QTimer bursts;
        int burst = 0;
        connect(&bursts, &QTimer::timeout, this, [&] {
            ++burst;
            for (int i = 0; i < 4 + burst / 4; ++i)
                for (const QString& topic : topics)
                    publisher.publish(topic, payload);
        });
        bursts.start(20);
        const QAbstractItemModel* model = tree->model();
        const auto figure = [&](int column) {
            for (int r = 0; r < model->rowCount(); ++r)
                if (model->index(r, MqttTopicTree::TopicColumn).data().toString() == u"faster"_s)
                    return model->index(r, column).data().toString();
            return QString();
        };
        // What each paint showed of the faster topic: the figures must be seen gaining digits.
        QStringList messagesShown;
        QStringList bytesShown;
        audit.afterPaint = [&] {
            for (auto [column, shown] : {std::pair {MqttTopicTree::MessagesColumn, &messagesShown},
                                         std::pair {MqttTopicTree::BytesColumn, &bytesShown}})
                if (const QString text = figure(column); shown->isEmpty() || shown->last() != text)
                    *shown << text;
        };
        QTRY_VERIFY_WITH_TIMEOUT(
            figure(MqttTopicTree::MessagesColumn).toInt() >= 1200 || !audit.problems.isEmpty(), 30000);
        bursts.stop();
        QVERIFY2(audit.problems.isEmpty(), qPrintable(audit.problems.join(u'\n')));
        // The figures did gain digits from one paint to the next (9 → 10, 999 → 1000, 9.9 → 10.0 kB).
        const auto gainsDigits = [](const QStringList& shown) {
            for (int i = 1; i < shown.size(); ++i)
                if (!shown[i - 1].isEmpty() && shown[i].size() > shown[i - 1].size())
                    return true;
            return false;
        };
        QVERIFY2(gainsDigits(messagesShown), qPrintable(messagesShown.join(u", "_s)));
        QVERIFY2(gainsDigits(bytesShown), qPrintable(bytesShown.join(u", "_s)));
        QVERIFY2(figure(MqttTopicTree::BytesColumn).startsWith(u"1"_s)
                     && figure(MqttTopicTree::BytesColumn).contains(u"kb"_s, Qt::CaseInsensitive),
                 qPrintable(figure(MqttTopicTree::BytesColumn)));
        QVERIFY2(figure(MqttTopicTree::RateColumn).toDouble() >= 100,
                 qPrintable(figure(MqttTopicTree::RateColumn)));
    }
};

QTEST_MAIN(TestFigureGrowth)
#include "tst_figuregrowth.moc"
