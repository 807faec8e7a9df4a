// SPDX-License-Identifier: MIT
#pragma once

#include "ros2/ros2participant.h"

#include <QCommandLineOption>
#include <QCommandLineParser>
#include <QCoreApplication>

/// The command-line options that choose the ROS graphs (`--ros 1|2|both`, `--ros-domain ID`,
/// `--ros-localhost-only`), the same for the window, discover and watch.
class RosOptions
{
    Q_DECLARE_TR_FUNCTIONS(RosOptions)
public:
    /// `defaultGraphs` is what --ros means when it is not given: "1", "2" or "both".
    explicit RosOptions(const QString& defaultGraphs = QStringLiteral("1"));
    void addTo(QCommandLineParser& parser) const;
    /// Reads them after parser.parse(); false with `error` on a bad value.
    bool read(const QCommandLineParser& parser, QString* error);

    bool ros1 = true;
    bool ros2 = false;
    bool graphsSet = false; ///< --ros was given
    bool ros2OptionsSet = false; ///< --ros-domain or --ros-localhost-only was given
    Ros2Options ros2Options; ///< from the environment, then the options
    QString environmentError; ///< a ROS_DOMAIN_ID that was not taken

private:
    QCommandLineOption m_graphs;
    QCommandLineOption m_domain;
    QCommandLineOption m_localhost;
    QString m_default;
};
