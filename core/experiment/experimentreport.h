// SPDX-License-Identifier: MIT
#pragma once

#include "experiment/experimentstate.h"
#include "experiment/throughputresult.h"
#include "latency/latencyseries.h"
#include "latency/rundata.h"
#include "latency/latencystats.h"
#include "latency/shiftestimate.h"
#include "report/reportformats.h"

#include <memory>
#include <optional>
#include <vector>
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
        QList<LatencyStats> stages; ///< per stage of the pipeline (the Table I layout)
        std::shared_ptr<const LatencySeries> total; ///< every sample's total, ns (null: not read)
        QString problem; ///< why its run was left out
    };
    struct Column
    {
        QString level;
        QList<int> cells; ///< complete cells at this level
        QList<LatencyStats> groups;
        std::shared_ptr<const LatencySeries> total; ///< the pooled totals, ns, for the ECDF
    };
    struct FactorTable
    {
        QString factor;
        QList<Column> columns;
    };

    /// Reads DIR (its plan copy, state and runs); an error when it is no experiment, or when
    /// `progress` cancels (it is asked while each run is read).
    static Result<ExperimentReport> load(const QString& directory, const Progress& progress = {});
    /// Whether `path` is an experiment's folder.
    static bool isExperiment(const QString& path);

    const ExperimentPlan& plan() const { return m_plan; }
    const QList<Group>& groups() const { return m_groups; }
    const QList<Cell>& cells() const { return m_cells; }
    const QList<FactorTable>& tables() const { return m_tables; }
    const QList<ThroughputResult>& throughput() const { return m_throughput; }
    /// The pipeline's stage labels (of the first complete cell's run).
    const QStringList& stageLabels() const { return m_stageLabels; }
    /// A method comparison (the plan varies the bridge): the report adds the paper's Table I
    /// layout, every stage a row and every complete cell a column.
    bool hasMethodTable() const;
    /// What the report found (ExperimentFindings::of): failed and unfinished cells, throughput, and
    /// per factor the levels with the lowest and the highest total mean, with the shift of their
    /// totals and its 95 % interval (ShiftEstimate); "no significant difference" when it holds zero.
    QStringList findings() const;
    /// The totals' ECDFs of factor table `table`, one curve per level (SVG, as the run reports').
    QByteArray ecdfSvg(int table, int width = 720, int height = 400) const;
    /// Where toMarkdown() links the ECDF of `factor` when given `figurePrefix` ("out/report"):
    /// "out/report-qos-ecdf.svg".
    static QString figurePath(const QString& figurePrefix, const QString& factor);

    static Result<QList<Statistic>> parseStatistics(const QString& list);
    static QString statisticName(Statistic s);
    static double value(const LatencyStats& s, Statistic statistic);
    /// A figure in ms as the tables show it ("12.3", "0.45"; "–" for none).
    static QString formatMs(double v);
    /// A cell's levels: "qos=1, payload=25%".
    static QString levelsText(const ExperimentCell& cell);
    /// Which ROS the cells ran on: "ROS 1", "ROS 2 (DDS, a private domain)".
    QString rosText() const;

    /// With `figurePrefix`, each factor's ECDF is linked as figurePath(figurePrefix, factor)
    /// (relative to the Markdown file: by its file name); the caller writes the SVGs.
    QString toMarkdown(const QList<Statistic>& statistics, const QString& figurePrefix = QString()) const;
    QString toTex(const QList<Statistic>& statistics) const;
    /// One page; `figures`: each factor's ECDF inline as SVG (browsers), or none (Qt rich text).
    QString toHtml(const QList<Statistic>& statistics, bool figures = true) const;
    /// A4: the HTML's tables, then every factor's ECDF. Needs a QGuiApplication.
    QByteArray toPdf(const QList<Statistic>& statistics) const;

    /// The report in `format` (md, tex, html, pdf, csv, json); Markdown links its figures under
    /// `figurePrefix` when one is given (see writeFigures()).
    QByteArray render(ReportFormats::Format format, const QList<Statistic>& statistics,
                      const QString& figurePrefix = QString()) const;
    /// The one export of a report, for the command and the page alike: the report in `format`
    /// written to `path` atomically (empty `path`: the bytes are only returned), Markdown with its
    /// figures beside it (figurePrefixOf(path)). An error when a file cannot be written.
    Result<QByteArray> exportTo(const QString& path, ReportFormats::Format format,
                                const QList<Statistic>& statistics) const;
    /// Writes every factor's ECDF as figurePath(figurePrefix, factor), each atomically.
    Status writeFigures(const QString& figurePrefix) const;
    /// The prefix of the figures beside a report file: "out/report.md" → "out/report".
    static QString figurePrefixOf(const QString& reportPath);
    QByteArray toJson() const;
    QString toCsv() const; ///< one row per cell and group: every statistic

private:
    /// A table per factor: its levels in the order the cells have them, each pooling the values
    /// (per cell and group, ns) of its complete cells.
    void buildTables(const std::vector<std::vector<LatencySeries>>& values);
    ExperimentPlan m_plan;
    QString m_dir;
    QList<Group> m_groups;
    QList<Cell> m_cells;
    QList<FactorTable> m_tables;
    QList<ThroughputResult> m_throughput;
    QStringList m_stageLabels;
};
