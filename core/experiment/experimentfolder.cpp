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

Result<QList<CellStatus>> ExperimentFolder::readState(const ExperimentPlan& plan) const
{
    const Result<QByteArray> bytes = RegularFile::readHead(statePath(), kMaxStateBytes);
    if (!bytes)
        return LocatedError {tr("%1: %2").arg(statePath(), bytes.error().toString())};
    Result<QList<CellStatus>> statuses = ExperimentState::parse(*bytes, plan);
    if (!statuses)
        return LocatedError {tr("%1: %2").arg(statePath(), statuses.error().toString())};
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
