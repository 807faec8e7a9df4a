// SPDX-License-Identifier: MIT
#include "fieldpath.h"

#include "wire/rosmessage.h"

#include <QJsonArray>
#include <QJsonObject>

using namespace Qt::StringLiterals;

namespace {
/// The index of "[i]", or -1 for a name.
int indexOf(const QString& part)
{
    if (!part.startsWith(u'[') || !part.endsWith(u']'))
        return -1;
    bool ok = false;
    const int i = part.mid(1, part.size() - 2).toInt(&ok);
    return ok && i >= 0 ? i : -1;
}
} // namespace

QString FieldPath::text(const QStringList& parts)
{
    QString out;
    for (const QString& p : parts)
        out += (out.isEmpty() || indexOf(p) >= 0 ? QString() : u"."_s) + p;
    return out;
}

int FieldPath::maxIndex(const QStringList& parts)
{
    int top = -1;
    for (const QString& p : parts)
        top = std::max(top, indexOf(p));
    return top;
}

bool FieldPath::isNumericType(const QString& type)
{
    return type != u"string"_s
        && (RosTypeRegistry::isBuiltin(type) || type == u"number"_s || type == u"bool"_s);
}

Result<double> FieldPath::number(const RosValue& message, const QStringList& parts)
{
    const RosValue* node = &message;
    for (const QString& part : parts) {
        const RosValue* next = nullptr;
        for (const RosValue& c : node->children) {
            if (c.name == part) {
                next = &c;
                break;
            }
        }
        if (!next)
            return LocatedError {tr("no field %1").arg(text(parts))};
        node = next;
    }
    if (node->kind != RosValue::Scalar || !isNumericType(node->type))
        return LocatedError {tr("%1 is no number").arg(text(parts))};
    if (node->type == u"bool"_s)
        return node->value.toBool() ? 1.0 : 0.0;
    bool ok = false;
    const double d = node->value.typeId() == QMetaType::QString
        ? node->value.toString().toDouble(&ok) // times
        : node->value.toDouble(&ok);
    if (!ok)
        return LocatedError {tr("%1 is no number").arg(text(parts))};
    return d;
}

Result<double> FieldPath::number(const QJsonValue& document, const QStringList& parts)
{
    QJsonValue v = document;
    for (const QString& part : parts) {
        const int i = indexOf(part);
        if (i >= 0 && v.isArray())
            v = v.toArray().at(i);
        else if (v.isObject())
            v = v.toObject().value(part);
        else
            v = QJsonValue(QJsonValue::Undefined);
        if (v.isUndefined())
            return LocatedError {tr("no field %1").arg(text(parts))};
    }
    if (v.isBool())
        return v.toBool() ? 1.0 : 0.0;
    if (v.isDouble())
        return v.toDouble();
    return LocatedError {tr("%1 is no number").arg(text(parts))};
}
