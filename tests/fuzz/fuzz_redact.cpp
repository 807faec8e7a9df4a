// SPDX-License-Identifier: MIT
// Fuzz target for the redaction of bridge configs before a run file stores them
// (Secrets::redactYaml): whatever the YAML says and however it says it (quotes, escapes, continued
// lines, complex keys, anchors and aliases, several documents), no value under a key that names a
// secret survives.
//
// Properties: a text that parses comes out as YAML whose every secret key holds "<redacted>", an
// empty value or a launch argument, aliases resolved; a text that does not parse comes out as the
// one comment that says so; redacting again changes nothing.
#include "yaml/secrets.h"
#include "yaml/yamllimits.h"
#include "fuzzcheck.h"

#include <yaml-cpp/yaml.h>

namespace {

/// Every scalar below `node` is redacted, empty or a launch argument.
bool allRedacted(const YAML::Node& node, int depth)
{
    if (depth > YamlLimits::maxDepth)
        return true;
    if (node.IsScalar()) {
        const std::string& v = node.Scalar();
        return v.empty() || v == Secrets::kRedacted || v.rfind("$(arg", 0) == 0;
    }
    if (node.IsSequence())
        for (const YAML::Node& item : node)
            if (!allRedacted(item, depth + 1))
                return false;
    if (node.IsMap())
        for (const auto& kv : node)
            if (!allRedacted(kv.second, depth + 1))
                return false;
    return true;
}

/// No secret key below `node` holds a value.
bool noSecretLeft(const YAML::Node& node, int depth)
{
    if (depth > YamlLimits::maxDepth)
        return true;
    if (node.IsSequence())
        for (const YAML::Node& item : node)
            if (!noSecretLeft(item, depth + 1))
                return false;
    if (node.IsMap())
        for (const auto& kv : node) {
            if (kv.first.IsScalar() && Secrets::isSecretKey(QString::fromStdString(kv.first.Scalar()))
                && !allRedacted(kv.second, depth + 1))
                return false;
            if (!noSecretLeft(kv.first, depth + 1) || !noSecretLeft(kv.second, depth + 1))
                return false;
        }
    return true;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    const QByteArray text = fuzz::bytes(data, size);
    bool changed = false;
    bool parsed = false;
    const QByteArray out = Secrets::redactYaml(text, &changed, &parsed);
    if (!parsed) {
        FUZZ_CHECK(changed && out == QByteArray("# ") + Secrets::kNotYaml + '\n',
                   "an unparsed text is kept, not replaced by the note");
        return 0;
    }
    YAML::Node tree;
    try {
        tree = YamlLimits::load(out);
    } catch (const YAML::Exception&) {
        FUZZ_CHECK(false, "a redacted text does not parse");
    }
    FUZZ_CHECK(noSecretLeft(tree, 0), "a secret key keeps its value");
    bool again = true;
    FUZZ_CHECK(Secrets::redactYaml(out, &again) == out, "redacting twice changes the text");
    FUZZ_CHECK(!again || !changed || out.startsWith('#'), "a redacted text still holds a secret");
    return 0;
}
