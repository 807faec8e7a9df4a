// SPDX-License-Identifier: MIT
#include "topicmime.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QMimeData>

using namespace Qt::StringLiterals;

namespace TopicMime {

QMimeData* encode(const QString& mimeType, const QList<Topic>& topics)
{
    QJsonArray list;
    QStringList names;
    for (const Topic& t : topics) {
        list.append(QJsonObject {{u"name"_s, t.name}, {u"type"_s, t.rosType}});
        names << t.name;
    }
    auto* data = new QMimeData;
    data->setData(mimeType, QJsonDocument(list).toJson(QJsonDocument::Compact));
    data->setText(names.join(u'\n')); // dropped into a text field: the names
    return data;
}

QList<Topic> decode(const QMimeData* data, const QString& mimeType)
{
    QList<Topic> out;
    if (!data || !data->hasFormat(mimeType))
        return out;
    for (const QJsonValue& v : QJsonDocument::fromJson(data->data(mimeType)).array()) {
        const QJsonObject o = v.toObject();
        const QString name = o.value(u"name"_s).toString();
        if (!name.isEmpty())
            out.append({name, o.value(u"type"_s).toString()});
    }
    return out;
}

} // namespace TopicMime
