// SPDX-License-Identifier: MIT
#pragma once

#include "config/bridgeconfig.h"

#include <optional>
#include <QWidget>

class ConfigDocument;
class ProblemModel;
class QComboBox;
class QLabel;
class QTreeView;
enum class MqttClientRelease;

/// The list of validation problems; activating one jumps to the mapping or setting it is about.
/// Above it, the mqtt_client release the file is checked against (issue 45): chosen per file and
/// kept in the settings for the next session, "auto" (the newest release that loads the layout)
/// until one is chosen.
class ProblemsPanel : public QWidget
{
    Q_OBJECT
public:
    explicit ProblemsPanel(ConfigDocument* document, QWidget* parent = nullptr);
    ProblemModel* model() const { return m_model; }

    /// The release chosen for a file in an earlier session, or none (auto).
    static std::optional<MqttClientRelease> savedTarget(const QString& filePath);
    /// Keeps (or, with none, forgets) the release chosen for a file; the newest kMaxSavedTargets
    /// files are kept.
    static void saveTarget(const QString& filePath, std::optional<MqttClientRelease> release);
    static constexpr int kMaxSavedTargets = 200;

signals:
    void mappingProblemActivated(quint64 mappingId, const QString& field);
    void settingsProblemActivated(OptionScope scope, const QString& field);

private:
    /// The document's file changed: its saved release, or auto.
    void adoptSavedTarget();
    void updateReleaseNote();

    ConfigDocument* m_doc;
    ProblemModel* m_model;
    QComboBox* m_release;
    QLabel* m_releaseLabel;
    QString m_path; ///< the file whose choice is shown
    QTreeView* m_view;
    QLabel* m_title;
};
