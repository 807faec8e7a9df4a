// SPDX-License-Identifier: MIT
#include "yamlvariant.h"

#include "text/exactutf8.h"
#include "yaml/yamlreader.h"

#include <QVariantList>
#include <QVariantMap>
#include <yaml-cpp/yaml.h>

namespace {
QVariant toVariant(const YAML::Node& node)
{
    switch (node.Type()) {
    case YAML::NodeType::Map: {
        QVariantMap map;
        for (const auto& kv : node)
            map.insert(exactUtf8(kv.first.as<std::string>()), toVariant(kv.second));
        return map;
    }
    case YAML::NodeType::Sequence: {
        QVariantList list;
        for (const auto& item : node)
            list.append(toVariant(item));
        return list;
    }
    case YAML::NodeType::Scalar:
        return exactUtf8(node.Scalar());
    default:
        return {};
    }
}
} // namespace

Result<QVariant> YamlVariant::read(const QByteArray& text)
{
    const YamlReader reader;
    const Result<YAML::Node> root = reader.parse(text);
    if (!root)
        return root.error();
    try {
        return toVariant(*root);
    } catch (const YAML::Exception& e) { // a key that is no text
        return reader.errorAt(e.mark, exactUtf8(e.msg));
    }
}
