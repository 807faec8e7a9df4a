// SPDX-License-Identifier: MIT
#include "secrets.h"

#include "yaml/yamllimits.h"

#include <QRegularExpression>
#include <QStringList>
#include <sstream>
#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/parser.h>
#include <yaml-cpp/yaml.h>

using namespace Qt::StringLiterals;

namespace Secrets {
namespace {

/// Replaces every scalar below `node` that is a value (not null, not a launch argument).
void redactAll(YAML::Node node, int depth, bool* changed)
{
    if (depth > YamlLimits::maxDepth)
        return;
    if (node.IsScalar()) {
        const std::string& v = node.Scalar();
        if (v.empty() || v.rfind("$(arg", 0) == 0 || v == kRedacted)
            return;
        node = std::string(kRedacted);
        *changed = true;
    } else if (node.IsSequence()) {
        for (YAML::Node item : node)
            redactAll(item, depth + 1, changed);
    } else if (node.IsMap()) {
        for (auto kv : node)
            redactAll(kv.second, depth + 1, changed);
    }
}

/// Walks the parsed tree: the value of every key that names a secret is redacted. An alias is the
/// node its anchor names (yaml-cpp shares it), so a secret reached through one is redacted where
/// it is defined too.
void redactTree(YAML::Node node, int depth, bool* changed)
{
    if (depth > YamlLimits::maxDepth)
        return;
    if (node.IsSequence()) {
        for (YAML::Node item : node)
            redactTree(item, depth + 1, changed);
    } else if (node.IsMap()) {
        for (auto kv : node) {
            YAML::Node key = kv.first;
            YAML::Node value = kv.second;
            if (key.IsScalar() && isSecretKey(QString::fromStdString(key.Scalar())))
                redactAll(value, depth + 1, changed);
            else
                redactTree(value, depth + 1, changed);
            redactTree(key, depth + 1, changed); // a complex key: a map may be a key
        }
    }
}

/// Events only: linear in the text, aliases not expanded.
class NoHandler : public YAML::EventHandler
{
public:
    void OnDocumentStart(const YAML::Mark&) override { }
    void OnDocumentEnd() override { }
    void OnNull(const YAML::Mark&, YAML::anchor_t) override { }
    void OnAlias(const YAML::Mark&, YAML::anchor_t) override { }
    void OnScalar(const YAML::Mark&, const std::string&, YAML::anchor_t, const std::string&) override { }
    void OnSequenceStart(const YAML::Mark&, const std::string&, YAML::anchor_t,
                         YAML::EmitterStyle::value) override
    { }
    void OnSequenceEnd() override { }
    void OnMapStart(const YAML::Mark&, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override
    { }
    void OnMapEnd() override { }
};

/// Whether `yaml` holds one document at most (YAML::Load reads only the first).
bool isSingleDocument(const QByteArray& yaml)
{
    std::istringstream in(yaml.toStdString());
    YAML::Parser parser(in);
    NoHandler none;
    try {
        return !parser.HandleNextDocument(none) || !parser.HandleNextDocument(none);
    } catch (const YAML::Exception&) {
        return false;
    }
}

qsizetype userInfoEnd(const QString& url, qsizetype start)
{
    // MQTT over TCP and TLS has no path, query or fragment: there every '/', '?', '#' and '@'
    // before the last '@' belongs to the user info (a password typed unencoded). Other schemes
    // (ws, http) keep the rule of URLs: the authority ends at the first '/', '?' or '#'.
    const QString scheme = url.left(start - 3).toLower();
    static const QStringList pathless {u"tcp"_s, u"ssl"_s, u"mqtt"_s, u"mqtts"_s};
    qsizetype end = url.size();
    if (!pathless.contains(scheme)) {
        for (const QChar c : {u'/', u'?', u'#'}) {
            const qsizetype i = url.indexOf(c, start);
            if (i >= 0 && i < end)
                end = i;
        }
    }
    return end > start ? url.lastIndexOf(u'@', end - 1) : -1;
}
} // namespace

bool isSecretKey(const QString& key)
{
    static const QRegularExpression secret(
        u"(?<![A-Za-z0-9])(?:[A-Za-z0-9]+_)*(?:pass|passwd|password|passphrase|secret|token|api_key)$"_s,
        QRegularExpression::CaseInsensitiveOption);
    return secret.match(key).hasMatch();
}

QString urlWithoutCredentials(const QString& url)
{
    const qsizetype scheme = url.indexOf(u"://"_s);
    if (scheme < 0)
        return url;
    // Done by hand: QUrl rejects some URLs that a user still types and expects to work.
    const qsizetype start = scheme + 3;
    const qsizetype at = userInfoEnd(url, start);
    if (at < start)
        return url;
    return url.left(start) + url.mid(at + 1);
}

QString redactedUrl(const QString& url)
{
    const qsizetype scheme = url.indexOf(u"://"_s);
    const qsizetype at = url.lastIndexOf(u'@');
    if (scheme < 0 || at < scheme + 3)
        return url;
    return url.left(scheme + 3) + QLatin1StringView(kRedacted) + url.mid(at);
}

QByteArray redactYaml(const QByteArray& yaml, bool* changed, bool* parsed)
{
    bool any = false;
    bool ok = true;
    YAML::Node root;
    try {
        root = YamlLimits::load(yaml);
    } catch (const YAML::Exception&) {
        ok = false;
    }
    QByteArray out = yaml;
    if (ok) {
        redactTree(root, 0, &any);
        if (any || !isSingleDocument(yaml)) {
            // Written anew from the tree: only what the parser saw, the first document alone.
            YAML::Emitter e;
            e << root;
            ok = e.good();
            out = ok ? QByteArray(e.c_str(), qsizetype(e.size())) + '\n' : QByteArray();
            any = true; // a later document may have held a secret as well
        }
    }
    if (!ok) {
        // Nothing of a text whose secrets cannot be found is kept, only why.
        out = QByteArray("# ") + kNotYaml + '\n';
        any = true;
    }
    if (changed)
        *changed = any;
    if (parsed)
        *parsed = ok;
    return out;
}

} // namespace Secrets
