// SPDX-License-Identifier: MIT
// File › Open Recent's list: newest first, each file once, the newest RecentFiles::kMax kept, and
// the same list in the next session (one settings folder).
#include "widgets/map/recentfiles.h"

#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

using namespace Qt::StringLiterals;

class TestRecentFiles : public QObject
{
    Q_OBJECT
    QTemporaryDir m_dir;

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        QSettings::setDefaultFormat(QSettings::IniFormat);
        QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, m_dir.path());
        QSettings().clear();
    }

    void newestFirstEachOnceAndBounded()
    {
        RecentFiles recent;
        QSignalSpy changed(&recent, &RecentFiles::changed);
        QCOMPARE(recent.files(), QStringList());
        recent.add(u"/lab/a.yaml"_s);
        recent.add(u"/lab/b.bsrun"_s);
        recent.add(u"/lab/a.yaml"_s); // again: moves to the front, not listed twice
        QCOMPARE(recent.files(), (QStringList {u"/lab/a.yaml"_s, u"/lab/b.bsrun"_s}));
        QCOMPARE(changed.size(), 3);
        QCOMPARE(changed.last().first().toStringList(), recent.files());

        for (int i = 0; i < RecentFiles::kMax; ++i)
            recent.add(u"/lab/%1.yaml"_s.arg(i));
        const QStringList files = recent.files();
        QCOMPARE(files.size(), RecentFiles::kMax);
        QCOMPARE(files.first(), u"/lab/%1.yaml"_s.arg(RecentFiles::kMax - 1));
        QCOMPARE(files.last(), u"/lab/0.yaml"_s); // a.yaml and b.bsrun fell off the end

        // The next session (another window, the same settings) sees the same list.
        QCOMPARE(RecentFiles().files(), files);
    }
};

QTEST_GUILESS_MAIN(TestRecentFiles)
#include "tst_recentfiles.moc"
