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
#include "yaml/yamlvariant.h"
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

    RosTypeRegistry ros2(RosTypeRegistry::Dialect::Ros2);
    if (const Result<void> added = ros2.addDefinition(type, definition); added) {
        if (const Result<RosValue> cdr = RosMessageDecoder::decodeCdr(ros2, type, payload); cdr) {
            // and back through the YAML a user edits to CDR (little-endian, as rmw writes it)
            const QStringList lines = cdr->toLines();
            if (const std::optional<QString> yaml = RosMessageEncoder::toYaml(*cdr)) {
                const Result<QVariant> tree = YamlVariant::read(yaml->toUtf8());
                FUZZ_CHECK(tree.ok(), "the encoder's YAML of a CDR message does not parse");
                if (const Result<QByteArray> bytes = RosMessageEncoder::encodeCdr(ros2, type, *tree); bytes) {
                    const Result<RosValue> again = RosMessageDecoder::decodeCdr(ros2, type, *bytes);
                    FUZZ_CHECK(again && again->toLines() == lines, "CDR-encoded values decode differently");
                } else {
                    FUZZ_CHECK(!bytes.error().toString().isEmpty(), "a CDR value refused without a message");
                }
            }
        } else {
            FUZZ_CHECK(!cdr.error().toString().isEmpty(), "a CDR message rejected without a message");
        }
    } else {
        FUZZ_CHECK(!added.error().toString().isEmpty(), "a ROS 2 definition rejected without a message");
    }

    RosTypeRegistry registry;
    if (const Result<void> added = registry.addDefinition(type, definition); !added) {
        FUZZ_CHECK(!added.error().toString().isEmpty(), "a definition rejected without a message");
        return 0;
    }
    (void)registry.fixedSize(type);

    const Result<RosValue> value = RosMessageDecoder::decode(registry, type, payload);
    if (!value) {
        FUZZ_CHECK(!value.error().toString().isEmpty(), "a message rejected without a message");
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
        const Result<QVariant> tree = YamlVariant::read(yaml->toUtf8());
        FUZZ_CHECK(tree.ok(), "the encoder's YAML does not parse");
        if (const Result<QByteArray> bytes = RosMessageEncoder::encode(registry, type, *tree); bytes) {
            const Result<RosValue> again = RosMessageDecoder::decode(registry, type, *bytes);
            FUZZ_CHECK(again && again->toLines() == lines, "encoded values decode differently");
        } else {
            FUZZ_CHECK(!bytes.error().toString().isEmpty(), "a value refused without a message");
        }
    }

    // Tight limits take the other branches (cut strings and arrays, shallow nesting).
    RosDecodeLimits tight;
    tight.maxArrayElements = 1;
    tight.maxStringChars = 2;
    tight.maxDepth = 2;
    (void)RosMessageDecoder::decode(registry, type, payload, tight);
    return 0;
}
