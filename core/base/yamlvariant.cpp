// SPDX-License-Identifier: MIT
#include "yamlvariant.h"

#include "base/exactutf8.h"
#include "base/yamllimits.h"

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

std::optional<QVariant> YamlVariant::parse(const QByteArray& text, QString* error)
{
    try {
        return toVariant(YamlLimits::load(text));
    } catch (const YAML::Exception& e) {
        if (error)
            *error = e.mark.is_null() ? exactUtf8(e.msg)
                                      : tr("line %1, column %2: %3")
                                            .arg(e.mark.line + 1)
                                            .arg(e.mark.column + 1)
                                            .arg(exactUtf8(e.msg));
        return std::nullopt;
    }
}
