// SPDX-License-Identifier: MIT
#include "pipeline.h"

#include "files/atomicfile.h"
#include "yaml/yamlreader.h"
#include "yaml/yamltree.h"

#include <QFile>
#include <yaml-cpp/yaml.h>

using namespace Qt::StringLiterals;

namespace {
/// Pipelines name the line of an error, not its column.
const YamlReader kReader(LocatedError::Style::Line);

/// A double-quoted YAML scalar: control characters escaped, so that a line break in a name
/// cannot be folded into a space (or end the scalar) when the file is read back.
QString quoted(const QString& s)
{
    QString out;
    out.reserve(s.size() + 2);
    out += u'"';
    for (const QChar c : s) {
        if (c == u'\\' || c == u'"') {
            out += u'\\';
            out += c;
        } else if (YamlText::mustEscape(c)) {
            out += u"\\u%1"_s.arg(uint(c.unicode()), 4, 16, QChar(u'0'));
        } else {
            out += c;
        }
    }
    out += u'"';
    return out;
}

/// The first control character in a name (a line break, a tab, NUL, ...), or -1. No ROS name has
/// one and MQTT asks clients not to use them; in a pipeline file one is nearly always a folded
/// line or a stray escape.
qsizetype controlCharacter(const QString& s)
{
    for (qsizetype i = 0; i < s.size(); ++i)
        if (s[i].unicode() < 0x20 || s[i].unicode() == 0x7f)
            return i;
    return -1;
}
} // namespace

Pipeline::Pipeline(QStringList topics, int window)
    : m_window(window)
{
    setTopics(std::move(topics));
}

QString Pipeline::normalized(QStringView topic)
{
    while (topic.startsWith(u'/'))
        topic = topic.mid(1);
    return topic.toString();
}

void Pipeline::setTopics(QStringList topics)
{
    m_topics.clear();
    m_index.clear();
    for (QString& t : topics) {
        const QString key = normalized(t);
        if (t.isEmpty() || m_index.contains(key))
            continue;
        m_index.insert(key, int(m_topics.size()));
        m_index.insert(u'/' + key, int(m_topics.size())); // the ROS spelling: found without a copy
        m_topics.append(std::move(t));
    }
    m_labels = PipelineLabels(m_topics);
}

int Pipeline::indexOf(const QString& topic) const
{
    // Both spellings are keys: the common case costs one hash lookup and no allocation.
    const auto it = m_index.constFind(topic);
    if (it != m_index.cend())
        return *it;
    return topic.startsWith(u"//") ? indexOf(QStringView(topic)) : -1;
}

int Pipeline::indexOf(QStringView topic) const
{
    QStringView t = topic;
    while (t.startsWith(u'/'))
        t = t.mid(1);
    return m_index.value(t.toString(), -1);
}

Result<Pipeline> Pipeline::read(const QByteArray& yaml)
{
    const Result<YAML::Node> parsed = kReader.parse(yaml);
    if (!parsed)
        return parsed.error();
    const YAML::Node& root = *parsed;
    if (!root.IsMap())
        return kReader.error(tr("a pipeline is a mapping with topics_in_order"));
    const YAML::Node topics = root["topics_in_order"];
    if (!topics || !topics.IsSequence())
        return kReader.error(tr("topics_in_order is missing or not a list"));
    QStringList names;
    for (const YAML::Node& t : topics) {
        if (!t.IsScalar() || t.Scalar().empty())
            return kReader.errorAt(t, tr("every entry of topics_in_order must be a topic name"));
        // Qt drops a leading byte-order mark when decoding: the topic would change (found by
        // fuzz_pipeline).
        if (t.Scalar().rfind("\xef\xbb\xbf", 0) == 0)
            return kReader.errorAt(t, tr("a topic starts with a byte-order mark (U+FEFF)"));
        names << QString::fromStdString(t.Scalar());
        if (const qsizetype at = controlCharacter(names.last()); at >= 0)
            return kReader.errorAt(t,
                                   tr("the topic %1 holds the control character U+%2 at %3")
                                       .arg(quoted(names.last()),
                                            u"%1"_s.arg(uint(names.last()[at].unicode()), 4, 16, QChar(u'0')),
                                            QString::number(at + 1)));
    }
    if (names.isEmpty())
        return kReader.error(tr("topics_in_order is empty"));
    Pipeline p(names);
    if (const Status s = p.readSettings(root); !s)
        return s.error();
    return p;
}

Status Pipeline::readSettings(const YAML::Node& root)
{
    if (const YAML::Node w = root["metrics_window"]) {
        int window = 0;
        if (!w.IsScalar() || !YAML::convert<int>::decode(w, window) || window < 0)
            return kReader.errorAt(w, tr("metrics_window must be a whole number of samples (0: whole run)"));
        m_window = window;
    }
    if (const YAML::Node one = root["one_clock"]) {
        bool oneClock = false;
        if (!one.IsScalar() || !YAML::convert<bool>::decode(one, oneClock))
            return kReader.errorAt(one, tr("one_clock is true or false"));
        m_oneClock = oneClock;
    }
    if (const YAML::Node hosts = root["hosts"]) {
        if (!hosts.IsMap())
            return kReader.errorAt(hosts, tr("hosts must map topics to host names"));
        for (const auto& kv : hosts) {
            const QString topic = YamlReader::text(kv.first);
            if (!kv.second.IsScalar())
                return kReader.errorAt(kv.second, tr("the host of %1 must be a name").arg(topic));
            if (indexOf(topic) < 0)
                return kReader.errorAt(kv.first,
                                       tr("hosts names %1, which is not in topics_in_order").arg(topic));
            const QString host = QString::fromStdString(kv.second.Scalar());
            if (controlCharacter(host) >= 0)
                return kReader.errorAt(kv.second, tr("the host of %1 holds a control character").arg(topic));
            setHost(topic, host);
        }
    }
    return {};
}

Result<Pipeline> Pipeline::readFile(const QString& path)
{
    return YamlReader::readFileWith(path, &Pipeline::read);
}

QByteArray Pipeline::toYaml() const
{
    QString out = u"metrics_window: %1\n"_s.arg(m_window);
    if (m_oneClock)
        out += u"one_clock: true\n"_s;
    out += u"topics_in_order:\n"_s;
    for (const QString& t : m_topics)
        out += u"  - "_s + quoted(t) + u'\n';
    if (hasHosts()) {
        out += u"hosts:\n"_s;
        for (const QString& t : m_topics) {
            const QString h = m_hosts.value(t);
            if (!h.isEmpty())
                out += u"  "_s + quoted(t) + u": "_s + quoted(h) + u'\n';
        }
    }
    return out.toUtf8();
}

Status Pipeline::save(const QString& path) const
{
    return AtomicFile::write(path, toYaml());
}

QString Pipeline::host(int topicIndex) const
{
    if (topicIndex < 0 || topicIndex >= m_topics.size())
        return {};
    return m_hosts.value(m_topics[topicIndex]);
}

void Pipeline::setHost(const QString& topic, const QString& host)
{
    const int i = indexOf(topic);
    if (i < 0)
        return;
    if (host.trimmed().isEmpty())
        m_hosts.remove(m_topics[i]);
    else
        m_hosts.insert(m_topics[i], host.trimmed());
}

bool Pipeline::hasHosts() const
{
    for (const QString& t : m_topics)
        if (!m_hosts.value(t).isEmpty())
            return true;
    return false;
}

bool Pipeline::isCrossing(int stage) const
{
    const QString a = host(stage);
    const QString b = host(stage + 1);
    return !a.isEmpty() && !b.isEmpty() && a != b;
}

QList<int> Pipeline::crossings() const
{
    QList<int> out;
    for (int s = 0; s < stageCount(); ++s)
        if (isCrossing(s))
            out << s;
    return out;
}

std::optional<std::pair<int, int>> Pipeline::outAndReturnCrossings() const
{
    const QList<int> c = crossings();
    if (c.size() != 2)
        return std::nullopt;
    const QString home = host(c[0]);
    const QString away = host(c[0] + 1);
    if (host(c[1]) != away || host(c[1] + 1) != home)
        return std::nullopt;
    return std::make_pair(c[0], c[1]);
}

QString Pipeline::stageLabel(int stage) const
{
    return m_labels.stageLabel(stage);
}

QString Pipeline::component(int topicIndex) const
{
    return m_labels.component(topicIndex);
}
