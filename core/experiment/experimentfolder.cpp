// SPDX-License-Identifier: MIT
#include "experimentfolder.h"

#include "files/regularfile.h"
#include "experiment/experimentplan.h"
#include "experiment/throughputresult.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

using namespace Qt::StringLiterals;

namespace {
constexpr qsizetype kMaxStateBytes = ExperimentState::kMaxBytes;
} // namespace

bool ExperimentFolder::isExperiment(const QString& path)
{
    return QFileInfo(path).isDir() && QFile::exists(QDir(path).filePath(stateFileName()));
}

QString ExperimentFolder::filePath(const QString& relative) const
{
    return QDir(m_path).filePath(relative);
}

std::optional<QList<CellStatus>> ExperimentFolder::readState(const ExperimentPlan& plan, QString* error) const
{
    QString why;
    const std::optional<QByteArray> bytes = RegularFile::readHead(statePath(), kMaxStateBytes, &why);
    std::optional<QList<CellStatus>> statuses
        = bytes ? ExperimentState::parse(*bytes, plan, &why) : std::nullopt;
    if (!statuses && error)
        *error = tr("%1: %2").arg(statePath(), why);
    return statuses;
}

QList<ThroughputResult> ExperimentFolder::readThroughput() const
{
    QList<ThroughputResult> results;
    const QJsonArray sizes = QJsonDocument::fromJson(RegularFile::head(throughputPath(), kMaxStateBytes))
                                 .object()
                                 .value(u"sizes"_s)
                                 .toArray();
    for (const QJsonValue& v : sizes) {
        const ThroughputResult r = ThroughputResult::fromJson(v.toObject());
        if (results.size() < ExperimentPlan::kMaxCells)
            results << r;
    }
    return results;
}
