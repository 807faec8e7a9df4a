// SPDX-License-Identifier: MIT
#pragma once

#include "base/result.h"

#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <QByteArray>
#include <QCoreApplication>
#include <QList>
#include <QString>

namespace YAML {
class Node;
}

/// The two levels at which a figure of a link raises a warning and an alert (NaN: not checked).
struct Threshold
{
    double warning = std::numeric_limits<double>::quiet_NaN();
    double alert = std::numeric_limits<double>::quiet_NaN();
    bool isSet() const { return !std::isnan(warning) || !std::isnan(alert); }
};

/// What a link is held to.
struct LinkRules
{
    enum Setting {
        LatencyP99Ms, ///< latency p99 above
        MinRateHz, ///< destination rate below
        MinRatePercent, ///< destination rate below this share of the source's
        MaxLossPercent, ///< messages lost above
        StallSeconds, ///< destination silent this long while the source publishes
        StallPeriods, ///< ... or this many of the source's periods, when StallSeconds is not set
        SourceStoppedSeconds, ///< source silent this long after it published (the link is idle, not stalled)
        SettingCount
    };
    std::array<Threshold, SettingCount> thresholds;

    const Threshold& operator[](Setting s) const { return thresholds[std::size_t(s)]; }
    Threshold& operator[](Setting s) { return thresholds[std::size_t(s)]; }
    /// The key of a setting in the rules YAML, e.g. "latency_p99_ms".
    static QString key(Setting s);
    static std::optional<Setting> settingOf(const QString& key);
    /// Bridgescope's defaults: stall after 5 periods (alert), source stopped after 5 periods or 3 s
    /// (warning), loss above 1 % (warning) and 5 % (alert), rate below 50 % of the source (alert).
    static LinkRules defaults();
};

/// What identifies a link to the rules: its topics, its bridge's client id and its config's name.
struct LinkKey
{
    QString rosTopic;
    QString mqttTopic;
    QString client;
    QString config;
};

/// The rules YAML of `bridgescope watch --rules` and the Links page:
///
///     defaults:                      # every link
///       latency_p99_ms: {warning: 50, alert: 200}
///       max_loss_percent: 5          # a plain number is the alert level
///     links:                         # later entries win
///       - match: "/vehicle/*"        # glob on the ROS or MQTT topic; "client:ID", "config:NAME"
///         stall_seconds: 2
///
/// A file is bounded (besides YamlLimits): at most kMaxLinkRules entries in links, each pattern at most
/// kMaxPatternChars. A glob is matched without a regular expression: nothing to compile, and the work
/// of one match is bounded by the pattern's and the name's length.
class WatchRules
{
    Q_DECLARE_TR_FUNCTIONS(WatchRules)
public:
    static constexpr int kMaxLinkRules = 2000;
    static constexpr qsizetype kMaxPatternChars = 512;

    struct Override
    {
        QString match;
        QList<std::pair<LinkRules::Setting, Threshold>> settings;
    };

    LinkRules defaults = LinkRules::defaults();
    QList<Override> overrides;

    /// Parses the YAML (bounded by YamlLimits); the error is located at its line ("line 3: …").
    static Result<WatchRules> read(const QByteArray& yaml);
    static Result<WatchRules> readFile(const QString& path);
    QByteArray toYaml() const;
    /// The defaults with every matching override applied in order.
    LinkRules forLink(const LinkKey& key) const;
    /// Whether the glob `pattern` matches the link; `steps` (when given) grows by the steps the
    /// match took, at most |pattern| × |name|.
    static bool matches(const QString& pattern, const LinkKey& key, qint64* steps = nullptr);

private:
    static Status readOverrides(const YAML::Node& links, QList<Override>* out);
};
