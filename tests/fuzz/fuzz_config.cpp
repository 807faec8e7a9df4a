// SPDX-License-Identifier: MIT
// Fuzz target for config files: read (mqtt_client ROS 1 and ROS 2 layouts, mqtt_bridge), validate,
// save a small edit in place, and write in every layout, as `config validate|convert|peer` and the
// Map page do with whatever file a user opens.
//
// The last input byte picks the edit; the rest is the file. Properties: every problem has a
// message; a patched text reads back as the edited config (the patcher promises to check that);
// whatever we write in a layout reads back as a config, and a config that reads without problems
// or loss reads back the same from its own layout.
#include "config/configpatcher.h"
#include "config/configreader.h"
#include "config/configvalidator.h"
#include "config/configwriter.h"
#include "fuzzcheck.h"

namespace {

BridgeConfig edited(const BridgeConfig& baseline, uint8_t edit)
{
    BridgeConfig wanted = baseline;
    switch (edit % 5) {
    case 0:
        wanted.client.values.setText(QStringLiteral("keep_alive_interval"), QStringLiteral("10.5"));
        break;
    case 1:
        wanted.broker.values.setText(QStringLiteral("host"), QStringLiteral("broker.example"));
        break;
    case 2:
        if (!wanted.mappings.isEmpty())
            wanted.mappings.first().set(QStringLiteral("mqtt_topic"), QStringLiteral("fuzz/edited"));
        break;
    case 3:
        if (!wanted.mappings.isEmpty())
            wanted.mappings.removeLast();
        break;
    default:
        wanted.mappings.append(Mapping::create(Direction::Ros2Mqtt, QStringLiteral("/fuzz/added"),
                                               QStringLiteral("fuzz/added")));
        break;
    }
    return wanted;
}

/// The same settings and mappings; the writer may put the two directions in the other order.
bool sameConfig(const BridgeConfig& a, const BridgeConfig& b)
{
    if (!a.sameSettings(b))
        return false;
    for (const Direction d : {Direction::Ros2Mqtt, Direction::Mqtt2Ros}) {
        QList<const Mapping*> ma;
        QList<const Mapping*> mb;
        for (const Mapping& m : a.mappings)
            if (m.direction == d)
                ma.append(&m);
        for (const Mapping& m : b.mappings)
            if (m.direction == d)
                mb.append(&m);
        if (ma.size() != mb.size())
            return false;
        for (qsizetype i = 0; i < ma.size(); ++i)
            if (!ma[i]->sameContent(*mb[i]))
                return false;
    }
    return true;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    if (size == 0)
        return 0;
    const QByteArray text = fuzz::bytes(data, size - 1);
    const uint8_t edit = data[size - 1];

    const ConfigReadResult read = ConfigReader::read(text);
    for (const Problem& p : read.problems)
        FUZZ_CHECK(!p.message.isEmpty(), "a read problem without a message");
    if (!read.parsed)
        return 0;

    ConfigValidator::Options options;
    options.rosHome = QStringLiteral("/nonexistent-ros-home");
    options.fileExists = [](const QString&) { return false; };
    for (const Problem& p : ConfigValidator::validate(read.config, options))
        FUZZ_CHECK(!p.message.isEmpty() && !p.format(QStringLiteral("fuzz.yaml")).isEmpty(),
                   "a validation problem without a message");

    const BridgeConfig wanted = edited(read.config, edit);
    QString whyNot;
    ConfigReadResult readBack;
    if (const std::optional<QByteArray> patched
        = ConfigPatcher::patch(text, read.config, wanted, &whyNot, &readBack)) {
        const ConfigReadResult again = ConfigReader::read(*patched);
        FUZZ_CHECK(again.parsed, "a patched config does not read");
        FUZZ_CHECK(sameConfig(again.config, wanted), "a patched config reads as another config");
    } else {
        FUZZ_CHECK(!whyNot.isEmpty(), "the patcher gave up without saying why");
    }

    for (const ConfigLayout layout : {ConfigLayout::Ros1, ConfigLayout::Ros2, ConfigLayout::MqttBridge}) {
        QStringList notes;
        const QString written = ConfigWriter::write(read.config, layout, &notes);
        const ConfigReadResult again = ConfigReader::read(written.toUtf8());
        FUZZ_CHECK(again.parsed, "a config we wrote does not read");
        // A file with problems may lose what has no place (convert refuses it without --force).
        if (layout == read.config.layout && read.problems.isEmpty() && !read.lossy
            && layout != ConfigLayout::MqttBridge)
            FUZZ_CHECK(sameConfig(again.config, read.config),
                       "a config changes when written in its own layout");
    }
    return 0;
}
