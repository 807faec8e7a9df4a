// SPDX-License-Identifier: MIT
// NameElider: the shortenings of slash-separated names keep what tells the names apart.
#include "text/nameelider.h"

#include <QSet>
#include <QTest>

using namespace Qt::StringLiterals;

class TestNameElider : public QObject
{
    Q_OBJECT
private:
    // The demo lab's names: twelve stamp topics that differ in the middle and at the end.
    static QStringList demoNames()
    {
        QStringList names;
        for (const QString& side : {u"vehicle"_s, u"cloud"_s})
            for (const QString& topic : {u"object_list"_s, u"pointcloud"_s})
                for (const QString& end : {u"in"_s, u"out"_s})
                    names << u"/benchmarking_suite/stamps/%1/%2/%3"_s.arg(side, topic, end);
        names << u"/mqtt_interface_vehicle/pointcloud"_s << u"/mqtt_interface_cloud/pointcloud"_s
              << u"/vehicle/pointcloud"_s << u"/rosout"_s;
        return names;
    }

private slots:
    void formsShortenFromTheLeft()
    {
        NameElider e;
        e.setNames(demoNames());
        const QStringList forms = e.forms(u"/benchmarking_suite/stamps/vehicle/object_list/in"_s);
        QCOMPARE(forms,
                 QStringList({u"/benchmarking_suite/stamps/vehicle/object_list/in"_s,
                              u"/b…/stamps/vehicle/object_list/in"_s, u"/b…/s…/vehicle/object_list/in"_s,
                              u"/b…/s…/v…/object_list/in"_s, u"/b…/s…/v…/o…/in"_s,
                              u"/b…/…/v…/o…/in"_s, // `stamps` has no siblings: it tells nothing apart
                              u"…/v…/o…/in"_s, u"…/o…/in"_s, u"…/in"_s}));
        // Siblings that share a long prefix keep enough of it to differ.
        QCOMPARE(e.forms(u"/mqtt_interface_vehicle/pointcloud"_s).value(1), u"/…vehicle/pointcloud"_s);
        QCOMPARE(e.forms(u"/mqtt_interface_cloud/pointcloud"_s).value(1), u"/…cloud/pointcloud"_s);
        // A segment no shorter with `…` stays whole; a root-level name has nothing to shorten.
        QCOMPARE(e.forms(u"/rosout"_s), QStringList {u"/rosout"_s});
    }

    void abbreviatedFormsStayDistinct()
    {
        // Every name's forms until the first namespace with siblings is dropped tell all the names
        // apart: the shortest of them for each name, side by side, are all different.
        const QStringList names = demoNames();
        NameElider e;
        e.setNames(names);
        QSet<QString> seen;
        for (const QString& name : names) {
            QString shortest = name;
            for (const QString& f : e.forms(name))
                if (!f.startsWith(u"…"_s))
                    shortest = f;
            QVERIFY2(!seen.contains(shortest), qPrintable(shortest));
            seen.insert(shortest);
        }
        QCOMPARE(seen.size(), names.size());
    }

    void prefixOfASiblingStaysWhole()
    {
        NameElider e;
        e.setNames({u"cloud/a"_s, u"cloud2/a"_s, u"type_msgs/Stamped"_s, u"geometry_msgs/PoseArray"_s});
        QCOMPARE(e.forms(u"cloud/a"_s), QStringList({u"cloud/a"_s, u"…/a"_s}));
        QCOMPARE(e.forms(u"cloud2/a"_s), QStringList({u"cloud2/a"_s, u"…/a"_s}));
        // ROS types: the package shortens, the type stays.
        QCOMPARE(e.forms(u"geometry_msgs/PoseArray"_s).value(1), u"g…/PoseArray"_s);
    }

    void hostileNamesAreBounded()
    {
        NameElider e;
        const QString deep = QString(u"/a"_s).repeated(10000);
        const QString slashes(5000, u'/');
        e.setNames({deep, slashes, QString(), u"/"_s});
        QCOMPARE(e.forms(deep), QStringList {deep}); // too deep: the caller elides it
        QCOMPARE(e.forms(QString()), QStringList {QString()});
        QCOMPARE(e.forms(u"/"_s), QStringList {u"/"_s});
        QCOMPARE(e.forms(u"a//b"_s).last(), u"…/b"_s);
    }
};

QTEST_GUILESS_MAIN(TestNameElider)
#include "tst_nameelider.moc"
