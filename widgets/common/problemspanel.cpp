// SPDX-License-Identifier: MIT
#include "problemspanel.h"

#include "config/configdocument.h"
#include "config/mqttclientrelease.h"
#include "config/problemmodel.h"
#include "widgets/common/severityiconproxy.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QSettings>
#include <QTreeView>
#include <QVBoxLayout>

using namespace Qt::StringLiterals;

namespace {
/// "RELEASE\tPATH" per file, the newest choice first.
constexpr auto kTargetsKey = "map/releaseTargets";
} // namespace

std::optional<MqttClientRelease> ProblemsPanel::savedTarget(const QString& filePath)
{
    if (filePath.isEmpty())
        return std::nullopt;
    const QStringList list = QSettings().value(QLatin1String(kTargetsKey)).toStringList();
    for (const QString& entry : list) {
        const qsizetype tab = entry.indexOf(u'\t');
        if (tab > 0 && QStringView(entry).mid(tab + 1) == filePath)
            return MqttClientReleases::fromName(entry.left(tab)); // a name no release has: auto
    }
    return std::nullopt;
}

void ProblemsPanel::saveTarget(const QString& filePath, std::optional<MqttClientRelease> release)
{
    if (filePath.isEmpty())
        return;
    QSettings settings;
    QStringList list = settings.value(QLatin1String(kTargetsKey)).toStringList();
    list.removeIf([&](const QString& entry) {
        const qsizetype tab = entry.indexOf(u'\t');
        return tab < 0 || QStringView(entry).mid(tab + 1) == filePath;
    });
    if (release)
        list.prepend(MqttClientReleases::name(*release) + u'\t' + filePath);
    while (list.size() > kMaxSavedTargets)
        list.removeLast();
    settings.setValue(QLatin1String(kTargetsKey), list);
}

ProblemsPanel::ProblemsPanel(ConfigDocument* document, QWidget* parent)
    : QWidget(parent)
    , m_doc(document)
    , m_model(new ProblemModel(document, this))
{
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    m_title = new QLabel(this);
    layout->addWidget(m_title);
    // On a row of its own: the panel stays as narrow as the inspector beside it needs.
    auto* target = new QHBoxLayout;
    m_release = new QComboBox(this);
    m_release->setObjectName(u"targetRelease"_s);
    m_release->addItem(tr("auto"), QString());
    for (const QString& name : MqttClientReleases::names())
        m_release->addItem(name, name);
    m_releaseLabel = new QLabel(tr("Tar&get: mqtt_client"), this);
    m_releaseLabel->setBuddy(m_release);
    target->addWidget(m_releaseLabel);
    target->addWidget(m_release);
    target->addStretch(1);
    layout->addLayout(target);
    m_view = new QTreeView(this);
    m_view->setObjectName(QStringLiteral("problemsView"));
    m_view->setRootIsDecorated(false);
    m_view->setUniformRowHeights(true);
    m_view->setAlternatingRowColors(true);
    auto* proxy = new SeverityIconProxy(ProblemModel::SeverityRole, this);
    proxy->setSourceModel(m_model);
    m_view->setModel(proxy);
    m_view->header()->setStretchLastSection(false);
    m_view->header()->setSectionResizeMode(ProblemModel::MessageColumn, QHeaderView::Stretch);
    m_view->header()->setSectionResizeMode(ProblemModel::LocationColumn, QHeaderView::ResizeToContents);
    layout->addWidget(m_view);
    m_title->setBuddy(m_view);

    auto updateTitle = [this](int errors, int warnings) {
        m_title->setText(tr("&Problems: %1").arg(ProblemModel::countText(errors, warnings)));
    };
    connect(m_model, &ProblemModel::countsChanged, this, updateTitle);
    updateTitle(m_model->errorCount(), m_model->warningCount());
    adoptSavedTarget();
    connect(document, &ConfigDocument::resetDone, this, &ProblemsPanel::adoptSavedTarget);
    connect(document, &ConfigDocument::filePathChanged, this, [this](const QString& path) {
        if (path == m_path)
            return; // a file opened: resetDone came first
        // Saved under another name: the choice goes with the file.
        m_path = path;
        saveTarget(path, m_doc->validationOptions().target);
    });
    connect(document, &ConfigDocument::problemsChanged, this, &ProblemsPanel::updateReleaseNote);
    connect(m_release, &QComboBox::activated, this, [this] {
        // The user's choice, for this file from now on (a file not saved yet keeps it while open).
        const auto chosen = MqttClientReleases::fromName(m_release->currentData().toString());
        saveTarget(m_doc->filePath(), chosen);
        ConfigValidator::Options options = m_doc->validationOptions();
        options.target = chosen;
        m_doc->setValidationOptions(options);
    });
    connect(m_view, &QTreeView::activated, this, [this](const QModelIndex& index) {
        const auto id = index.data(ProblemModel::MappingIdRole).value<quint64>();
        const QString field = index.data(ProblemModel::FieldRole).toString();
        if (id)
            emit mappingProblemActivated(id, field);
        else
            emit settingsProblemActivated(OptionScope(index.data(ProblemModel::ScopeRole).toInt()), field);
    });
}

void ProblemsPanel::adoptSavedTarget()
{
    m_path = m_doc->filePath();
    const std::optional<MqttClientRelease> saved = savedTarget(m_path);
    m_release->setCurrentIndex(saved ? m_release->findData(MqttClientReleases::name(*saved)) : 0);
    ConfigValidator::Options options = m_doc->validationOptions();
    if (options.target != saved) {
        options.target = saved;
        m_doc->setValidationOptions(options);
    }
    updateReleaseNote();
}

void ProblemsPanel::updateReleaseNote()
{
    // Which releases load the file, and why: on the choice itself, where it is looked at.
    const QString summary = MqttClientReleases::summary(m_doc->config(), m_doc->validationOptions().target);
    const QString help = tr("The mqtt_client release the config is checked against. Keys it does not "
                            "read are flagged with the release that brings them; auto is the newest "
                            "release that loads the layout. The choice is kept for this file.");
    m_release->setToolTip(summary + u"\n\n"_s + help);
    m_releaseLabel->setToolTip(m_release->toolTip());
}
