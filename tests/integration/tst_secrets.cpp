// SPDX-License-Identifier: MIT
// Credentials never reach a file or a log in plain text (issue 11). Every command that takes a
// broker runs against a real mosquitto that requires a password, with HOME, the XDG folders and
// TMPDIR inside one temporary folder; then every file in it and everything printed is searched
// for the password. That the commands really connected (so the password was used, not dropped)
// is checked by what they report.
#include "yaml/secrets.h"
#include "mqtt/mqttprofile.h"
#include "resulttext.h"
#include "testservers.h"

#include <algorithm>
#include <QDirIterator>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QTest>
#include <sys/stat.h>

using namespace Qt::StringLiterals;

namespace {
const QString kUser = u"alice"_s;
const QString kPassword = u"s3cr3t-Pw"_s;
const QString kConfigPassword = u"c0nfig-Pw"_s;
/// A second user whose password holds what URLs and option parsing trip over (issue 41, point 9).
const QString kOddUser = u"bob"_s;
const QString kOddPassword = u"Od/d?Pw#x@y"_s;
const QString kOddPasswordEncoded = u"Od%2Fd%3FPw%23x%40y"_s;
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

    /// Everything a command writes goes below m_home: HOME, the XDG folders, TMPDIR, ROS's logs.
    QProcessEnvironment environment() const
    {
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
        return env;
    }

    /// Reads every file under `root` but `skip` (the user's own input): the paths searched,
    /// relative to `root`; those that hold a password go to `holding`.
    static QStringList searchForPasswords(const QString& root, const QString& skip, QStringList* holding)
    {
        QStringList searched;
        QDirIterator it(root, QDir::Files | QDir::Hidden | QDir::System, QDirIterator::Subdirectories);
        while (it.hasNext()) {
            const QString path = it.next();
            if (path == skip)
                continue;
            QFile f(path);
            if (!f.open(QIODevice::ReadOnly)) {
                *holding << path + u" (unreadable)"_s;
                continue;
            }
            const QByteArray bytes = f.readAll();
            searched << path.mid(root.size() + 1);
            for (const QString& secret : {kPassword, kConfigPassword})
                if (bytes.contains(secret.toUtf8()))
                    *holding << path;
        }
        return searched;
    }

    Run bridgescope(const QStringList& args, int timeoutMs = 30000, int stopAfterMs = 0)
    {
        QProcess p;
        p.setProcessEnvironment(environment());
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

    /// What ps showed while a command ran: every process whose command line held the password.
    struct PsScan
    {
        QStringList seen;
        int children = 0; ///< processes seen that were handed a broker through a pipe (--broker-fd)
        bool ownHidden = false; ///< the command's own line read, with its URL's user info hidden
        int exit = -1;
        QString err;
    };

    /// Starts bridgescope with `args` and reads every process's command line every 250 ms for
    /// `scanMs` (as ps -eo args does), then waits for it to end. The command's own line is read
    /// only once it is `ownAfterMs` old (it hides its password first thing in main(), but the
    /// kernel shows argv from exec on) or has children.
    PsScan runAndScan(const QStringList& args, int scanMs, int ownAfterMs = 1500,
                      const QStringList& secrets = {kPassword})
    {
        QProcess p;
        p.setProcessEnvironment(environment());
        p.setWorkingDirectory(m_home);
        p.start(QStringLiteral(BRIDGESCOPE_BINARY), args);
        PsScan scan;
        if (!p.waitForStarted())
            return scan;
        QElapsedTimer clock;
        clock.start();
        while (clock.elapsed() < scanMs && p.state() == QProcess::Running) {
            QTest::qWait(250);
            const bool ownToo = scan.children > 0 || clock.elapsed() >= ownAfterMs;
            QDirIterator proc(u"/proc"_s, QDir::Dirs | QDir::NoDotAndDotDot);
            while (proc.hasNext()) {
                const QString dir = proc.next();
                bool isPid = false;
                const qint64 pid = QFileInfo(dir).fileName().toLongLong(&isPid);
                if (!isPid || (pid == p.processId() && !ownToo))
                    continue;
                QFile cmdline(dir + u"/cmdline"_s);
                if (!cmdline.open(QIODevice::ReadOnly))
                    continue;
                const QByteArray line = cmdline.readAll();
                if (pid == p.processId())
                    scan.ownHidden = scan.ownHidden || line.contains("tcp://***");
                if (line.contains("--broker-fd"))
                    ++scan.children;
                for (const QString& secret : secrets)
                    if (line.contains(secret.toUtf8()))
                        scan.seen << QString::fromUtf8(QByteArray(line).replace('\0', ' '));
            }
        }
        if (!p.waitForFinished(120000))
            p.kill();
        p.waitForFinished();
        scan.exit = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1;
        scan.err = QString::fromUtf8(p.readAllStandardError());
        m_printed << scan.err << QString::fromUtf8(p.readAllStandardOutput());
        return scan;
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
        p.start(u"mosquitto_passwd"_s, {u"-b"_s, passwd, kOddUser, kOddPassword});
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
        // Issue 31: MQTT over TCP has no path; what runs to the last '@' is the user info.
        QTest::newRow("/ # ? in password")
            << u"tcp://alice:Pa/s#s?x@host:1"_s << u"tcp://host:1"_s << u"alice"_s << u"Pa/s#s?x"_s;
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

    // Issue 31: a URL that fails to parse is never echoed as typed, in the profile's check nor by
    // the commands that take --broker.
    void brokerUrlErrorsNeverEchoAPassword()
    {
        MqttProfile p;
        p.url = u"ws://alice:Pa/ss@127.0.0.1:x"_s;
        QString why;
        QVERIFY(!noted(p.validate(), &why));
        QVERIFY2(!why.contains(u"Pa"_s) && why.contains(u"<redacted>@127.0.0.1:x"_s), qPrintable(why));
        const QString bad = u"tcp://alice:Pa/ss#1@127.0.0.1:notaport"_s;
        for (const QStringList& args :
             {QStringList {u"watch"_s, u"--broker"_s, bad, u"--seconds"_s, u"1"_s},
              QStringList {u"discover"_s, u"--broker"_s, bad, u"--seconds"_s, u"1"_s},
              QStringList {u"probe"_s, u"--broker"_s, bad, u"--count"_s, u"1"_s}}) {
            const Run r = bridgescope(args);
            QVERIFY2(r.exit == 2, qPrintable(args.first() + u": "_s + r.err));
            QVERIFY2(!r.err.contains(u"Pa/ss"_s) && !r.out.contains(u"Pa/ss"_s), qPrintable(r.err));
            QVERIFY2(r.err.contains(u"127.0.0.1:notaport"_s), qPrintable(r.err));
        }
    }

    void configsAreRedacted_data()
    {
        QTest::addColumn<QByteArray>("yaml");
        QTest::addColumn<QByteArray>("secret"); ///< text that must be gone
        QTest::addColumn<QByteArray>("kept"); ///< text that must stay
        // The forms the line-by-line redactor missed (issue 31) and the ones it knew.
        QTest::newRow("'' in single quotes") << QByteArray("pass: 'it''s-hunter2'\nport: 1\n")
                                             << QByteArray("hunter2") << QByteArray("port: 1");
        QTest::newRow("plain continued") << QByteArray("broker:\n  pass: first\n    hunter2\n  port: 1\n")
                                         << QByteArray("hunter2") << QByteArray("port: 1");
        QTest::newRow("double-quoted continued")
            << QByteArray("broker:\n  pass: \"first\n    hunter2\"\n  port: 1\n") << QByteArray("hunter2")
            << QByteArray("port: 1");
        QTest::newRow("complex key") << QByteArray("broker:\n  ? pass\n  : hunter2\n  port: 1\n")
                                     << QByteArray("hunter2") << QByteArray("port: 1");
        QTest::newRow("escaped key") << QByteArray("broker: {\"p\\x61ss\": hunter2, port: 1}\n")
                                     << QByteArray("hunter2") << QByteArray("port: 1");
        QTest::newRow("alias of another key")
            << QByteArray("client:\n  id: &pw hunter2\nbroker:\n  pass: *pw\n  port: 1\n")
            << QByteArray("hunter2") << QByteArray("port: 1");
        QTest::newRow("second document")
            << QByteArray("port: 1\n---\npass: hunter2\n") << QByteArray("hunter2") << QByteArray("port: 1");
        QTest::newRow("block") << QByteArray("broker:\n  user: a # who\n  pass: hunter2 # why\n")
                               << QByteArray("hunter2") << QByteArray("user: a");
        QTest::newRow("flow") << QByteArray("broker: {user: a, pass: 'hunter2,x', port: 1}\n")
                              << QByteArray("hunter2") << QByteArray("port: 1");
        QTest::newRow("tls password") << QByteArray("client:\n  tls:\n    password: \"hunter2 y\"\n")
                                      << QByteArray("hunter2") << QByteArray("tls:");
        QTest::newRow("block scalar") << QByteArray("pass: |\n  hunter2\n  line2\nport: 1\n")
                                      << QByteArray("hunter2") << QByteArray("port: 1");
        QTest::newRow("not yaml") << QByteArray("pass: [hunter2\n") << QByteArray("hunter2")
                                  << QByteArray(Secrets::kNotYaml);
    }

    void configsAreRedacted()
    {
        QFETCH(QByteArray, yaml);
        QFETCH(QByteArray, secret);
        QFETCH(QByteArray, kept);
        bool changed = false;
        const QByteArray out = Secrets::redactYaml(yaml, &changed);
        QVERIFY2(!out.contains(secret), out.constData());
        QVERIFY2(out.contains(kept), out.constData());
        QVERIFY(changed); // the run is private
        // What is stored is redacted for good: a second pass finds nothing left.
        bool again = true;
        QCOMPARE(Secrets::redactYaml(out, &again), out);
        QVERIFY2(!again || out.startsWith('#'), out.constData());
    }

    void whatHoldsNoSecretIsKeptAsItIs_data()
    {
        QTest::addColumn<QByteArray>("yaml");
        QTest::newRow("arg") << QByteArray("pass: $(arg pw)  # from the launch file\n");
        QTest::newRow("not a secret") << QByteArray("bypass: 1\npassive: true\npass_count: 3\n");
        QTest::newRow("empty") << QByteArray("pass: ''\nuser: ~\n");
        QTest::newRow("nothing") << QByteArray();
    }

    void whatHoldsNoSecretIsKeptAsItIs()
    {
        QFETCH(QByteArray, yaml);
        bool changed = true;
        QCOMPARE(Secrets::redactYaml(yaml, &changed), yaml);
        QVERIFY(!changed);
    }

    // Issue 31: watch -o stores the first config in the run; every YAML form of a password is
    // redacted there (by yaml-cpp's reading, not by patterns), and the run is private (0600).
    void watchRunsHoldNoPasswordInAnyForm_data()
    {
        QTest::addColumn<QByteArray>("before"); ///< the config's start
        QTest::addColumn<QByteArray>("form"); ///< the broker's password, as the config writes it
        QTest::newRow("'' in single quotes") << QByteArray() << QByteArray("  pass: 'it''s-%1'\n");
        QTest::newRow("plain continued") << QByteArray() << QByteArray("  pass: first\n    %1\n");
        QTest::newRow("double-quoted continued") << QByteArray() << QByteArray("  pass: \"first\n    %1\"\n");
        QTest::newRow("complex key") << QByteArray() << QByteArray("  ? pass\n  : %1\n");
        QTest::newRow("escaped key") << QByteArray() << QByteArray("  \"p\\x61ss\": %1\n");
        QTest::newRow("alias of another key")
            << QByteArray("client:\n  id: &pw %1\n") << QByteArray("  pass: *pw\n");
    }

    void watchRunsHoldNoPasswordInAnyForm()
    {
        QFETCH(QByteArray, before);
        QFETCH(QByteArray, form);
        const QString tag = QString::fromLatin1(QTest::currentDataTag()).replace(u' ', u'-').remove(u'\'');
        const auto withPassword = [](const QByteArray& text) {
            return text.contains("%1") ? QString::fromUtf8(text).arg(kConfigPassword).toUtf8() : text;
        };
        const QByteArray config = withPassword(before)
            + u"broker:\n  host: 127.0.0.1\n  port: %1\n  user: %2\n"_s.arg(m_servers.mosquittoPort())
                  .arg(kUser)
                  .toUtf8()
            + withPassword(form)
            + "bridge:\n  mqtt2ros:\n    - {mqtt_topic: lab/x, ros_topic: /lab/x, primitive: true}\n";
        // Outside the home folder, which the last test searches for passwords: the user's input.
        const QString path = m_servers.tempPath() + u"/"_s + tag + u".yaml"_s;
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(config);
        file.close();
        const QString run = m_home + u"/out/watch-"_s + tag + u".bsrun"_s;
        const Run watch = bridgescope({u"watch"_s, path, u"--broker"_s, urlWithPassword(), u"--seconds"_s,
                                       u"1"_s, u"--allow-empty"_s, u"-o"_s, run});
        QVERIFY2(watch.exit == 0, qPrintable(watch.err));
        struct stat st
        {
        };
        QCOMPARE(::stat(QFile::encodeName(run).constData(), &st), 0);
        QCOMPARE(int(st.st_mode & 0777), 0600);
        QDirIterator it(m_home + u"/out"_s, {u"watch-"_s + tag + u"*"_s}, QDir::Files | QDir::Hidden);
        int files = 0;
        while (it.hasNext()) {
            QFile f(it.next());
            QVERIFY(f.open(QIODevice::ReadOnly));
            QVERIFY2(!f.readAll().contains(kConfigPassword.toUtf8()), qPrintable(f.fileName()));
            ++files;
        }
        QVERIFY(files >= 1);
    }

    // Issue 31: demo started its bridges with --broker URL, password and all, on their command
    // lines, which every user reads in ps. Now the URL goes through a pipe, and the commands hide
    // the user info of the URL typed on their own command line once they have read it (before
    // they start anything): no process has the password in its command line.
    void demoChildrenNeverSeeThePassword()
    {
        const PsScan s = runAndScan({u"demo"_s, u"--broker"_s, urlWithPassword(), u"--ros-master"_s,
                                     m_servers.rosMasterUri(), u"--seconds"_s, u"8"_s},
                                    6000);
        QVERIFY2(s.seen.isEmpty(), qPrintable(s.seen.join(u'\n')));
        QVERIFY2(s.children > 0, qPrintable(s.err)); // the bridges were seen, given the pipe
        QVERIFY(s.ownHidden);
        QVERIFY2(s.exit == 0, qPrintable(s.err)); // they connected with the credentials: samples
    }

    // watch: its own command line, for the hours it runs
    void watchNeverShowsThePassword()
    {
        QVERIFY(publish(m_servers, u"lab/watched"_s, u"1"_s));
        const PsScan s = runAndScan({u"watch"_s, u"--broker"_s, urlWithPassword(), u"--ros-master"_s,
                                     m_servers.rosMasterUri(), u"--seconds"_s, u"4"_s},
                                    3500, 1000);
        QVERIFY2(s.seen.isEmpty(), qPrintable(s.seen.join(u'\n')));
        QVERIFY(s.ownHidden);
        QVERIFY2(s.exit == 0 && !s.err.contains(u"cannot be reached"_s), qPrintable(s.err)); // it connected
    }

    // experiment --broker: the plan holds no credentials (it is copied beside the runs); the
    // command line may, and neither the experiment nor its bridges show them
    void experimentNeverShowsThePassword()
    {
        const QString plan = writeFile(u"plan.yaml"_s, "samples: 5\nwarmup: 0\ntimeout_s: 60\n");
        const QString dir = m_home + u"/out/experiment"_s;
        const PsScan s = runAndScan({u"experiment"_s, plan, u"-o"_s, dir, u"--broker"_s, urlWithPassword(),
                                     u"--ros-master"_s, m_servers.rosMasterUri()},
                                    12000);
        QVERIFY2(s.seen.isEmpty(), qPrintable(s.seen.join(u'\n')));
        QVERIFY2(s.children > 0, qPrintable(s.err));
        QVERIFY(s.ownHidden);
        QVERIFY2(s.exit == 0, qPrintable(s.err)); // the cell completed: the bridges had the credentials
        // and none of its files holds them: the plan, the state, the runs, the logs
        QStringList holding;
        const QStringList searched = searchForPasswords(dir, {}, &holding);
        QVERIFY2(holding.isEmpty(), qPrintable(holding.join(u", "_s) + u" hold a password"_s));
        QVERIFY2(searched.contains(u"plan.yaml"_s), qPrintable(searched.join(u", "_s)));
        QVERIFY2(std::any_of(searched.cbegin(), searched.cend(),
                             [](const QString& f) { return f.endsWith(u".bsrun"_s); }),
                 qPrintable(searched.join(u", "_s)));
        QCOMPARE(bridgescope({u"experiment"_s, plan, u"-o"_s, dir, u"--broker"_s, u"tcp://x:y@"_s}).exit, 2);
    }

    // Issue 41, point 9: the window never hid its --broker password (only the commands did), and
    // a command given --broker=URL as one argument kept a password with '/', '?' or '#'. Now
    // main() hides every URL's user info first thing, for every entry point and form; each still
    // connects with the password as typed (the window's log says so, the commands' exit too).
    void noEntryPointShowsThePasswordInAnyForm_data()
    {
        QTest::addColumn<QStringList>("args"); ///< %URL% stands for the broker URL
        QTest::addColumn<bool>("encoded"); ///< the password percent-encoded in the URL
        QTest::addColumn<int>("ms"); ///< how long it runs
        const QString shot = u"--screenshot"_s;
        QTest::newRow("window --broker URL")
            << QStringList {u"--broker"_s, u"%URL%"_s,   u"--platform"_s, u"offscreen"_s, shot,
                            u"w1.png"_s,   u"--after"_s, u"3"_s,          u"--verbose"_s}
            << false << 3000;
        QTest::newRow("window --broker=URL, encoded")
            << QStringList {u"--broker=%URL%"_s, u"--platform"_s, u"offscreen"_s, shot,
                            u"w2.png"_s,         u"--after"_s,    u"3"_s,         u"--verbose"_s}
            << true << 3000;
        QTest::newRow("window --demo --broker=URL") << QStringList {u"--demo"_s,
                                                                    u"--broker=%URL%"_s,
                                                                    u"--ros-master"_s,
                                                                    m_servers.rosMasterUri(),
                                                                    u"--platform"_s,
                                                                    u"offscreen"_s,
                                                                    shot,
                                                                    u"w3.png"_s,
                                                                    u"--after"_s,
                                                                    u"5"_s,
                                                                    u"--verbose"_s}
                                                    << false << 5000;
        QTest::newRow("watch --broker=URL")
            << QStringList {u"watch"_s, u"--broker=%URL%"_s, u"--seconds"_s, u"3"_s} << false << 3000;
        QTest::newRow("discover --broker=URL, encoded")
            << QStringList {u"discover"_s, u"--broker=%URL%"_s, u"--seconds"_s, u"3"_s} << true << 3000;
        QTest::newRow("watch --broker URL")
            << QStringList {u"watch"_s, u"--broker"_s, u"%URL%"_s, u"--seconds"_s, u"3"_s} << false << 3000;
    }

    void noEntryPointShowsThePasswordInAnyForm()
    {
        QFETCH(QStringList, args);
        QFETCH(bool, encoded);
        QFETCH(int, ms);
        // concatenated: the encoded password's %2F and %3F would be arg()'s placeholders
        const QString url = u"tcp://"_s + kOddUser + u':' + (encoded ? kOddPasswordEncoded : kOddPassword)
            + u"@127.0.0.1:"_s + QString::number(m_servers.mosquittoPort());
        for (QString& a : args) {
            a.replace(u"%URL%"_s, url);
            if (a.endsWith(u".png"_s))
                a = m_home + u"/out/"_s + a;
        }
        // The password as typed, its pieces after each character a parser might stop at, the user.
        const QStringList secrets {
            kOddPassword, kOddPasswordEncoded, u"Od/d"_s,      u"Od%2F"_s, u"?Pw"_s, u"#x@"_s,
            u"x@y"_s,     u"%40y"_s,           kOddUser + u':'};
        // Under ASan the exit status holds LeakSanitizer's verdict too (the window that ran the
        // demo once left the chart views' first QChart behind).
        const PsScan s = runAndScan(args, ms - 500, 1500, secrets);
        QVERIFY2(s.seen.isEmpty(), qPrintable(s.seen.join(u'\n')));
        QVERIFY2(s.ownHidden, qPrintable(s.err)); // its own line was read, hidden
        QVERIFY2(s.exit == 0, qPrintable(s.err));
        // It used the password: the window's log, the command's exit and silence about the broker.
        if (args.contains(u"--verbose"_s))
            QVERIFY2(s.err.contains(u"tcp://127.0.0.1:%1 connected"_s.arg(m_servers.mosquittoPort())),
                     qPrintable(s.err));
        else
            QVERIFY2(!s.err.contains(u"cannot be reached"_s) && !s.err.contains(u"not authori"_s),
                     qPrintable(s.err));
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

        // Now search everything (but the config, the user's own input).
        QStringList holding;
        const QStringList searched = searchForPasswords(m_home, config, &holding);
        QVERIFY2(holding.isEmpty(), qPrintable(holding.join(u", "_s) + u" hold a password"_s));
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
