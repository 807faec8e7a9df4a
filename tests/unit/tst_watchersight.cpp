// SPDX-License-Identifier: MIT
// WatcherSight: which links the watcher cannot see, and why (what an unseen link reports is
// pinned in tst_linkmonitor).
#include "watch/linktrack.h"
#include "watch/watchersight.h"

#include <QTest>

using namespace Qt::StringLiterals;

namespace {
std::unique_ptr<LinkTrack> track(const QString& rosTopic, bool onRos2)
{
    auto t = std::make_unique<LinkTrack>();
    t->def.rosTopic = rosTopic;
    t->def.mqttTopic = u"m"_s + rosTopic;
    t->onRos2 = onRos2;
    return t;
}
} // namespace

class TestWatcherSight : public QObject
{
    Q_OBJECT
private slots:
    void eachLinkIsBlindForTheGraphItsSideIsOn()
    {
        std::vector<std::unique_ptr<LinkTrack>> tracks;
        tracks.push_back(track(u"/one"_s, false));
        tracks.push_back(track(u"/two"_s, true));
        WatcherSight sight;
        QVERIFY(sight.sees(SourceGraph::Mqtt));
        sight.update(tracks, 10);
        QCOMPARE(tracks[0]->blindness, LinkBlindness::None);
        QCOMPARE(tracks[1]->blindness, LinkBlindness::None);

        sight.setSeeing(SourceGraph::Ros1, false);
        sight.update(tracks, 20);
        QCOMPARE(tracks[0]->blindness, LinkBlindness::RosMaster);
        QVERIFY(tracks[0]->blind);
        QCOMPARE(tracks[1]->blindness, LinkBlindness::None);

        sight.setSeeing(SourceGraph::Ros1, true);
        sight.setSeeing(SourceGraph::Ros2, false);
        sight.update(tracks, 30);
        QCOMPARE(tracks[0]->blindness, LinkBlindness::None);
        QVERIFY(!tracks[0]->blind);
        QCOMPARE(tracks[0]->sightNs, qint64(30));
        QCOMPARE(tracks[1]->blindness, LinkBlindness::Ros2Domain);

        // Without its own broker the watcher sees no link at all.
        sight.setSeeing(SourceGraph::Mqtt, false);
        QVERIFY(!sight.sees(SourceGraph::Mqtt));
        sight.update(tracks, 40);
        QCOMPARE(tracks[0]->blindness, LinkBlindness::Broker);
        QCOMPARE(tracks[1]->blindness, LinkBlindness::Broker);
    }
};

QTEST_GUILESS_MAIN(TestWatcherSight)
#include "tst_watchersight.moc"
