// SPDX-License-Identifier: MIT
#include "experimentfolder.h"

#include "base/regularfile.h"
#include "experiment/experimentrunner.h"

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
        const QJsonObject o = v.toObject();
        ThroughputResult r;
        r.payloadBytes = o.value(u"payload_bytes"_s).toInt();
        r.level = o.value(u"level"_s).toString().left(256);
        r.complete = o.value(u"complete"_s).toBool();
        for (const QJsonValue& pv : o.value(u"rates"_s).toArray()) {
            const QJsonObject po = pv.toObject();
            ThroughputPoint p;
            p.rateHz = po.value(u"rate_hz"_s).toDouble();
            p.samples = po.value(u"samples"_s).toInteger();
            p.expected = po.value(u"expected"_s).toInteger();
            p.dropped = po.value(u"dropped"_s).toInteger();
            p.p50Ms = po.value(u"p50_ms"_s).toDouble();
            p.p99Ms = po.value(u"p99_ms"_s).toDouble();
            p.sustainable = po.value(u"sustainable"_s).toBool();
            if (r.points.size() < 1000)
                r.points << p;
        }
        if (results.size() < ExperimentPlan::kMaxCells)
            results << r;
    }
    return results;
}
