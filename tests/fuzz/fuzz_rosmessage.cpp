// SPDX-License-Identifier: MIT
// Fuzz target for the ROS 1 message decoder with the definition it decodes by: both come from the
// broker (mqtt_client's type announcement carries the definition, the data topic the bytes).
//
// Input: the type name on the first line, the full definition (with "MSG: pkg/Type" dependencies
// after "===" lines) up to the first NUL byte, then the serialized message. A definition that does
// not parse is an error with a message; one that parses decodes the bytes within the limits or
// says why not, and a decoded value prints and finds its fields without crashing, and encodes
// back (RosMessageEncoder) to bytes with the same values. The same definition and bytes go
// through the ROS 2 dialect and the CDR decoder too (a ROS 2 publisher is as hostile), and what
// decodes comes back through the CDR encoder to the same values.
#include "base/yamlvariant.h"
#include "fuzzcheck.h"
#include "wire/rosmessage.h"
#include "wire/rosmessageencoder.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    const auto [text, payload] = fuzz::splitAtNul(fuzz::bytes(data, size));
    const QString definitionText = QString::fromUtf8(text);
    const qsizetype newline = definitionText.indexOf(u'\n');
    const QString type = newline < 0 ? definitionText : definitionText.left(newline);
    const QString definition = newline < 0 ? QString() : definitionText.mid(newline + 1);

    QString error;
    RosTypeRegistry ros2(RosTypeRegistry::Dialect::Ros2);
    if (ros2.addDefinition(type, definition, &error)) {
        error.clear();
        if (const auto cdr = RosMessageDecoder::decodeCdr(ros2, type, payload, &error)) {
            // and back through the YAML a user edits to CDR (little-endian, as rmw writes it)
            const QStringList lines = cdr->toLines();
            if (const std::optional<QString> yaml = RosMessageEncoder::toYaml(*cdr)) {
                const std::optional<QVariant> tree = YamlVariant::parse(yaml->toUtf8(), &error);
                FUZZ_CHECK(tree.has_value(), "the encoder's YAML of a CDR message does not parse");
                error.clear();
                if (const auto bytes = RosMessageEncoder::encodeCdr(ros2, type, *tree, &error)) {
                    const auto again = RosMessageDecoder::decodeCdr(ros2, type, *bytes, &error);
                    FUZZ_CHECK(again && again->toLines() == lines, "CDR-encoded values decode differently");
                } else {
                    FUZZ_CHECK(!error.isEmpty(), "a CDR value refused without a message");
                }
            }
        } else {
            FUZZ_CHECK(!error.isEmpty(), "a CDR message rejected without a message");
        }
    } else {
        FUZZ_CHECK(!error.isEmpty(), "a ROS 2 definition rejected without a message");
    }
    error.clear();

    RosTypeRegistry registry;
    if (!registry.addDefinition(type, definition, &error)) {
        FUZZ_CHECK(!error.isEmpty(), "a definition rejected without a message");
        return 0;
    }
    (void)registry.fixedSize(type);

    error.clear();
    const std::optional<RosValue> value = RosMessageDecoder::decode(registry, type, payload, &error);
    if (!value) {
        FUZZ_CHECK(!error.isEmpty(), "a message rejected without a message");
        return 0;
    }
    const QStringList lines = value->toLines();
    (void)lines;
    for (const RosValue& child : value->children) // find() takes dotted paths: "a.b" is two levels
        if (!child.name.contains(u'.'))
            FUZZ_CHECK(value->find(child.name) != nullptr, "a decoded field that find() does not find");

    // What decodes whole comes back through the YAML a user edits: the encoder takes it, or
    // says why not (a time past 2106 after normalizing), and its bytes decode to the same values.
    if (const std::optional<QString> yaml = RosMessageEncoder::toYaml(*value)) {
        const std::optional<QVariant> tree = YamlVariant::parse(yaml->toUtf8(), &error);
        FUZZ_CHECK(tree.has_value(), "the encoder's YAML does not parse");
        error.clear();
        if (const auto bytes = RosMessageEncoder::encode(registry, type, *tree, &error)) {
            const auto again = RosMessageDecoder::decode(registry, type, *bytes, &error);
            FUZZ_CHECK(again && again->toLines() == lines, "encoded values decode differently");
        } else {
            FUZZ_CHECK(!error.isEmpty(), "a value refused without a message");
        }
    }

    // Tight limits take the other branches (cut strings and arrays, shallow nesting).
    RosDecodeLimits tight;
    tight.maxArrayElements = 1;
    tight.maxStringChars = 2;
    tight.maxDepth = 2;
    (void)RosMessageDecoder::decode(registry, type, payload, &error, tight);
    return 0;
}
