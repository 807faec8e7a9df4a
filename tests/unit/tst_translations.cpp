// SPDX-License-Identifier: MIT
// Every user-visible string has a German translation, and the translations load.
#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>
#include <QTranslator>

using namespace Qt::StringLiterals;

class TestTranslations : public QObject
{
    Q_OBJECT
private slots:
    // Regression guard: a tr() added without a German translation fails here, not in a user's hands.
    void germanIsComplete()
    {
        QTemporaryDir dir;
        const QString ts = dir.filePath(u"bridgescope_de.ts"_s);
        QVERIFY(QFile::copy(QStringLiteral(BRIDGESCOPE_SOURCE_DIR "/translations/bridgescope_de.ts"), ts));
        QFile::setPermissions(ts, QFileDevice::ReadOwner | QFileDevice::WriteOwner);
        QProcess lupdate;
        const QString src = QStringLiteral(BRIDGESCOPE_SOURCE_DIR);
        lupdate.start(QStringLiteral(LUPDATE_EXECUTABLE),
                      {u"-no-obsolete"_s, u"-locations"_s, u"none"_s, src + u"/app"_s, src + u"/core"_s,
                       src + u"/widgets"_s, u"-ts"_s, ts});
        QVERIFY(lupdate.waitForFinished(120000));
        QCOMPARE(lupdate.exitCode(), 0);
        QFile f(ts);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QString text = QString::fromUtf8(f.readAll());
        // Name the untranslated sources, so the failure says what to translate.
        static const QRegularExpression unfinished(
            uR"(<source>([^<]*)</source>\s*<translation type="unfinished")"_s);
        QStringList missing;
        for (auto it = unfinished.globalMatch(text); it.hasNext();)
            missing << it.next().captured(1);
        QVERIFY2(missing.isEmpty(), qPrintable(u"untranslated: "_s + missing.join(u" | "_s)));
        QVERIFY(text.count(u"<message"_s) > 100);

        QProcess lrelease;
        const QString qm = dir.filePath(u"bridgescope_de.qm"_s);
        lrelease.start(QStringLiteral(LRELEASE_EXECUTABLE), {ts, u"-qm"_s, qm});
        QVERIFY(lrelease.waitForFinished(60000));
        QCOMPARE(lrelease.exitCode(), 0);
        QTranslator translator;
        QVERIFY(translator.load(qm));
        QCoreApplication::installTranslator(&translator);
        QCOMPARE(QCoreApplication::translate("MainWindow", "&File"), u"&Datei"_s);
        QCOMPARE(QCoreApplication::translate("ProblemModel", "no problems"), u"keine Probleme"_s);
        QCoreApplication::removeTranslator(&translator);
    }
};

QTEST_GUILESS_MAIN(TestTranslations)
#include "tst_translations.moc"
