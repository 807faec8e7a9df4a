// SPDX-License-Identifier: MIT
// A 5,000-mapping config: open, validate and save with Bridgescope, against the same work done
// by yaml-cpp alone and by PyYAML (what users' scripts use), in the same run.
//
//   scripts/bench.sh bench_config
#include "app/gui/mainwindow.h"
#include "yaml/yamllimits.h"
#include "benchutil.h"
#include "config/configdocument.h"
#include "config/configreader.h"
#include "config/configvalidator.h"
#include "config/configwriter.h"
#include "widgets/map/configeditor.h"
#include "widgets/map/configfilecontroller.h"

#include <fstream>
#include <QApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QTableView>
#include <QTemporaryDir>
#include <yaml-cpp/yaml.h>

using namespace Qt::StringLiterals;

namespace {
// 2,500 mappings each way with comments, options and a substitution now and then: the shape of
// a large fleet config.
QByteArray makeConfig(int mappings)
{
    QByteArray text = "# generated: a large fleet bridge\nbroker:\n  host: broker.example\n  port: 1883\n"
                      "client:\n  id: fleet\nbridge:\n  ros2mqtt:\n";
    for (int i = 0; i < mappings / 2; ++i) {
        if (i % 10 == 0)
            text += "    # vehicle " + QByteArray::number(i / 10) + "\n";
        text += "    - ros_topic: /vehicle_" + QByteArray::number(i / 10) + "/sensor_" + QByteArray::number(i)
            + "\n      mqtt_topic: fleet/vehicle_" + QByteArray::number(i / 10) + "/sensor_"
            + QByteArray::number(i) + "\n";
        if (i % 3 == 0)
            text += "      inject_timestamp: true\n      advanced:\n        mqtt:\n          qos: $(arg "
                    "qos)\n";
    }
    text += "  mqtt2ros:\n";
    for (int i = 0; i < mappings / 2; ++i) {
        text += "    - mqtt_topic: fleet/commands/vehicle_" + QByteArray::number(i)
            + "\n      ros_topic: /commands_" + QByteArray::number(i) + "  # from the cloud\n";
        if (i % 4 == 0)
            text += "      primitive: true\n";
    }
    return text;
}

double pythonMs(const QString& path, int runs)
{
    // PyYAML with its C loader when available, the way a user's conversion script would do it.
    const QString script = uR"(
import sys, time, yaml
Loader = getattr(yaml, 'CSafeLoader', yaml.SafeLoader)
Dumper = getattr(yaml, 'CSafeDumper', yaml.SafeDumper)
times = []
for _ in range(int(sys.argv[2])):
    t = time.perf_counter()
    with open(sys.argv[1]) as f:
        data = yaml.load(f, Loader=Loader)
    with open(sys.argv[1] + '.py.yaml', 'w') as f:
        yaml.dump(data, f, Dumper=Dumper)
    times.append((time.perf_counter() - t) * 1000)
times.sort()
print(times[len(times) // 2])
)"_s;
    QProcess p;
    p.start(u"/usr/bin/python3"_s, {u"-c"_s, script, path, QString::number(runs)});
    if (!p.waitForFinished(120000) || p.exitCode() != 0)
        return -1;
    return p.readAllStandardOutput().trimmed().toDouble();
}
} // namespace

int main(int argc, char** argv)
{
    qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    const int mappings = 5000;
    const int runs = 7;
    QTemporaryDir dir;
    const QString path = dir.filePath(u"fleet.yaml"_s);
    {
        QFile f(path);
        f.open(QIODevice::WriteOnly);
        f.write(makeConfig(mappings));
    }
    std::printf("bench_config: %d mappings, %lld bytes, median of %d runs\n\n", mappings,
                static_cast<long long>(QFileInfo(path).size()), runs);
    Bench::header("ms");

    // Peers: parse + dump with yaml-cpp alone, and with PyYAML.
    const double yamlCpp = Bench::medianMs(runs, [&] {
        YAML::Node n = YAML::LoadFile(path.toStdString());
        std::ofstream out(QString(path + u".cpp.yaml"_s).toStdString());
        out << YAML::Dump(n);
    });
    Bench::row(u"peer: yaml-cpp load + dump + write"_s, yamlCpp);
    const double py = pythonMs(path, runs);
    Bench::row(u"peer: PyYAML (C loader) load + dump + write"_s, py);

    // Bridgescope, headless.
    const double open = Bench::medianMs(runs, [&] {
        ConfigDocument doc;
        if (!doc.load(path).ok)
            qFatal("load failed");
    });
    Bench::row(u"open (read, parse, validate)"_s, open, u"%1x yaml-cpp"_s.arg(open / yamlCpp, 0, 'f', 2));

    // The hostile-input pre-pass every open starts with (issue 11): UTF-8, control characters,
    // sizes, aliases, duplicate keys; one pass over the parser's events.
    QByteArray text;
    {
        QFile f(path);
        f.open(QIODevice::ReadOnly);
        text = f.readAll();
    }
    const double limits = Bench::medianMs(runs, [&] {
        if (YamlLimits::check(text))
            qFatal("limits refused the config");
    });
    Bench::row(u"of which: YAML limits pre-pass"_s, limits, u"%1 of open"_s.arg(limits / open, 0, 'f', 2));

    ConfigDocument doc;
    doc.load(path);
    const double validate = Bench::medianMs(runs, [&] { ConfigValidator::validate(doc.config()); });
    Bench::row(u"validate alone (every rule, 5,000 mappings)"_s, validate);

    int round = 0;
    const double save = Bench::medianMs(runs, [&] {
        Mapping m = doc.mapping(round % doc.mappingCount());
        m.set(u"advanced.mqtt.qos"_s, QString::number(round % 3));
        doc.replaceMapping(m);
        ++round;
        if (doc.save(path, ConfigLayout::Ros1, false).status != ConfigDocument::SaveResult::Saved)
            qFatal("save failed");
    });
    Bench::row(u"edit one mapping + save in place (comments kept, verified)"_s, save,
               u"%1x yaml-cpp"_s.arg(save / yamlCpp, 0, 'f', 2));

    const double total = Bench::medianMs(runs, [&] {
        ConfigDocument d;
        d.load(path);
        Mapping m = d.mapping(round % d.mappingCount());
        m.set(u"mqtt_topic"_s, u"renamed/%1"_s.arg(round++));
        d.replaceMapping(m);
        if (d.save(path, ConfigLayout::Ros1, false).status != ConfigDocument::SaveResult::Saved)
            qFatal("save failed");
    });
    Bench::row(u"open + validate + edit + save (the goal: < 1000 ms)"_s, total,
               u"%1x yaml-cpp, %2x PyYAML"_s.arg(total / yamlCpp, 0, 'f', 2)
                   .arg(py > 0 ? total / py : 0, 0, 'f', 2));

    const double convert
        = Bench::medianMs(runs, [&] { ConfigWriter::write(doc.config(), ConfigLayout::Ros2); });
    Bench::row(u"write the whole config as ROS 2"_s, convert);

    // The editor window: model, views, preview.
    const double gui = Bench::medianMs(3, [&] {
        MainWindow w;
        w.show();
        w.files()->openFile(path);
        QCoreApplication::processEvents();
        if (w.configEditor()->table()->model()->rowCount() != mappings)
            qFatal("rows missing");
    });
    Bench::row(u"GUI: open in the editor window (table, inspector, preview)"_s, gui);
    return 0;
}
