// SPDX-License-Identifier: MIT
// Help: the bundled user guide, every shortcut listed, About with the libraries' versions.
#include "app/gui/mainwindow.h"

#include <QDialog>
#include <QKeySequence>
#include <QTableWidget>
#include <QTest>
#include <QTextBrowser>

using namespace Qt::StringLiterals;

class TestHelp : public QObject
{
    Q_OBJECT

private slots:
    void theUserGuideIsBundled()
    {
        MainWindow w;
        w.showUserGuide();
        auto* guide = w.findChild<QDialog*>(u"userGuide"_s);
        QVERIFY(guide && guide->isVisible());
        const QString text = guide->findChild<QTextBrowser*>()->toPlainText();
        // Headings of the guide as Markdown renders them: the whole file, not a stub.
        QVERIFY2(text.contains(u"The Experiments page"_s) && text.contains(u"Watching links for hours"_s),
                 qPrintable(text.left(300)));
    }

    void everyShortcutIsListed()
    {
        MainWindow w;
        const auto list = w.shortcuts();
        const auto has = [&](const QString& what, const QKeySequence& keys) {
            for (const auto& [name, k] : list)
                if (name.contains(what) && k == keys.toString(QKeySequence::NativeText))
                    return true;
            return false;
        };
        QVERIFY(has(u"File › Open"_s, QKeySequence(QKeySequence::Open)));
        QVERIFY(has(u"View › Experiments"_s, QKeySequence(Qt::ALT | Qt::Key_6)));
        QVERIFY(has(u"Tools › Link Probe"_s, QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_P)));
        QVERIFY(has(u"Help › User Guide"_s, QKeySequence(QKeySequence::HelpContents)));
        QVERIFY(has(u"Button: Run"_s, QKeySequence(Qt::CTRL | Qt::Key_R)));
        w.showShortcuts();
        auto* table = w.findChild<QTableWidget*>(u"shortcutTable"_s);
        QVERIFY(table);
        QCOMPARE(table->rowCount(), int(list.size()));
    }

    void aboutNamesTheLibraries()
    {
        const QString about = MainWindow::aboutText();
        QVERIFY2(about.contains(QStringLiteral("Qt " QT_VERSION_STR)), qPrintable(about));
        QVERIFY2(about.contains(u"Paho MQTT C++ 1."_s), qPrintable(about));
        QVERIFY2(about.contains(u"yaml-cpp 0."_s), qPrintable(about));
        QVERIFY2(about.contains(u"roscpp 1."_s), qPrintable(about));
    }
};

QTEST_MAIN(TestHelp)
#include "tst_help.moc"
