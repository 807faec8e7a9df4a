// SPDX-License-Identifier: MIT
#pragma once

#include "config/bridgeconfig.h"
#include "config/configreader.h"
#include "config/configvalidator.h"
#include "config/problem.h"

#include <QObject>

/// An open bridge config: the file it came from, its edits, and its problems.
///
/// Views and undo commands change it only through the edit functions below; each emits
/// fine-grained signals (rows about to be inserted/removed, one row changed) so that models can
/// forward them without resetting. Saving edits the original text in place where possible, so
/// comments survive (see ConfigPatcher).
class ConfigDocument : public QObject
{
    Q_OBJECT
public:
    explicit ConfigDocument(QObject* parent = nullptr);

    struct LoadResult
    {
        bool ok = false;
        bool unreadable = false; ///< the file could not be read at all (as opposed to invalid)
        QString error; ///< why it could not be opened
        QList<Problem> problems; ///< syntax/structure problems when !ok
        /// When the file was read but is no config (or too large): its first bytes, at most
        /// kShownBytes, to be looked at read-only (openReadOnly()).
        QByteArray text;
        qint64 fileSize = 0;
    };
    /// What a file that cannot be edited shows of itself: at most this much of its text.
    static constexpr qsizetype kShownBytes = 1024 * 1024;
    /// A file opened only to be read: why, where the error is, and as much of its text as is shown.
    struct ReadOnlyView
    {
        QString reason; ///< the error that keeps it from being edited; empty: not read-only
        TextPos errorPos;
        QString text; ///< the file's first kShownBytes
        qint64 fileSize = 0;
        bool truncated = false; ///< the text is the file's first part only
    };
    struct SaveResult
    {
        enum Status { Saved, NeedsRewrite, Failed };
        Status status = Failed;
        QString error; ///< when Failed
        QString rewriteReason; ///< when NeedsRewrite: why comments cannot be kept
        bool rewritten = false; ///< when Saved: the whole file was written anew
        QStringList notes; ///< what the layout could not express
    };

    /// Everything an open config is, so that several can take turns in one document (the Map
    /// page's tabs): the file, its text, its edits, and whether they are saved.
    struct Snapshot
    {
        QString path;
        QString suggestedPath;
        QByteArray text;
        BridgeConfig baseline;
        BridgeConfig current;
        ConfigLayout layout = ConfigLayout::Ros1;
        bool lossy = false;
        bool modified = false;
        QList<Problem> readProblems;
        ReadOnlyView readOnly;
    };
    Snapshot snapshot() const;
    /// Becomes `s` again, as a load would (resetDone and the rest are emitted).
    void restore(const Snapshot& s);

    LoadResult load(const QString& path);
    /// Shows a file that load() could read but not take (`failed`): its text, read-only, with
    /// its error; nothing can be edited or saved (a broken or too large file is fixed elsewhere).
    void openReadOnly(const QString& path, const LoadResult& failed);
    bool isReadOnly() const { return !m_readOnly.reason.isEmpty(); }
    const ReadOnlyView& readOnlyView() const { return m_readOnly; }
    /// Replaces the document by `config` (no file), e.g. a generated peer config.
    void reset(const BridgeConfig& config, const QString& suggestedPath = QString());
    void clear();
    /// Saves to `path` in `layout`. Without `allowRewrite`, a save that cannot keep the file's
    /// comments stops with NeedsRewrite so that the user can be asked first.
    SaveResult save(const QString& path, ConfigLayout layout, bool allowRewrite);
    /// What a save in `layout` would write now, and whether the file's comments would be kept.
    QString preview(ConfigLayout layout, bool* keepsComments = nullptr, QStringList* notes = nullptr) const;

    const BridgeConfig& config() const { return m_current; }
    const Mapping& mapping(int row) const { return m_current.mappings.at(row); }
    int mappingCount() const { return int(m_current.mappings.size()); }
    int rowOf(quint64 id) const { return m_current.indexOfMapping(id); }
    QString filePath() const { return m_path; }
    QString suggestedPath() const { return m_suggestedPath; }
    ConfigLayout layout() const { return m_layout; }
    void setLayout(ConfigLayout layout);
    bool isModified() const { return m_modified; }
    bool hasFileText() const { return !m_text.isEmpty(); }
    const QList<Problem>& problems() const { return m_problems; }
    QList<Problem> problemsOf(quint64 mappingId) const;
    Severity worstSeverity(quint64 mappingId, bool* any) const;
    void setValidationOptions(const ConfigValidator::Options& options);
    const ConfigValidator::Options& validationOptions() const { return m_validation; }
    /// Problems only the running lab shows (DiscoveryLints), listed after the file's own; they go
    /// with the document's reset. Emits problemsChanged only when they differ from the last ones.
    void setDiscoveryProblems(const QList<Problem>& problems);
    const QList<Problem>& discoveryProblems() const { return m_discoveryProblems; }

    // Edits (each one emits its signals and revalidates).
    void insertMappings(int row, const QList<Mapping>& mappings);
    void removeMappings(const QList<quint64>& ids);
    void replaceMapping(const Mapping& mapping);
    void setBlock(OptionScope scope, const OptionBlock& block);

signals:
    void aboutToReset();
    void resetDone();
    void mappingsAboutToBeInserted(int first, int last);
    void mappingsInserted();
    void mappingsAboutToBeRemoved(int first, int last);
    void mappingsRemoved();
    void mappingChanged(int row);
    void settingsChanged();
    void problemsChanged();
    void modifiedChanged(bool modified);
    void filePathChanged(const QString& path);
    void layoutChanged(ConfigLayout layout);

private:
    void changed();
    void revalidate();
    /// m_problems and the worst severity per mapping from the read, rule and lab problems.
    void listProblems();
    /// After the state was replaced whole: checks it and says everything changed.
    void finishReset();
    void adoptSaved(const QByteArray& text, const ConfigReadResult& read);

    QString m_path;
    QString m_suggestedPath;
    QByteArray m_text; ///< the file as last read or written
    BridgeConfig m_baseline; ///< what m_text reads as
    BridgeConfig m_current;
    ConfigLayout m_layout = ConfigLayout::Ros1;
    bool m_lossy = false;
    bool m_modified = false;
    QList<Problem> m_readProblems; ///< structure problems found when the file was read
    ReadOnlyView m_readOnly;
    QList<Problem> m_problems;
    QList<Problem> m_ruleProblems; ///< ConfigValidator's, as of the last revalidate()
    QList<Problem> m_discoveryProblems; ///< DiscoveryLints' of the running lab
    QHash<quint64, Severity> m_severity;
    ConfigValidator::Options m_validation;
};
