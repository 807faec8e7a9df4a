// SPDX-License-Identifier: MIT
#include "topicnames.h"

using namespace Qt::StringLiterals;

namespace {
// Names that passed through a decoder which replaced bytes it could not read (U+FFFD), or strings
// with halves of UTF-16 pairs: no broker or master would see the name the user meant.
QString encodingProblem(const QString& text)
{
    for (qsizetype i = 0; i < text.size(); ++i) {
        const QChar c = text[i];
        if (c.unicode() == 0xfffd)
            return TopicNames::tr("it contains U+FFFD, the mark of bytes that were not valid UTF-8");
        if (c.isHighSurrogate() && i + 1 < text.size() && text[i + 1].isLowSurrogate()) {
            ++i;
            continue;
        }
        if (c.isSurrogate())
            return TopicNames::tr("it is not valid Unicode (half of a UTF-16 surrogate pair)");
    }
    return QString();
}
} // namespace

bool TopicNames::isValidRosName(const QString& name, bool strict, QString* why)
{
    auto fail = [why](const QString& reason) {
        if (why)
            *why = reason;
        return false;
    };
    if (name.isEmpty())
        return fail(tr("it is empty"));
    if (const QString bad = encodingProblem(name); !bad.isEmpty())
        return fail(bad);
    const QChar first = name.front();
    if (!(first.isLetter() && first.unicode() < 128) && first != u'/' && first != u'~')
        return fail(tr("it must start with a letter, '/' or '~'"));
    for (int i = 1; i < name.size(); ++i) {
        const QChar c = name[i];
        const bool ok = (c.unicode() < 128 && c.isLetterOrNumber()) || c == u'_' || c == u'/';
        if (!ok)
            return fail(tr("'%1' is not allowed (only letters, digits, '_' and '/')").arg(c));
    }
    if (name.contains(u"//"_s))
        return fail(tr("it contains '//'"));
    if (name.size() > 1 && name.endsWith(u'/'))
        return fail(tr("it ends with '/'"));
    if (name.startsWith(u'~') && name.size() > 1 && name[1] != u'/')
        return fail(tr("'~' must be followed by '/'"));
    if (strict) {
        for (const QString& token : name.split(u'/', Qt::SkipEmptyParts)) {
            if (token != u"~"_s && token.front().isDigit())
                return fail(tr("in ROS 2 a name level must not start with a digit"));
        }
    }
    return true;
}

bool TopicNames::hasWildcard(const QString& topic)
{
    return topic.contains(u'+') || topic.contains(u'#');
}

bool TopicNames::isValidMqttTopic(const QString& topic, bool publish, QString* why)
{
    auto fail = [why](const QString& reason) {
        if (why)
            *why = reason;
        return false;
    };
    if (topic.isEmpty())
        return fail(tr("it is empty"));
    if (topic.contains(QChar(0)))
        return fail(tr("it contains a NUL character"));
    if (const QString bad = encodingProblem(topic); !bad.isEmpty())
        return fail(bad);
    if (topic.toUtf8().size() > 65535)
        return fail(tr("it is longer than 65535 bytes"));
    if (publish && hasWildcard(topic))
        return fail(tr("wildcards are not allowed in a published topic"));
    const QStringList levels = topic.split(u'/');
    for (int i = 0; i < levels.size(); ++i) {
        const QString& level = levels[i];
        if (level.contains(u'#') && (level != u"#"_s || i != levels.size() - 1))
            return fail(tr("'#' must be a whole level and the last one"));
        if (level.contains(u'+') && level != u"+"_s)
            return fail(tr("'+' must be a whole level"));
    }
    return true;
}

bool TopicNames::topicMatches(const QString& filter, const QString& topic)
{
    const QStringList f = filter.split(u'/');
    const QStringList t = topic.split(u'/');
    if (!filter.startsWith(u'$') && topic.startsWith(u'$'))
        return false;
    int i = 0;
    for (; i < f.size(); ++i) {
        if (f[i] == u"#"_s)
            return true;
        if (i >= t.size())
            return false;
        if (f[i] != u"+"_s && f[i] != t[i])
            return false;
    }
    return i == t.size();
}
