// SPDX-License-Identifier: MIT
// Credentials never reach a file or a log in plain text (issue 11). Every command that takes a
// broker runs against a real mosquitto that requires a password, with HOME, the XDG folders and
// TMPDIR inside one temporary folder; then every file in it and everything printed is searched
// for the password. That the commands really connected (so the password was used, not dropped)
// is checked by what they report.
#include "base/secrets.h"
#include "mqtt/mqttprofile.h"
#include "testservers.h"

#include <QDirIterator>
#include <QFile>
#include <QProcess>
#include <QTest>
#include <sys/stat.h>

using namespace Qt::StringLiterals;

namespace {
const QString kUser = u"alice"_s;
const QString kPassword = u"s3cr3t-Pw"_s;
const QString kConfigPassword = u"c0nfig-Pw"_s;
} // namespace

class TestSecrets : public QObject
{
    Q_OBJECT
private:
    TestServers m_servers;
    QString m_home; ///< everything the commands write goes below it
    QStringList m_printed; ///< all their stdout and stderr

    struct Run
    {
        int exit = -1;
        QString out;
        QString err;
    };

    Run bridgescope(const QStringList& args, int timeoutMs = 30000, int stopAfterMs = 0)
    {
        QProcess p;
        QProcessEnvironment env = m_servers.rosEnvironment();
        env.insert(u"HOME"_s, m_home);
        env.insert(u"XDG_CONFIG_HOME"_s, m_home + u"/.config"_s);
        env.insert(u"XDG_DATA_HOME"_s, m_home + u"/.local/share"_s);
        env.insert(u"XDG_CACHE_HOME"_s, m_home + u"/.cache"_s);
        env.insert(u"XDG_STATE_HOME"_s, m_home + u"/.local/state"_s);
        env.insert(u"TMPDIR"_s, m_home + u"/tmp"_s);
        env.insert(u"ROS_HOME"_s, m_home + u"/.ros"_s);
        env.insert(u"ROS_LOG_DIR"_s, m_home + u"/.ros/log"_s);
        env.insert(u"QT_QPA_PLATFORM"_s, u"offscreen"_s);
        p.setProcessEnvironment(env);
        p.setWorkingDirectory(m_home);
        p.start(QStringLiteral(BRIDGESCOPE_BINARY), args);
        Run r;
        if (stopAfterMs > 0 && !p.waitForFinished(stopAfterMs))
            p.terminate();
        if (!p.waitForFinished(timeoutMs)) {
            p.kill();
            p.waitForFinished();
        } else {
            r.exit = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1;
        }
        r.out = QString::fromUtf8(p.readAllStandardOutput());
        r.err = QString::fromUtf8(p.readAllStandardError());
        m_printed << r.out << r.err;
        return r;
    }

    QString urlWithPassword() const
    {
        return u"tcp://%1:%2@127.0.0.1:%3"_s.arg(kUser, kPassword).arg(m_servers.mosquittoPort());
    }

    static bool publish(const TestServers& s, const QString& topic, const QString& payload)
    {
        QProcess p;
        p.start(u"mosquitto_pub"_s,
                {u"-h"_s, u"127.0.0.1"_s, u"-p"_s, QString::number(s.mosquittoPort()), u"-u"_s, kUser,
                 u"-P"_s, kPassword, u"-r"_s, u"-t"_s, topic, u"-m"_s, payload});
        return p.waitForFinished(10000) && p.exitCode() == 0;
    }

    QString writeFile(const QString& name, const QByteArray& content, QFile::Permissions perms = {})
    {
        const QString path = m_home + u"/input/"_s + name;
        QFile f(path);
        if (!f.open(QIODevice::WriteOnly))
            return {};
        f.write(content);
        f.close();
        if (perms)
            f.setPermissions(perms);
        return path;
    }

private slots:
    void initTestCase()
    {
        m_home = m_servers.tempPath() + u"/home"_s;
        for (const QString& d : {u""_s, u"/input"_s, u"/tmp"_s, u"/out"_s})
            QVERIFY(QDir().mkpath(m_home + d));
        const QString passwd = m_servers.tempPath() + u"/passwd"_s;
        QProcess p;
        p.start(u"mosquitto_passwd"_s, {u"-c"_s, u"-b"_s, passwd, kUser, kPassword});
        QVERIFY(p.waitForFinished(10000) && p.exitCode() == 0);
        TestMosquittoOptions opts;
        opts.allowAnonymous = false;
        opts.passwordFile = passwd;
        QVERIFY2(m_servers.startMosquitto(opts), qPrintable(m_servers.errorString()));
        QVERIFY2(m_servers.startRosMaster(), qPrintable(m_servers.errorString()));
    }

    void urlsLoseTheirCredentials_data()
    {
        QTest::addColumn<QString>("url");
        QTest::addColumn<QString>("clean");
        QTest::addColumn<QString>("user");
        QTest::addColumn<QString>("password");
        QTest::newRow("plain") << u"tcp://host:1883"_s << u"tcp://host:1883"_s << QString() << QString();
        QTest::newRow("both") << u"tcp://alice:pw@host:1883"_s << u"tcp://host:1883"_s << u"alice"_s
                              << u"pw"_s;
        QTest::newRow("user only") << u"ssl://alice@host"_s << u"ssl://host"_s << u"alice"_s << QString();
        QTest::newRow("@ in password")
            << u"mqtt://alice:p@ss@host:1"_s << u"mqtt://host:1"_s << u"alice"_s << u"p@ss"_s;
        QTest::newRow("encoded") << u"tcp://al%3Ace:p%2Fw@host"_s << u"tcp://host"_s << u"al:ce"_s
                                 << u"p/w"_s;
        QTest::newRow("@ in path") << u"ws://host:80/mqtt@x"_s << u"ws://host:80/mqtt@x"_s << QString()
                                   << QString();
    }

    void urlsLoseTheirCredentials()
    {
        QFETCH(QString, url);
        QFETCH(QString, clean);
        QFETCH(QString, user);
        QFETCH(QString, password);
        const MqttProfile p = MqttProfile::fromUrl(url);
        QCOMPARE(p.url, clean);
        QCOMPARE(p.name, clean);
        QCOMPARE(p.username, user);
        QCOMPARE(p.password, password);
        QCOMPARE(Secrets::urlWithoutCredentials(url), clean);
    }

    void configsAreRedacted_data()
    {
        QTest::addColumn<QByteArray>("yaml");
        QTest::addColumn<QByteArray>("expected");
        QTest::newRow("block") << QByteArray("broker:\n  user: a # who\n  pass: secret # why\n")
                               << QByteArray("broker:\n  user: a # who\n  pass: \"<redacted>\" # why\n");
        QTest::newRow("flow") << QByteArray("broker: {user: a, pass: 'se,cret', port: 1}\n")
                              << QByteArray("broker: {user: a, pass: \"<redacted>\", port: 1}\n");
        QTest::newRow("tls password") << QByteArray("client:\n  tls:\n    password: \"x y\"\n")
                                      << QByteArray("client:\n  tls:\n    password: \"<redacted>\"\n");
        QTest::newRow("anchor kept") << QByteArray("pass: &p hunter2\nother: *p\n")
                                     << QByteArray("pass: &p \"<redacted>\"\nother: *p\n");
        QTest::newRow("block scalar") << QByteArray("pass: |\n  line1\n  line2\nport: 1\n")
                                      << QByteArray("pass: |\n  <redacted>\n  <redacted>\nport: 1\n");
        QTest::newRow("arg kept") << QByteArray("pass: $(arg pw)\n") << QByteArray("pass: $(arg pw)\n");
        QTest::newRow("not a secret")
            << QByteArray("bypass: 1\npassive: true\n") << QByteArray("bypass: 1\npassive: true\n");
    }

    void configsAreRedacted()
    {
        QFETCH(QByteArray, yaml);
        QFETCH(QByteArray, expected);
        QCOMPARE(Secrets::redactYaml(yaml), expected);
    }

    // The commands with a password in --broker and in a config; none of it may be written down.
    void noCredentialInAnyFileOrLog()
    {
        QVERIFY(publish(m_servers, u"lab/ts/a"_s, u"{\"sample\": \"1\", \"time\": 100.0}"_s));
        QVERIFY(publish(m_servers, u"lab/ts/b"_s, u"{\"sample\": \"1\", \"time\": 100.25}"_s));
        const QString pipeline
            = writeFile(u"pipe.yaml"_s, "topics_in_order: [lab/ts/a, lab/ts/b]\nmetrics_window: 10\n");
        const QByteArray configText = u"broker:\n  host: 127.0.0.1\n  port: %1\n  user: %2\n  pass: %3\n"
                                      u"bridge:\n  mqtt2ros:\n    - {mqtt_topic: lab/x, ros_topic: /lab/x, "
                                      u"primitive: true}\n"_s.arg(m_servers.mosquittoPort())
                                          .arg(kUser, kConfigPassword)
                                          .toUtf8();
        const QString config = writeFile(u"bridge.yaml"_s, configText, QFile::ReadOwner | QFile::WriteOwner);

        // discover: connected with the URL's credentials (it sees the retained stamps).
        const Run discover = bridgescope(
            {u"discover"_s, u"--broker"_s, urlWithPassword(), u"--seconds"_s, u"2"_s, u"--json"_s});
        QCOMPARE(discover.exit, 0);
        QVERIFY2(discover.out.contains(u"lab/ts/a"_s), qPrintable(discover.out + discover.err));

        // record: the run holds the stamps, and neither password.
        const QString run = m_home + u"/out/run.bsrun"_s;
        const Run record
            = bridgescope({u"record"_s, u"--pipeline"_s, pipeline, u"--broker"_s, urlWithPassword(),
                           u"--config"_s, config, u"--seconds"_s, u"3"_s, u"-o"_s, run});
        QCOMPARE(record.exit, 0);
        QVERIFY2(record.out.contains(u"1 complete samples"_s), qPrintable(record.out + record.err));
        struct stat st
        {
        };
        QCOMPARE(::stat(QFile::encodeName(run).constData(), &st), 0);
        QCOMPARE(int(st.st_mode & 0777), 0600); // it embeds a private config

        // report: every format.
        for (const QString& format : {u"md"_s, u"html"_s, u"json"_s, u"tex"_s, u"csv"_s}) {
            const Run report = bridgescope(
                {u"report"_s, run, u"--format"_s, format, u"-o"_s, m_home + u"/out/report."_s + format});
            QVERIFY2(report.exit == 0, qPrintable(format + u": "_s + report.err));
        }

        // bridge: uses the URL's credentials (it connects) and logs without them.
        const Run bridge = bridgescope({u"bridge"_s, config, u"--broker"_s, urlWithPassword()}, 15000, 4000);
        QVERIFY2(bridge.err.contains(u"connected to tcp://127.0.0.1"_s), qPrintable(bridge.err));
        QCOMPARE(bridge.exit, 0);

        // The window: a broker with credentials on the command line; settings are written on the way.
        const Run gui = bridgescope({u"--broker"_s, urlWithPassword(), u"--screenshot"_s,
                                     m_home + u"/out/shot.png"_s, u"--after"_s, u"2"_s},
                                    60000);
        QVERIFY2(gui.exit == 0, qPrintable(gui.err));

        // Now search everything.
        QStringList searched;
        QDirIterator it(m_home, QDir::Files | QDir::Hidden | QDir::System, QDirIterator::Subdirectories);
        while (it.hasNext()) {
            const QString path = it.next();
            if (path == config)
                continue; // the user's own input
            QFile f(path);
            QVERIFY2(f.open(QIODevice::ReadOnly), qPrintable(path));
            const QByteArray bytes = f.readAll();
            searched << path.mid(m_home.size() + 1);
            for (const QString& secret : {kPassword, kConfigPassword})
                QVERIFY2(!bytes.contains(secret.toUtf8()), qPrintable(path + u" holds a password"_s));
        }
        for (const QString& text : std::as_const(m_printed))
            for (const QString& secret : {kPassword, kConfigPassword})
                QVERIFY2(!text.contains(secret), qPrintable(u"printed: "_s + text));
        // The search did look at what the commands wrote.
        QVERIFY2(searched.contains(u"out/run.bsrun"_s), qPrintable(searched.join(u", "_s)));
        QVERIFY2(searched.contains(u".config/Bridgescope/bridgescope.conf"_s),
                 qPrintable(searched.join(u", "_s)));
        QVERIFY(searched.contains(u"out/report.html"_s));
    }
};

QTEST_GUILESS_MAIN(TestSecrets)
#include "tst_secrets.moc"
