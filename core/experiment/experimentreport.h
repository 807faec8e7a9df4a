// SPDX-License-Identifier: MIT
#pragma once

#include "experiment/experimentrunner.h"
#include "latency/latencystats.h"

#include <optional>
#include <QCoreApplication>
#include <QStringList>

/// An experiment folder as the paper's kind of tables: for each factor a table with its levels as
/// columns and the stage groups as rows (the MQTT interfaces, the crossings between hosts, each
/// other component such as the detection, local hand-overs, the total), a cell table that traces
/// every figure to its run, and findings.
///
/// A group's value per sample is the sum of its stages in that sample (so its statistics are
/// exact, not sums of means); a level's column pools the samples of every complete cell at that
/// level, which for a one-factor plan is that cell's run alone.
class ExperimentReport
{
    Q_DECLARE_TR_FUNCTIONS(ExperimentReport)
public:
    enum class Statistic { Mean, Median, Std, P99 };
    struct Group
    {
        QString label; ///< "interfaces", "vehicle ↔ cloud", "object_detection", "transfers", "total"
        QList<int> stages; ///< empty for the total (first to last stamp)
        bool total = false;
    };
    struct Cell
    {
        ExperimentCell cell;
        CellStatus status;
        QList<LatencyStats> groups; ///< per group (empty when the run could not be read)
        QString problem; ///< why its run was left out
    };
    struct Column
    {
        QString level;
        QList<int> cells; ///< complete cells at this level
        QList<LatencyStats> groups;
    };
    struct FactorTable
    {
        QString factor;
        QList<Column> columns;
    };

    /// Reads DIR (its plan copy, state and runs); nullopt with `error` when it is no experiment.
    static std::optional<ExperimentReport> load(const QString& directory, QString* error);
    /// Whether `path` is an experiment's folder.
    static bool isExperiment(const QString& path);

    const ExperimentPlan& plan() const { return m_plan; }
    const QList<Group>& groups() const { return m_groups; }
    const QList<Cell>& cells() const { return m_cells; }
    const QList<FactorTable>& tables() const { return m_tables; }
    const QList<ThroughputResult>& throughput() const { return m_throughput; }
    QStringList findings() const;

    static std::optional<QList<Statistic>> parseStatistics(const QString& list, QString* error);
    static QString statisticName(Statistic s);
    static double value(const LatencyStats& s, Statistic statistic);

    QString toMarkdown(const QList<Statistic>& statistics) const;
    QString toTex(const QList<Statistic>& statistics) const;
    QString toHtml(const QList<Statistic>& statistics) const;
    QByteArray toJson() const;
    QString toCsv() const; ///< one row per cell and group: every statistic

private:
    ExperimentPlan m_plan;
    QString m_dir;
    QList<Group> m_groups;
    QList<Cell> m_cells;
    QList<FactorTable> m_tables;
    QList<ThroughputResult> m_throughput;
};
