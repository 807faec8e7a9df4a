// SPDX-License-Identifier: MIT
// The layers (cmake/layers.txt): every #include under core/, widgets/ and app/ runs down the table,
// third-party headers stay in the folder that wraps them, there is no cycle between folders,
// docs/ARCHITECTURE.md's table is the file's, and the build refuses a forbidden include. No
// function is longer than kMaxFunctionLines, those defined inside class bodies included.
#include "base/logging.h"
#include "functionlengths.h"

#include <algorithm>
#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

using namespace Qt::StringLiterals;

namespace {

struct Layer
{
    QString folder;
    QStringList uses;
    QStringList libraries;
};

struct Table
{
    QList<Layer> layers;
    QString error;

    const Layer* find(const QString& folder) const
    {
        for (const Layer& l : layers)
            if (l.folder == folder)
                return &l;
        return nullptr;
    }
    /// Folders `folder` may use, directly or through others.
    QSet<QString> closure(const QString& folder) const
    {
        QSet<QString> seen;
        QStringList todo {folder};
        while (!todo.isEmpty()) {
            const Layer* l = find(todo.takeLast());
            for (const QString& u : l ? l->uses : QStringList()) {
                if (!seen.contains(u)) {
                    seen.insert(u);
                    todo << u;
                }
            }
        }
        return seen;
    }
    /// The table folder a file (repository-relative path) belongs to: the longest that holds it.
    QString folderOf(const QString& path) const
    {
        QString best;
        for (const Layer& l : layers)
            if (path.startsWith(l.folder + u'/') && !path.mid(l.folder.size() + 1).contains(u'/')
                && l.folder.size() > best.size())
                best = l.folder;
        return best;
    }
};

Table parseTable(const QString& text)
{
    Table t;
    const QStringList lines = text.split(u'\n');
    for (int i = 0; i < lines.size(); ++i) {
        QString line = lines[i];
        line = line.left(line.indexOf(u'#') < 0 ? line.size() : line.indexOf(u'#')).trimmed();
        if (line.isEmpty())
            continue;
        const QStringList cols = line.split(QRegularExpression(u"\\s{2,}"_s));
        if (cols.size() != 3) {
            t.error = u"layers.txt:%1: want 3 columns"_s.arg(i + 1);
            return t;
        }
        Layer l {cols[0], cols[1].split(u' ', Qt::SkipEmptyParts), cols[2].split(u' ', Qt::SkipEmptyParts)};
        l.uses.removeAll(u"-"_s);
        l.libraries.removeAll(u"-"_s);
        t.layers << l;
    }
    return t;
}

/// Third-party header families and the library a folder must list (itself or below) to use them.
const QList<std::pair<QRegularExpression, QString>>& families()
{
    static const QList<std::pair<QRegularExpression, QString>> f {
        {QRegularExpression(u"^(ros|rosbag|topic_tools|xmlrpcpp|[a-z_]+_msgs)/"_s), u"PkgConfig::ROSCPP"_s},
        {QRegularExpression(u"^(mqtt/|MQTTAsync|MQTTClient)"_s), u"PahoMqttCpp::paho-mqttpp3"_s},
        {QRegularExpression(u"^qt6keychain/"_s), u"qt6keychain"_s},
        {QRegularExpression(u"^yaml-cpp/"_s), u"yaml-cpp"_s},
        {QRegularExpression(u"^sqlite3\\.h$"_s), u"SQLite::SQLite3"_s},
        {QRegularExpression(u"^(QtWidgets|QtCharts)/|^Q(Widget|Application|MainWindow|Dialog|Chart)\\b"_s),
         u"Qt6::Widgets"_s},
    };
    return f;
}

struct Finding
{
    QString where; ///< file:line
    QString what;
};

/// Checks every #include of the sources under `root` (core/, widgets/, app/) against `table`.
/// Returns the offending lines and fills `edges` with folder -> folder uses.
QList<Finding> checkIncludes(const QString& root, const Table& table, QHash<QString, QSet<QString>>* edges)
{
    QList<Finding> out;
    static const QRegularExpression include(u"^\\s*#\\s*include\\s*([<\"])([^>\"]+)[>\"]"_s);
    QSet<QString> files;
    for (const QString& top : {u"core"_s, u"widgets"_s, u"app"_s}) {
        QDirIterator it(root + u'/' + top, {u"*.cpp"_s, u"*.h"_s}, QDir::Files, QDirIterator::Subdirectories);
        while (it.hasNext())
            files.insert(QDir(root).relativeFilePath(it.next()));
    }
    for (const QString& path : std::as_const(files)) {
        const QString folder = table.folderOf(path);
        const bool program = path.startsWith(u"app/"_s) && !path.mid(4).contains(u'/'); // main()s
        if (folder.isEmpty() && !program) {
            out << Finding {path, u"is in no folder of cmake/layers.txt"_s};
            continue;
        }
        const QSet<QString> visible = program ? QSet<QString>() : table.closure(folder);
        QSet<QString> libraries;
        for (const QString& f : visible + QSet<QString> {folder})
            if (const Layer* l = table.find(f))
                for (const QString& lib : l->libraries)
                    libraries.insert(lib);
        QFile file(root + u'/' + path);
        if (!file.open(QIODevice::ReadOnly)) {
            out << Finding {path, u"cannot be read"_s};
            continue;
        }
        const QStringList lines = QString::fromUtf8(file.readAll()).split(u'\n');
        const QString dir = QFileInfo(path).path();
        const QString base = QFileInfo(path).completeBaseName();
        for (int i = 0; i < lines.size(); ++i) {
            const QRegularExpressionMatch m = include.match(lines[i]);
            if (!m.hasMatch())
                continue;
            const QString where = u"%1:%2"_s.arg(path).arg(i + 1);
            const QString name = m.captured(2);
            if (m.captured(1) == u"<"_s) {
                if (program)
                    continue;
                for (const auto& [pattern, library] : families())
                    if (pattern.match(name).hasMatch() && !libraries.contains(library))
                        out << Finding {
                            where, u"<%1> needs %2, which %3 does not link"_s.arg(name, library, folder)};
                continue;
            }
            if (name.endsWith(u".moc"_s) || name.startsWith(u"moc_"_s))
                continue;
            if (!name.contains(u'/')) {
                if (QFileInfo(name).completeBaseName() != base || !files.contains(dir + u'/' + name))
                    out << Finding {
                        where,
                        u"\"%1\": name the folder (only a file's own header goes without)"_s.arg(name)};
                continue;
            }
            const QString target
                = name.startsWith(u"widgets/"_s) || name.startsWith(u"app/"_s) ? name : u"core/"_s + name;
            if (!files.contains(target)) {
                out << Finding {where, u"\"%1\" names no file of core/, widgets/ or app/"_s.arg(name)};
                continue;
            }
            const QString to = table.folderOf(target);
            if (program || to == folder)
                continue;
            (*edges)[folder].insert(to);
            if (!visible.contains(to))
                out << Finding {where, u"%1 may not use %2 (\"%3\")"_s.arg(folder, to, name)};
        }
    }
    return out;
}

/// A cycle in the folder graph, as "a -> b -> a", or empty. Folders are visited in name order, so
/// the same graph always gives the same cycle.
QString findCycle(const QHash<QString, QSet<QString>>& edges)
{
    QHash<QString, int> state; // 1: on the path, 2: done
    QStringList path;
    std::function<QString(const QString&)> visit = [&](const QString& n) -> QString {
        state[n] = 1;
        path << n;
        QStringList next = edges.value(n).values();
        next.sort();
        for (const QString& m : std::as_const(next)) {
            if (state.value(m) == 1)
                return (path.mid(path.indexOf(m)) << m).join(u" -> "_s);
            if (state.value(m) == 0)
                if (QString c = visit(m); !c.isEmpty())
                    return c;
        }
        path.removeLast();
        state[n] = 2;
        return {};
    };
    QStringList folders = edges.keys();
    folders.sort();
    for (const QString& f : std::as_const(folders))
        if (state.value(f) == 0)
            if (QString c = visit(f); !c.isEmpty())
                return c;
    return {};
}

QString readAll(const QString& path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? QString::fromUtf8(f.readAll()) : QString();
}

QString source(const QString& relative)
{
    return QStringLiteral(BRIDGESCOPE_SOURCE_DIR) + u'/' + relative;
}

QString describe(const QList<Finding>& findings)
{
    QStringList lines;
    for (const Finding& f : findings)
        lines << f.where + u": "_s + f.what;
    return lines.join(u'\n');
}

/// The longest a function may be, from the first line of its head to its closing brace.
constexpr int kMaxFunctionLines = 100;

/// Functions known to be longer, each with why it stays for now ("file:name"). One that is no
/// longer over the limit is said too, so that the list only shrinks.
const QHash<QString, QString>& knownLongFunctions()
{
    static const QHash<QString, QString> known {};
    return known;
}

/// The functions of the sources under `root` (core/, widgets/, app/) longer than
/// kMaxFunctionLines, and the files that could not be measured; `measured` counts the functions.
QList<Finding> checkFunctionLengths(const QString& root, int* measured)
{
    QList<Finding> out;
    QSet<QString> stillLong;
    for (const QString& top : {u"core"_s, u"widgets"_s, u"app"_s}) {
        QDirIterator it(root + u'/' + top, {u"*.cpp"_s, u"*.h"_s}, QDir::Files, QDirIterator::Subdirectories);
        while (it.hasNext()) {
            const QString path = it.next();
            QFile file(path);
            const QString relative = QDir(root).relativeFilePath(path);
            if (!file.open(QIODevice::ReadOnly)) {
                out << Finding {relative, u"cannot be read"_s};
                continue;
            }
            const FunctionLengths::Scan scan = FunctionLengths::scan(QString::fromUtf8(file.readAll()));
            if (!scan.error.isEmpty())
                out << Finding {relative, u"cannot be measured: "_s + scan.error};
            *measured += int(scan.functions.size());
            for (const FunctionLengths::Function& f : scan.functions) {
                const QString key = relative + u':' + f.name;
                if (f.lines > kMaxFunctionLines && !knownLongFunctions().contains(key))
                    out << Finding {
                        u"%1:%2"_s.arg(relative).arg(f.line),
                        u"%1 is %2 lines, more than %3"_s.arg(f.name).arg(f.lines).arg(kMaxFunctionLines)};
                if (f.lines > kMaxFunctionLines)
                    stillLong << key;
            }
        }
    }
    for (auto it = knownLongFunctions().cbegin(); it != knownLongFunctions().cend(); ++it)
        if (!stillLong.contains(it.key()))
            out << Finding {it.key(), u"is listed as long but is not (any more): take it off the list"_s};
    std::sort(out.begin(), out.end(), [](const Finding& a, const Finding& b) { return a.where < b.where; });
    return out;
}

void writeFile(const QString& path, const QByteArray& text)
{
    QDir().mkpath(QFileInfo(path).path());
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(text);
}

} // namespace

class TestArchitecture : public QObject
{
    Q_OBJECT
    Table m_table;

private slots:
    void initTestCase()
    {
        m_table = parseTable(readAll(source(u"cmake/layers.txt"_s)));
        QVERIFY2(m_table.error.isEmpty(), qPrintable(m_table.error));
        QVERIFY(m_table.layers.size() >= 10);
    }

    void tableRunsDownward()
    {
        QStringList above;
        for (const Layer& l : std::as_const(m_table.layers)) {
            QVERIFY2(QFileInfo(source(l.folder)).isDir(), qPrintable(l.folder + u" is not a folder"_s));
            for (const QString& u : l.uses)
                QVERIFY2(above.contains(u),
                         qPrintable(l.folder + u" uses " + u + u", not listed above it"_s));
            above << l.folder;
        }
    }

    void everyIncludeIsAllowed()
    {
        QHash<QString, QSet<QString>> edges;
        const QList<Finding> findings
            = checkIncludes(QStringLiteral(BRIDGESCOPE_SOURCE_DIR), m_table, &edges);
        QVERIFY2(findings.isEmpty(), qPrintable(u"\n"_s + describe(findings)));
        // The tree really is layered: the session folder reaches both transports.
        QVERIFY(edges.value(u"core/session"_s).contains(u"core/mqtt"_s));
        QVERIFY(edges.value(u"core/session"_s).contains(u"core/ros"_s));
        const QString cycle = findCycle(edges);
        QVERIFY2(cycle.isEmpty(), qPrintable(cycle));
        // The folder graph as the includes draw it, for `tst_architecture everyIncludeIsAllowed`.
        QStringList graph;
        for (auto it = edges.cbegin(); it != edges.cend(); ++it) {
            QStringList to = it.value().values();
            to.sort();
            graph << it.key() + u" -> "_s + to.join(u", "_s);
        }
        graph.sort();
        qInfo().noquote() << u"folder graph (no cycle):\n  "_s + graph.join(u"\n  "_s);
    }

    // Issue 42: the views show either ROS graph through core/topics and core/session
    // (GraphStatus); no widget includes a ROS transport, so a third graph is no widget's change.
    void noWidgetIncludesARosTransport()
    {
        QHash<QString, QSet<QString>> edges;
        (void)checkIncludes(QStringLiteral(BRIDGESCOPE_SOURCE_DIR), m_table, &edges);
        QStringList found;
        for (auto it = edges.cbegin(); it != edges.cend(); ++it)
            if (it.key().startsWith(u"widgets/"_s))
                for (const QString& transport : {u"core/ros"_s, u"core/ros2"_s, u"core/dds"_s})
                    if (it.value().contains(transport))
                        found << it.key() + u" -> "_s + transport;
        QVERIFY2(found.isEmpty(), qPrintable(found.join(u"; "_s)));
        QVERIFY(edges.value(u"widgets/common"_s).contains(u"core/topics"_s)); // the topic table's models
    }

    // A page takes the parts it shows (its Parts), built where the window is composed
    // (app/gui/pageparts.h), never the live session itself; nor does a consumer in core/.
    void noWidgetIncludesTheLiveSession()
    {
        static const QRegularExpression include(u"^\\s*#\\s*include\\s*\"session/livesession\\.h\""_s,
                                                QRegularExpression::MultilineOption);
        QStringList found;
        const QStringList consumers {u"core/session/fieldplotter.h"_s, u"core/session/fieldplotter.cpp"_s,
                                     u"core/session/measuresession.h"_s, u"core/session/measuresession.cpp"_s,
                                     u"core/watch/watchsession.h"_s, u"core/watch/watchsession.cpp"_s};
        for (const QString& path : consumers)
            if (include.match(readAll(source(path))).hasMatch())
                found << path;
        QDirIterator files(source(u"widgets"_s), {u"*.cpp"_s, u"*.h"_s}, QDir::Files, QDirIterator::Subdirectories);
        int read = 0;
        while (files.hasNext()) {
            const QString path = files.next();
            ++read;
            if (include.match(readAll(path)).hasMatch())
                found << path;
        }
        QVERIFY(read > 50); // the widgets were read
        QVERIFY2(found.isEmpty(), qPrintable(found.join(u"; "_s)));
    }

    // The checker itself, on a small tree that breaks each rule once.
    void checkerFindsEveryKindOfViolation()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const Table table = parseTable(u"core/base  -  Qt6::Core\n"
                                       "core/config  core/base  yaml-cpp\n"
                                       "core/ros  core/base  PkgConfig::ROSCPP\n"_s);
        QVERIFY(table.error.isEmpty());
        writeFile(dir.filePath(u"core/base/clock.h"_s), "#pragma once\n#include \"config/reader.h\"\n");
        writeFile(dir.filePath(u"core/config/reader.h"_s), "#pragma once\n#include <ros/ros.h>\n");
        writeFile(dir.filePath(u"core/config/reader.cpp"_s),
                  "#include \"reader.h\"\n#include \"base/clock.h\"\n#include \"clock.h\"\n"
                  "#include \"base/missing.h\"\n#include <yaml-cpp/yaml.h>\n");
        writeFile(dir.filePath(u"core/ros/node.cpp"_s),
                  "#include <ros/ros.h>\n#include \"config/reader.h\"\n");
        writeFile(dir.filePath(u"core/stray/x.cpp"_s), "\n");
        QHash<QString, QSet<QString>> edges;
        const QString found = describe(checkIncludes(dir.path(), table, &edges));
        QVERIFY2(found.contains(u"core/base/clock.h:2: core/base may not use core/config"_s),
                 qPrintable(found));
        QVERIFY2(found.contains(u"core/config/reader.h:2: <ros/ros.h> needs PkgConfig::ROSCPP"_s),
                 qPrintable(found));
        QVERIFY2(found.contains(u"core/config/reader.cpp:3: \"clock.h\": name the folder"_s),
                 qPrintable(found));
        QVERIFY2(found.contains(u"core/config/reader.cpp:4: \"base/missing.h\" names no file"_s),
                 qPrintable(found));
        QVERIFY2(found.contains(u"core/ros/node.cpp:2: core/ros may not use core/config"_s),
                 qPrintable(found));
        QVERIFY2(found.contains(u"core/stray/x.cpp: is in no folder"_s), qPrintable(found));
        QVERIFY2(!found.contains(u"reader.cpp:1"_s) && !found.contains(u"reader.cpp:2"_s)
                     && !found.contains(u"reader.cpp:5"_s) && !found.contains(u"node.cpp:1"_s),
                 qPrintable(found));
        QCOMPARE(findCycle(edges), u"core/base -> core/config -> core/base"_s);
    }

    // Issue 42, point 7: every function is measured, those defined inside class bodies too
    // (inline members in headers, members of a .cpp's own classes: Checker::checkTypedValues was 101).
    void noFunctionIsLongerThanTheLimit()
    {
        int measured = 0;
        const QList<Finding> findings
            = checkFunctionLengths(QStringLiteral(BRIDGESCOPE_SOURCE_DIR), &measured);
        qInfo("%d functions measured", measured);
        QVERIFY2(measured > 2000, qPrintable(QString::number(measured))); // the whole tree was read
        QVERIFY2(findings.isEmpty(), qPrintable(u"\n"_s + describe(findings)));
    }

    // The length checker itself, on every kind of function and on what only looks like one.
    void lengthCheckerSeesEveryKindOfFunction()
    {
        // A source as lines (in a raw string moc would read them as code and directives).
        const QString text = QStringList {
            u"#include \"x.h\""_s,
            u"#define BRACE {"_s,
            u"namespace {"_s,
            u"const QHash<QString, int> kTable {{\"a{\", 1}, {\"}\", 2}};"_s,
            u"class Local"_s,
            u"{"_s,
            u"    Q_DECLARE_TR_FUNCTIONS(Local)"_s,
            u"public:"_s,
            u"    Local(int a)"_s,
            u"        : m_a {a}"_s,
            u"        , m_b(a)"_s,
            u"    {"_s,
            u"        m_c = '{';"_s,
            u"    }"_s,
            u"    int inlineMember() const"_s,
            u"    {"_s,
            u"        return 1'000'000; // {"_s,
            u"    }"_s,
            u"    bool operator==(const Local& o) const { return m_a == o.m_a; }"_s,
            u"    struct Inner"_s,
            u"    {"_s,
            u"        void nested() { const auto f = [] { return \"}\"; }; }"_s,
            u"    };"_s,
            u"private:"_s,
            u"    int m_a {0};"_s,
            u"    int m_b = 0;"_s,
            u"    std::function<void()> m_f = [] {"_s,
            u"    };"_s,
            u"};"_s,
            u"} // namespace"_s,
            u""_s,
            u"template <typename T>"_s,
            u"T Outer::member(T t) const"_s,
            u"{"_s,
            u"    /* } */"_s,
            u"    return t + R\"x(})x\";"_s,
            u"}"_s,
            u""_s,
            u"void free()"_s,
            u"{"_s,
            u"}"_s,
        }.join(u'\n') + u'\n';
        const FunctionLengths::Scan scan = FunctionLengths::scan(text);
        QVERIFY2(scan.error.isEmpty(), qPrintable(scan.error));
        QStringList found;
        for (const FunctionLengths::Function& f : scan.functions)
            found << u"%1 %2 %3"_s.arg(f.name).arg(f.line).arg(f.lines);
        QCOMPARE(found,
                 QStringList({u"Local 9 6"_s, u"inlineMember 15 4"_s, u"operator== 19 1"_s, u"nested 22 1"_s,
                              u"Outer::member 32 6"_s, u"free 39 3"_s}));
        // A brace that does not close is said, not measured as a function to the end.
        QVERIFY(!FunctionLengths::scan(u"void f()\n{\n"_s).error.isEmpty());
    }

    void documentedTableIsTheFile()
    {
        const QString doc = readAll(source(u"docs/ARCHITECTURE.md"_s));
        const qsizetype from = doc.indexOf(u"<!-- layers -->"_s);
        const qsizetype to = doc.indexOf(u"<!-- /layers -->"_s);
        QVERIFY2(from >= 0 && to > from, "docs/ARCHITECTURE.md has no <!-- layers --> table");
        QStringList rows;
        static const QRegularExpression row(u"^\\|\\s*`([^`]+)`\\s*\\|[^|]*\\|([^|]*)\\|"_s);
        for (const QString& line : doc.mid(from, to - from).split(u'\n')) {
            const QRegularExpressionMatch m = row.match(line);
            if (!m.hasMatch())
                continue;
            QStringList uses;
            static const QRegularExpression tick(u"`([^`]+)`"_s);
            for (auto it = tick.globalMatch(m.captured(2)); it.hasNext();)
                uses << it.next().captured(1);
            rows << m.captured(1) + u": "_s + uses.join(u' ');
        }
        QStringList expected;
        for (const Layer& l : std::as_const(m_table.layers))
            expected << l.folder + u": "_s + l.uses.join(u' ');
        QCOMPARE(rows, expected);
    }

    // Issue 35: the logging categories the code has are the ones ARCHITECTURE.md's table and the
    // user guide list, in the order of Logging::categoryNames(); each is defined once and used.
    void everyLoggingCategoryIsDocumentedAndUsed()
    {
        const QStringList names = Logging::categoryNames();
        const QString code = readAll(source(u"core/base/logging.cpp"_s));
        static const QRegularExpression defined(u"Q_LOGGING_CATEGORY\\((\\w+), \"([^\"]+)\""_s);
        QStringList definedNames, variables;
        for (auto it = defined.globalMatch(code); it.hasNext();) {
            const QRegularExpressionMatch m = it.next();
            variables << m.captured(1);
            definedNames << m.captured(2);
        }
        QCOMPARE(names, definedNames);

        const QString doc = readAll(source(u"docs/ARCHITECTURE.md"_s));
        const qsizetype from = doc.indexOf(u"<!-- logging -->"_s);
        const qsizetype to = doc.indexOf(u"<!-- /logging -->"_s);
        QVERIFY2(from >= 0 && to > from, "docs/ARCHITECTURE.md has no <!-- logging --> table");
        QStringList documented;
        static const QRegularExpression row(u"^\\|\\s*`(bridgescope\\.[a-z0-9]+)`"_s);
        for (const QString& line : doc.mid(from, to - from).split(u'\n'))
            if (const QRegularExpressionMatch m = row.match(line); m.hasMatch())
                documented << m.captured(1);
        QCOMPARE(documented, names);

        const QString guide = readAll(source(u"docs/user-guide.md"_s));
        for (const QString& name : names)
            QVERIFY2(guide.contains(u'`' + name + u'`'), qPrintable(name + u" is not in the user guide"_s));

        // Defined in logging.cpp only, and each used somewhere else.
        QHash<QString, int> uses;
        for (const QString& folder : {u"core"_s, u"app"_s, u"widgets"_s}) {
            QDirIterator files(source(folder), {u"*.cpp"_s, u"*.h"_s}, QDir::Files, QDirIterator::Subdirectories);
            while (files.hasNext()) {
                const QString path = files.next();
                if (path.endsWith(u"/base/logging.cpp"_s) || path.endsWith(u"/base/logging.h"_s))
                    continue;
                const QString text = readAll(path);
                QVERIFY2(!text.contains(u"Q_LOGGING_CATEGORY("_s), qPrintable(path));
                for (const QString& v : std::as_const(variables))
                    if (text.contains(u'(' + v + u')'))
                        ++uses[v];
            }
        }
        for (const QString& v : std::as_const(variables))
            QVERIFY2(uses.value(v) > 0, qPrintable(v + u" is never used"_s));
    }

    // The build enforces the table too: in a config source's compile command, an MQTT header is
    // not found, while a base header is.
    void buildRefusesForbiddenInclude()
    {
        QFile db(QStringLiteral(BRIDGESCOPE_BINARY_DIR) + u"/compile_commands.json"_s);
        QVERIFY2(db.open(QIODevice::ReadOnly), "no compile_commands.json in the build folder");
        const QJsonArray commands = QJsonDocument::fromJson(db.readAll()).array();
        QString command;
        QString file;
        for (const QJsonValue& v : commands) {
            const QJsonObject o = v.toObject();
            // The core_config library's command (the fuzz targets compile the same file their own way).
            if (o.value(u"file"_s).toString().endsWith(u"/core/config/configreader.cpp"_s)
                && o.value(u"command"_s).toString().contains(u"/core_config.dir/"_s)) {
                command = o.value(u"command"_s).toString();
                file = o.value(u"file"_s).toString();
            }
        }
        QVERIFY2(!command.isEmpty(), "core/config/configreader.cpp is not in compile_commands.json");
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        auto compiles = [&](const QByteArray& include, QString* said) {
            const QString probe = dir.filePath(u"probe.cpp"_s);
            writeFile(probe, "#include \"" + include + "\"\nint main() { return 0; }\n");
            QStringList args = QProcess::splitCommand(command);
            if (QFileInfo(args.first()).fileName() == u"ccache"_s)
                args.removeFirst();
            const QString compiler = args.takeFirst();
            // Only check the probe: no object, no dependency file, not the real source.
            QStringList kept;
            for (int i = 0; i < args.size(); ++i) {
                const QString& a = args[i];
                if (a == u"-o"_s || a == u"-MT"_s || a == u"-MF"_s)
                    ++i;
                else if (a != u"-c"_s && a != file && !a.startsWith(u"-MD"_s))
                    kept << a;
            }
            QProcess p;
            p.start(compiler, kept << u"-fsyntax-only"_s << probe);
            p.waitForFinished(120000);
            *said = QString::fromUtf8(p.readAllStandardError());
            return p.exitStatus() == QProcess::NormalExit && p.exitCode() == 0;
        };
        QString said;
        QVERIFY2(compiles("base/wallclock.h", &said), qPrintable(said));
        QVERIFY(!compiles("mqtt/mqttconnection.h", &said));
        QVERIFY2(said.contains(u"mqtt/mqttconnection.h"_s) && said.contains(u"No such file"_s),
                 qPrintable(said));
        QVERIFY(!compiles("session/livesession.h", &said));
        QVERIFY2(said.contains(u"session/livesession.h"_s), qPrintable(said));
    }
};

QTEST_GUILESS_MAIN(TestArchitecture)
#include "tst_architecture.moc"
