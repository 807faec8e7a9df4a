// SPDX-License-Identifier: MIT
#include "configdocument.h"

#include "files/atomicfile.h"
#include "base/logging.h"
#include "files/regularfile.h"
#include "yaml/yamllimits.h"
#include "config/configpatcher.h"
#include "config/configreader.h"
#include "config/configwriter.h"

#include <algorithm>
#include <limits>
#include <QFile>
#include <QFileInfo>

using namespace Qt::StringLiterals;

ConfigDocument::ConfigDocument(QObject* parent)
    : QObject(parent)
{
    revalidate();
}

ConfigDocument::LoadResult ConfigDocument::load(const QString& path)
{
    LoadResult result;
    // A regular file (not a FIFO or a device), read no further than a config may go: a file past
    // the limit is said to be so by its size, and only its start is read, to be shown.
    const Result<RegularFile::Opened> opened = RegularFile::open(path, std::numeric_limits<qint64>::max());
    if (!opened) {
        result.unreadable = true;
        result.error = tr("Cannot open %1: %2").arg(path, opened.error().toString());
        return result;
    }
    QFile& file = *opened->file;
    result.fileSize = opened->size;
    if (result.fileSize > YamlLimits::maxBytes) {
        const Problem tooLarge = ConfigReader::tooLarge(result.fileSize);
        result.problems = {tooLarge};
        result.error = tooLarge.format(path);
        result.text = file.read(std::min<qint64>(kShownBytes, opened->size));
        return result;
    }
    const QByteArray text = file.read(std::min<qint64>(opened->size, YamlLimits::maxBytes + 1));
    const ConfigReadResult read = ConfigReader::read(text);
    if (!read.parsed) {
        result.problems = read.problems;
        result.error = read.problems.isEmpty() ? tr("%1 is not a bridge config.").arg(path)
                                               : read.problems.first().format(path);
        result.text = text.left(kShownBytes);
        result.fileSize = std::max<qint64>(result.fileSize, text.size());
        return result;
    }
    emit aboutToReset();
    m_path = QFileInfo(path).absoluteFilePath();
    m_suggestedPath.clear();
    m_text = text;
    m_baseline = read.config;
    m_current = read.config;
    m_layout = read.config.layout;
    m_lossy = read.lossy;
    m_modified = false;
    m_readProblems = read.problems;
    m_readOnly = ReadOnlyView();
    finishReset();
    qCDebug(lcConfig).noquote() << "opened" << m_path << layoutName(m_layout) << m_current.mappings.size()
                                << "mappings," << read.problems.size() << "read problems"
                                << (m_lossy ? "(lossy)" : "");
    result.ok = true;
    return result;
}

void ConfigDocument::openReadOnly(const QString& path, const LoadResult& failed)
{
    emit aboutToReset();
    m_path = QFileInfo(path).absoluteFilePath();
    m_suggestedPath.clear();
    m_text.clear();
    m_baseline = BridgeConfig();
    m_current = BridgeConfig();
    m_layout = ConfigLayout::Ros1;
    m_lossy = false;
    m_modified = false;
    m_readProblems = failed.problems;
    m_readOnly = ReadOnlyView();
    if (failed.problems.isEmpty()) {
        m_readOnly.reason = failed.error;
    } else {
        const Problem& first = failed.problems.first();
        m_readOnly.reason = first.message;
        if (!first.fix.isEmpty())
            m_readOnly.reason += u" ("_s + first.fix + u')';
    }
    if (m_readOnly.reason.isEmpty())
        m_readOnly.reason = tr("The file is not a bridge config.");
    m_readOnly.errorPos = failed.problems.isEmpty() ? TextPos() : failed.problems.first().pos;
    // Shown as text: a cut multi-byte character at the end, or bytes that are not UTF-8, become
    // replacement characters rather than an error.
    m_readOnly.text = QString::fromUtf8(failed.text);
    m_readOnly.fileSize = failed.fileSize;
    m_readOnly.truncated = failed.fileSize > failed.text.size();
    finishReset();
    qCDebug(lcConfig).noquote() << "opened read-only" << m_path << failed.error;
}

ConfigDocument::Snapshot ConfigDocument::snapshot() const
{
    return {m_path,   m_suggestedPath, m_text,     m_baseline,     m_current,
            m_layout, m_lossy,         m_modified, m_readProblems, m_readOnly};
}

void ConfigDocument::restore(const Snapshot& s)
{
    emit aboutToReset();
    m_path = s.path;
    m_suggestedPath = s.suggestedPath;
    m_text = s.text;
    m_baseline = s.baseline;
    m_current = s.current;
    m_layout = s.layout;
    m_lossy = s.lossy;
    m_modified = s.modified;
    m_readProblems = s.readProblems;
    m_readOnly = s.readOnly;
    finishReset();
}

void ConfigDocument::reset(const BridgeConfig& config, const QString& suggestedPath)
{
    emit aboutToReset();
    m_path.clear();
    m_suggestedPath = suggestedPath;
    m_text.clear();
    m_baseline = BridgeConfig();
    m_baseline.layout = config.layout;
    m_current = config;
    m_current.assignIds();
    m_layout = config.layout;
    m_lossy = false;
    m_modified = true;
    m_readProblems.clear();
    m_readOnly = ReadOnlyView();
    finishReset();
}

void ConfigDocument::clear()
{
    reset(BridgeConfig());
    m_modified = false;
    emit modifiedChanged(false);
}

void ConfigDocument::setLayout(ConfigLayout layout)
{
    if (layout == m_layout)
        return;
    m_layout = layout;
    m_current.layout = layout;
    emit layoutChanged(layout);
    changed();
}

void ConfigDocument::setDiscoveryProblems(const QList<Problem>& problems)
{
    if (sameProblems(problems, m_discoveryProblems))
        return;
    m_discoveryProblems = problems;
    listProblems(); // the file's own problems have not changed: not checked again
    emit problemsChanged();
}

void ConfigDocument::setValidationOptions(const ConfigValidator::Options& options)
{
    m_validation = options;
    revalidate();
    emit problemsChanged();
}

QString ConfigDocument::preview(ConfigLayout layout, bool* keepsComments, QStringList* notes) const
{
    if (isReadOnly()) {
        if (keepsComments)
            *keepsComments = true;
        return m_readOnly.text;
    }
    if (!m_text.isEmpty() && layout == m_baseline.layout && !m_lossy) {
        BridgeConfig wanted = m_current;
        wanted.layout = layout;
        if (const auto patched = ConfigPatcher::patch(m_text, m_baseline, wanted)) {
            if (keepsComments)
                *keepsComments = true;
            return QString::fromUtf8(*patched);
        }
    }
    if (keepsComments)
        *keepsComments = m_text.isEmpty();
    return ConfigWriter::write(m_current, layout, notes);
}

ConfigDocument::SaveResult ConfigDocument::save(const QString& path, ConfigLayout layout, bool allowRewrite)
{
    SaveResult result;
    if (isReadOnly()) {
        result.error = tr("%1 is open read-only: %2").arg(QFileInfo(m_path).fileName(), m_readOnly.reason);
        return result;
    }
    BridgeConfig wanted = m_current;
    wanted.layout = layout;
    QByteArray bytes;
    ConfigReadResult written;
    if (!m_text.isEmpty() && layout == m_baseline.layout && !m_lossy) {
        QString why;
        if (const auto patched = ConfigPatcher::patch(m_text, m_baseline, wanted, &why, &written))
            bytes = *patched;
        else
            result.rewriteReason = tr("this edit cannot be made in place (%1)").arg(why);
    } else if (!m_text.isEmpty()) {
        result.rewriteReason = m_lossy ? tr("parts of the file could not be read and would be lost")
                                       : tr("the file is saved in another layout");
    }
    if (bytes.isEmpty()) {
        if (!m_text.isEmpty() && !allowRewrite) {
            result.status = SaveResult::NeedsRewrite;
            return result;
        }
        bytes = ConfigWriter::write(wanted, layout, &result.notes).toUtf8();
        result.rewritten = !m_text.isEmpty();
        written = ConfigReader::read(bytes);
    }
    if (const Status saved = AtomicFile::write(path, bytes); !saved) {
        result.error = saved.error().toString();
        result.status = SaveResult::Failed;
        return result;
    }
    const QString absolute = QFileInfo(path).absoluteFilePath();
    const bool pathChanged = absolute != m_path;
    m_path = absolute;
    m_suggestedPath.clear();
    if (m_layout != layout) {
        m_layout = layout;
        emit layoutChanged(layout);
    }
    adoptSaved(bytes, written);
    if (pathChanged)
        emit filePathChanged(m_path);
    qCDebug(lcConfig).noquote() << "saved" << m_path << layoutName(layout) << bytes.size() << "bytes,"
                                << (result.rewritten ? "rewritten" : "patched in place");
    result.status = SaveResult::Saved;
    return result;
}

// After a save, the written text is the new baseline: read it back and give its mappings the
// ids of the mappings in memory (matched by content), so that undo history and views stay valid.
void ConfigDocument::adoptSaved(const QByteArray& text, const ConfigReadResult& read)
{
    m_text = text;
    m_lossy = false;
    m_readProblems = read.problems;
    BridgeConfig baseline = read.config;
    QList<bool> used(m_current.mappings.size(), false);
    for (Mapping& b : baseline.mappings) {
        for (int i = 0; i < m_current.mappings.size(); ++i) {
            if (!used[i] && m_current.mappings[i].sameContent(b)) {
                used[i] = true;
                b.id = m_current.mappings[i].id;
                m_current.mappings[i].block.source = b.block.source;
                break;
            }
        }
    }
    m_current.broker.source = baseline.broker.source;
    m_current.client.source = baseline.client.source;
    m_current.layout = baseline.layout;
    m_baseline = baseline;
    m_modified = false;
    emit modifiedChanged(false);
    revalidate();
    emit problemsChanged();
}

void ConfigDocument::insertMappings(int row, const QList<Mapping>& mappings)
{
    if (mappings.isEmpty())
        return;
    row = std::clamp(row, 0, mappingCount());
    emit mappingsAboutToBeInserted(row, row + int(mappings.size()) - 1);
    for (int i = 0; i < mappings.size(); ++i) {
        Mapping m = mappings[i];
        if (m.id == 0)
            m.id = Mapping::nextId();
        m_current.mappings.insert(row + i, m);
    }
    emit mappingsInserted();
    changed();
}

void ConfigDocument::removeMappings(const QList<quint64>& ids)
{
    QList<int> rows;
    for (quint64 id : ids) {
        const int row = rowOf(id);
        if (row >= 0)
            rows << row;
    }
    if (rows.isEmpty())
        return;
    std::sort(rows.begin(), rows.end());
    // Remove contiguous runs from the back, so that each signal names rows that still exist.
    int i = int(rows.size()) - 1;
    while (i >= 0) {
        int j = i;
        while (j > 0 && rows[j - 1] == rows[j] - 1)
            --j;
        emit mappingsAboutToBeRemoved(rows[j], rows[i]);
        m_current.mappings.remove(rows[j], rows[i] - rows[j] + 1);
        emit mappingsRemoved();
        i = j - 1;
    }
    changed();
}

void ConfigDocument::replaceMapping(const Mapping& mapping)
{
    const int row = rowOf(mapping.id);
    if (row < 0)
        return;
    Mapping m = mapping;
    if (m.direction != m_current.mappings[row].direction)
        m.block.source = SourceMap(); // a new entry in the other list
    m_current.mappings[row] = m;
    emit mappingChanged(row);
    changed();
}

void ConfigDocument::setBlock(OptionScope scope, const OptionBlock& block)
{
    if (scope != OptionScope::Broker && scope != OptionScope::Client)
        return;
    OptionBlock& target = m_current.block(scope);
    const SourceMap source = target.source;
    target = block;
    target.source = source;
    emit settingsChanged();
    changed();
}

QList<Problem> ConfigDocument::problemsOf(quint64 mappingId) const
{
    QList<Problem> out;
    for (const Problem& p : m_problems) {
        if (p.mappingId == mappingId)
            out << p;
    }
    return out;
}

Severity ConfigDocument::worstSeverity(quint64 mappingId, bool* any) const
{
    const auto it = m_severity.constFind(mappingId);
    if (any)
        *any = it != m_severity.cend();
    return it == m_severity.cend() ? Severity::Info : *it;
}

void ConfigDocument::changed()
{
    bool modified = m_current.layout != m_baseline.layout || !m_current.sameSettings(m_baseline)
        || m_current.mappings.size() != m_baseline.mappings.size();
    for (int i = 0; !modified && i < m_current.mappings.size(); ++i) {
        const Mapping& a = m_current.mappings[i];
        const Mapping& b = m_baseline.mappings[i];
        modified = a.id != b.id || !a.sameContent(b);
    }
    if (m_text.isEmpty() && m_path.isEmpty())
        modified = modified || !m_current.mappings.isEmpty();
    revalidate();
    emit problemsChanged();
    if (modified != m_modified) {
        m_modified = modified;
        emit modifiedChanged(modified);
    }
}

void ConfigDocument::finishReset()
{
    m_discoveryProblems.clear(); // about the mappings that were
    revalidate();
    emit resetDone();
    emit filePathChanged(m_path);
    emit layoutChanged(m_layout);
    emit modifiedChanged(m_modified);
    emit problemsChanged();
}

void ConfigDocument::revalidate()
{
    m_ruleProblems = ConfigValidator::validate(m_current, m_validation);
    listProblems();
}

void ConfigDocument::listProblems()
{
    // Reading problems (structure) stay visible beside the rule checks.
    m_problems = m_readProblems + m_ruleProblems;
    // The lab's findings stay with the mappings they are about until the lab is looked at again.
    for (const Problem& p : std::as_const(m_discoveryProblems))
        if (p.mappingId == 0 || m_current.indexOfMapping(p.mappingId) >= 0)
            m_problems << p;
    m_severity.clear();
    for (const Problem& p : std::as_const(m_problems)) {
        if (p.mappingId == 0)
            continue;
        auto it = m_severity.find(p.mappingId);
        if (it == m_severity.end())
            m_severity.insert(p.mappingId, p.severity);
        else if (int(p.severity) > int(*it))
            *it = p.severity;
    }
}
