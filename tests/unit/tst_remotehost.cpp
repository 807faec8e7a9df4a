// SPDX-License-Identifier: MIT
// Hosts of an experiment plan (issue 43): ssh:// URLs read strictly (never a password), and the
// command lines ssh gets, where no word of a plan can add shell syntax on the far host.
#include "remote/outputtail.h"
#include "remote/remotehost.h"
#include "remote/sshcommand.h"

#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

using namespace Qt::StringLiterals;

namespace {
// What a POSIX shell makes of `line`: each word it ends up with, in brackets.
QString shellWords(const QString& line, const QString& dir)
{
    QProcess sh;
    sh.setWorkingDirectory(dir);
    sh.start(u"/bin/sh"_s, {u"-c"_s, u"printf '[%s]' "_s + line});
    if (!sh.waitForFinished(10000))
        return u"<timeout>"_s;
    return QString::fromUtf8(sh.readAllStandardOutput() + sh.readAllStandardError());
}
} // namespace

class TestRemoteHost : public QObject
{
    Q_OBJECT
private slots:
    void parsesHostUrls_data()
    {
        QTest::addColumn<QString>("url");
        QTest::addColumn<QString>("user");
        QTest::addColumn<QString>("host");
        QTest::addColumn<int>("port");
        QTest::addColumn<QString>("canonical");
        QTest::newRow("name") << u"ssh://pi@vehicle.lab"_s << u"pi"_s << u"vehicle.lab"_s << 22
                              << u"ssh://pi@vehicle.lab"_s;
        QTest::newRow("port") << u"ssh://ros_user@cloud:2222"_s << u"ros_user"_s << u"cloud"_s << 2222
                              << u"ssh://ros_user@cloud:2222"_s;
        QTest::newRow("port 22 dropped") << u"ssh://a@h:22"_s << u"a"_s << u"h"_s << 22 << u"ssh://a@h"_s;
        QTest::newRow("ipv4") << u"ssh://root@10.1.2.3:1"_s << u"root"_s << u"10.1.2.3"_s << 1
                              << u"ssh://root@10.1.2.3:1"_s;
        QTest::newRow("ipv6") << u"ssh://u@[fe80::1]:65535"_s << u"u"_s << u"fe80::1"_s << 65535
                              << u"ssh://u@[fe80::1]:65535"_s;
        QTest::newRow("ipv6 no port") << u"ssh://u@[::1]"_s << u"u"_s << u"::1"_s << 22 << u"ssh://u@[::1]"_s;
        QTest::newRow("user 32") << u"ssh://_abcdefghijklmnopqrstuvwxyz-0123@h"_s
                                 << u"_abcdefghijklmnopqrstuvwxyz-0123"_s << u"h"_s << 22
                                 << u"ssh://_abcdefghijklmnopqrstuvwxyz-0123@h"_s;
    }
    void parsesHostUrls()
    {
        QFETCH(QString, url);
        const Result<RemoteHost> host = RemoteHost::parse(url);
        QVERIFY2(host.ok(), qPrintable(host.ok() ? QString() : host.error().toString()));
        QTEST(host->user, "user");
        QTEST(host->host, "host");
        QTEST(int(host->port), "port");
        QTEST(host->url(), "canonical");
    }

    void refusesWhatIsNotAHostUrl_data()
    {
        QTest::addColumn<QString>("url");
        QTest::addColumn<QString>("message");
        QTest::newRow("scheme")
            << u"http://u@h"_s
            << u"\"http://u@h\" is not an ssh:// URL: want ssh://user@host or ssh://user@host:port"_s;
        QTest::newRow("no user")
            << u"ssh://h"_s << u"\"ssh://h\" names no user: want ssh://user@host or ssh://user@host:port"_s;
        QTest::newRow("upper-case user")
            << u"ssh://Root@h"_s
            << u"\"Root\" is not a user name (lower-case letters, digits, '_' and '-', at most 32, not starting with a digit or '-')"_s;
        QTest::newRow("user 33")
            << u"ssh://abcdefghijklmnopqrstuvwxyz0123456@h"_s
            << u"\"abcdefghijklmnopqrstuvwxyz0123456\" is not a user name (lower-case letters, digits, '_' and '-', at most 32, not starting with a digit or '-')"_s;
        QTest::newRow("option as user")
            << u"ssh://-oProxyCommand=x@h"_s
            << u"\"-oProxyCommand=x\" is not a user name (lower-case letters, digits, '_' and '-', at most 32, not starting with a digit or '-')"_s;
        QTest::newRow("option as host")
            << u"ssh://u@-oProxyCommand=touch"_s
            << u"\"-oProxyCommand=touch\" is neither a host name nor an IP address (a path, a query or other characters are not allowed)"_s;
        QTest::newRow("shell in host")
            << u"ssh://u@h;reboot"_s
            << u"\"h;reboot\" is neither a host name nor an IP address (a path, a query or other characters are not allowed)"_s;
        QTest::newRow("path")
            << u"ssh://u@h/x"_s
            << u"\"h/x\" is neither a host name nor an IP address (a path, a query or other characters are not allowed)"_s;
        QTest::newRow("no host")
            << u"ssh://u@"_s << u"\"ssh://u@\" names no host: want ssh://user@host or ssh://user@host:port"_s;
        QTest::newRow("bad ipv4")
            << u"ssh://u@10.0.0.256"_s
            << u"\"10.0.0.256\" is neither a host name nor an IP address (a path, a query or other characters are not allowed)"_s;
        QTest::newRow("bare ipv6")
            << u"ssh://u@::1"_s
            << u"\"ssh://u@::1\": an IPv6 address goes in brackets (ssh://user@[::1]:22)"_s;
        QTest::newRow("bad ipv6") << u"ssh://u@[fe80::g]"_s << u"\"fe80::g\" is not an IPv6 address"_s;
        QTest::newRow("port 0") << u"ssh://u@h:0"_s << u"\"0\" is not a port (1 to 65535)"_s;
        QTest::newRow("port 65536") << u"ssh://u@h:65536"_s << u"\"65536\" is not a port (1 to 65535)"_s;
        QTest::newRow("port sign") << u"ssh://u@h:+22"_s << u"\"+22\" is not a port (1 to 65535)"_s;
        QTest::newRow("empty port") << u"ssh://u@h:"_s << u"\"ssh://u@h:\": an empty port"_s;
        QTest::newRow("too long") << u"ssh://u@"_s + QString(400, u'a')
                                  << u"a host URL longer than 300 characters"_s;
    }
    void refusesWhatIsNotAHostUrl()
    {
        QFETCH(QString, url);
        const Result<RemoteHost> host = RemoteHost::parse(url);
        QVERIFY(!host.ok());
        QTEST(host.error().toString(), "message");
    }

    void refusesAPasswordWithoutRepeatingIt_data()
    {
        QTest::addColumn<QString>("url");
        QTest::newRow("ssh") << u"ssh://user:s3cret-pw@h"_s;
        QTest::newRow("empty user") << u"ssh://:s3cret-pw@h:22"_s;
        QTest::newRow("other scheme") << u"sftp://user:s3cret-pw@h"_s;
        QTest::newRow("@ in password") << u"ssh://user:s3cret-pw@x@h"_s;
    }
    void refusesAPasswordWithoutRepeatingIt()
    {
        QFETCH(QString, url);
        const Result<RemoteHost> host = RemoteHost::parse(url);
        QVERIFY(!host.ok());
        QCOMPARE(
            host.error().toString(),
            u"a password in a host URL is never accepted: use a key or an ssh agent (ssh://user@host)"_s);
        QVERIFY(!host.error().toString().contains(u"s3cret"_s));
    }

    void sshArgumentsAreFixedAndBatch()
    {
        const RemoteHost host = *RemoteHost::parse(u"ssh://pi@[fd00::2]:2200"_s);
        SshOptions options;
        options.identityFile = u"/keys/lab key"_s;
        options.knownHostsFile = u"/keys/known_hosts"_s;
        const Result<QStringList> args = SshCommand::arguments(host, options, u"'true'"_s);
        QVERIFY(args.ok());
        QCOMPARE(*args, QStringList({u"-o"_s,         u"BatchMode=yes"_s,
                                     u"-o"_s,         u"PasswordAuthentication=no"_s,
                                     u"-o"_s,         u"KbdInteractiveAuthentication=no"_s,
                                     u"-o"_s,         u"ConnectTimeout=5"_s,
                                     u"-o"_s,         u"ServerAliveInterval=2"_s,
                                     u"-o"_s,         u"ServerAliveCountMax=3"_s,
                                     u"-i"_s,         u"/keys/lab key"_s,
                                     u"-o"_s,         u"UserKnownHostsFile=/keys/known_hosts"_s,
                                     u"-p"_s,         u"2200"_s,
                                     u"pi@fd00::2"_s, u"--"_s,
                                     u"'true'"_s}));
        // Without a key or known-hosts file: ssh's defaults (and the agent), nothing added.
        const Result<QStringList> plain = SshCommand::arguments(host, SshOptions {}, u"'true'"_s);
        QVERIFY(!plain->contains(u"-i"_s));
        QCOMPARE(plain->size(), args->size() - 4);
        // A known-hosts name ssh would split or expand is refused rather than passed.
        options.knownHostsFile = u"/keys/a b"_s;
        const Result<QStringList> split = SshCommand::arguments(host, options, u"'true'"_s);
        QVERIFY(!split.ok());
        QVERIFY(split.error().toString().contains(u"white space"_s));
    }

    void hostileWordsReachTheShellAsPlainWords_data()
    {
        QTest::addColumn<QStringList>("words");
        const QString touch = u"touch injected"_s;
        QTest::newRow("semicolon") << QStringList {u"a; "_s + touch};
        QTest::newRow("command substitution") << QStringList {u"$("_s + touch + u")"_s};
        QTest::newRow("backticks") << QStringList {u"`"_s + touch + u"`"_s};
        QTest::newRow("newline") << QStringList {u"a\n"_s + touch};
        QTest::newRow("single quote") << QStringList {u"it's'; "_s + touch + u"; '"_s};
        QTest::newRow("double quote") << QStringList {u"\"; "_s + touch + u"; \""_s};
        QTest::newRow("pipe and redirect") << QStringList {u"| "_s + touch + u" > x &"_s};
        QTest::newRow("variables and globs") << QStringList {u"$HOME ${IFS} * ~ \\"_s};
        QTest::newRow("leading dash") << QStringList {u"-rf"_s, u"--"_s, u"-oProxyCommand="_s + touch};
        QTest::newRow("empty word") << QStringList {QString(), u"b"_s};
        QTest::newRow("utf-8") << QStringList {u"Fahrzeug–Wolke ✓"_s};
    }
    void hostileWordsReachTheShellAsPlainWords()
    {
        QFETCH(QStringList, words);
        QTemporaryDir dir;
        const Result<QString> line = SshCommand::commandLine(words);
        QVERIFY(line.ok());
        QString expected;
        for (const QString& word : words)
            expected += u'[' + word + u']';
        QCOMPARE(shellWords(*line, dir.path()), expected);
        QVERIFY2(!QFile::exists(dir.filePath(u"injected"_s)), "a word ran a command");
    }

    void refusesWordsItCannotSend()
    {
        QVERIFY(!SshCommand::commandLine({}).ok());
        const Result<QString> nul = SshCommand::commandLine({u"a"_s + QChar(0) + u"b"_s});
        QVERIFY(!nul.ok());
        QCOMPARE(nul.error().toString(), u"a word for the far host holds a NUL character"_s);
    }

    void outputTailKeepsTheLastLinesBounded()
    {
        OutputTail tail(3, 10);
        QCOMPARE(tail.append("one\ntwo\nthr"), QStringList({u"one"_s, u"two"_s}));
        QCOMPARE(tail.append("ee\n" + QByteArray(100000, 'x') + "\nfive"),
                 QStringList({u"three"_s, QString(10, u'x') + u"…"_s}));
        tail.flush();
        QCOMPARE(tail.lines(), QStringList({u"three"_s, QString(10, u'x') + u"…"_s, u"five"_s}));
    }
};

QTEST_GUILESS_MAIN(TestRemoteHost)
#include "tst_remotehost.moc"
