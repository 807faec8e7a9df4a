// SPDX-License-Identifier: MIT
// The window remembers how it was left: geometry, page, splitters, columns and their sort, filter
// texts; and a first start fits the screen.
#include "app/gui/mainwindow.h"
#include "config/configdocument.h"
#include "guisession.h"
#include "mqtt/mqttconnection.h"
#include "mqtt/mqttprofile.h"
#include "session/livesession.h"
#include "testservers.h"
#include "widgets/common/windowmemory.h"
#include "widgets/discover/discoverpage.h"
#include "widgets/links/linkspage.h"
#include "widgets/map/configeditor.h"

#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QScreen>
#include <QSettings>
#include <QSplitter>
#include <QTableView>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTest>

using namespace Qt::StringLiterals;

class TestSession : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        GuiSession::useSettingsFolder(m_dir.path());
    }

    void aFirstStartFitsTheScreen()
    {
        MainWindow w;
        w.rememberSession(); // nothing saved yet
        const QRect screen = w.screen()->availableGeometry();
        QVERIFY(w.width() <= screen.width() && w.height() <= screen.height());
        QCOMPARE(w.size(), QSize(std::min(1280, screen.width()), std::min(800, screen.height())));
    }

    // Issue 33, point 6: "no problems" while the broker is down is no status at all.
    void theStatusBarSaysWhenTheBrokerIsDown()
    {
        TestServers servers;
        QVERIFY2(servers.startMosquitto(), qPrintable(servers.errorString()));
        MainWindow w;
        auto* status = w.findChild<QLabel*>(u"problemStatus"_s);
        QVERIFY(status);
        w.session()->connectBroker(MqttProfile::fromUrl(servers.brokerUrl()));
        QTRY_COMPARE_WITH_TIMEOUT(w.session()->mqtt()->state(), MqttConnection::State::Connected, 10000);
        // A new config: its one error (no mapping) said as what to do, not as "1 error".
        QVERIFY2(status->text().startsWith(u"no mappings yet"_s), qPrintable(status->text()));
        auto* editor = w.findChild<ConfigEditor*>();
        QVERIFY(editor);
        editor->addMapping(Direction::Ros2Mqtt);
        QTRY_VERIFY2(!status->text().contains(u"no mappings"_s), qPrintable(status->text()));
        const QString up = status->text(); // the config's problems, if any
        QVERIFY2(!up.contains(u"unreachable"_s), qPrintable(up));
        servers.stopMosquitto();
        QTRY_VERIFY2_WITH_TIMEOUT(status->text().contains(u"unreachable"_s), qPrintable(status->text()), 15000);
        QVERIFY2(status->text().contains(u"127.0.0.1:%1"_s.arg(servers.mosquittoPort())), qPrintable(status->text()));
        QVERIFY2(status->text().endsWith(up) || up == u"no problems"_s, qPrintable(status->text()));
        // Down and empty again: the broker, and no "· 1 error" after it.
        w.document()->removeMappings({w.document()->mapping(0).id});
        QTRY_VERIFY2(!status->text().contains(u" · "_s), qPrintable(status->text()));
        QVERIFY2(status->text().contains(u"unreachable"_s), qPrintable(status->text()));
        QVERIFY(!status->text().contains(u"no problems"_s));
        QVERIFY(!status->toolTip().isEmpty()); // why
    }

    void theWindowComesBackAsItWasLeft()
    {
        QList<int> sizes;
        QSize size;
        {
            MainWindow w;
            w.rememberSession();
            w.show();
            QVERIFY(QTest::qWaitForWindowExposed(&w));
            w.resize(1200, 640);
            size = w.size(); // as the window's minimum allows
            QVERIFY(size != QSize(1280, 800));
            w.pages()->setCurrentWidget(w.linksPage());
            w.findChild<QLineEdit*>(u"rosFilter"_s)->setText(u"bench"_s);
            w.findChild<QLineEdit*>(u"linkFilter"_s)->setText(u"pointcloud"_s);
            auto* splitter = w.discoverPage()->findChild<QSplitter*>();
            QVERIFY(splitter && splitter->count() >= 2);
            sizes = splitter->sizes();
            sizes[0] += 90;
            sizes[1] -= 90;
            splitter->setSizes(sizes);
            sizes = splitter->sizes();
            QHeaderView* header = w.findChild<QTableView*>(u"linkTable"_s)->horizontalHeader();
            QVERIFY(header->count() > 2);
            header->resizeSection(0, 233);
            header->setSortIndicator(2, Qt::DescendingOrder);
            QVERIFY(w.close());
        }
        MainWindow w;
        w.rememberSession();
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QCOMPARE(w.size(), size);
        QCOMPARE(w.pages()->currentWidget(), w.linksPage());
        QCOMPARE(w.findChild<QLineEdit*>(u"rosFilter"_s)->text(), u"bench"_s);
        QCOMPARE(w.findChild<QLineEdit*>(u"linkFilter"_s)->text(), u"pointcloud"_s);
        w.pages()->setCurrentWidget(w.discoverPage()); // a page's splitters come back when it shows
        QCOMPARE(w.discoverPage()->findChild<QSplitter*>()->sizes(), sizes);
        QHeaderView* header = w.findChild<QTableView*>(u"linkTable"_s)->horizontalHeader();
        QCOMPARE(header->sectionSize(0), 233);
        QCOMPARE(header->sortIndicatorSection(), 2);
        QCOMPARE(header->sortIndicatorOrder(), Qt::DescendingOrder);
    }

    void theMasterEnteredLastComesBack()
    {
        QSettings().clear();
        qunsetenv("ROS_MASTER_URI");
        {
            MainWindow w;
            w.rememberSession();
            w.show();
            auto* field = w.findChild<QLineEdit*>(u"masterUri"_s);
            QVERIFY(field);
            field->setText(u"http://127.0.0.1:1/"_s); // nothing listens there: asking fails quietly
            QTest::keyClick(field, Qt::Key_Return);
            w.discoverPage()->setRosMasterUri(u"http://127.0.0.1:2/"_s); // a program's (the demo's)
            QVERIFY(w.close());
        }
        {
            MainWindow w;
            w.rememberSession();
            QCOMPARE(w.session()->rosMasterUri(), u"http://127.0.0.1:1/"_s);
        }
        qputenv("ROS_MASTER_URI", "http://127.0.0.1:3/"); // the environment's comes first
        {
            MainWindow w;
            w.rememberSession();
            QCOMPARE(w.session()->rosMasterUri(), u"http://127.0.0.1:3/"_s);
        }
        qunsetenv("ROS_MASTER_URI");
    }

    void aWindowThatIsNotToRememberLeavesNothing()
    {
        QSettings().clear();
        {
            MainWindow w;
            w.show();
            w.pages()->setCurrentIndex(2);
            QVERIFY(w.close());
        }
        QVERIFY(QSettings().allKeys().filter(u"window/"_s).isEmpty());
    }

    void keysFollowTheWidgetTree()
    {
        QWidget root;
        auto* named = new QLineEdit(&root);
        named->setObjectName(u"rosFilter"_s);
        auto* a = new QSplitter(&root);
        auto* b = new QSplitter(&root);
        QCOMPARE(WindowMemory::keyOf(named, &root), u"rosFilter"_s);
        QCOMPARE(WindowMemory::keyOf(a, &root), u"QSplitter#0"_s);
        QCOMPARE(WindowMemory::keyOf(b, &root), u"QSplitter#1"_s);
    }
};

QTEST_MAIN(TestSession)
#include "tst_session.moc"
