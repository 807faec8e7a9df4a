// SPDX-License-Identifier: MIT
#pragma once

#include "base/result.h"
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
    /// Reads them after parser.parse(); an error on a bad value.
    Status read(const QCommandLineParser& parser);

    /// "ROS 2 (ROS_DISTRO=jazzy), domain 0": which graphs were chosen and why, as discover and watch
    /// say it on stderr and the window in its status bar.
    QString choice() const;
    /// What a command says on stderr before it starts: a ROS_DOMAIN_ID that was not taken (when it
    /// would have been used), a ROS_VERSION or ROS_DISTRO that was not understood, then choice().
    QStringList notes() const;
    /// "1" or "2" as the environment says (ROS_VERSION, else a ROS_DISTRO it names), else empty;
    /// `why` gets the variable ("ROS_DISTRO=jazzy"), `warning` a value that was not understood.
    static QString environmentGraphs(QString* why, QString* warning);

    bool ros1 = true;
    bool ros2 = false;
    bool graphsSet = false; ///< --ros was given
    bool graphsFromEnvironment = false; ///< --ros was not given and the environment chose
    QString reason; ///< why: "--ros 2", "ROS_VERSION=2", "ROS_DISTRO=noetic" or "default"
    QString environmentWarning; ///< a ROS_VERSION or ROS_DISTRO that was not understood (ignored)
    bool ros2OptionsSet = false; ///< --ros-domain or --ros-localhost-only was given
    bool domainSet = false; ///< --ros-domain was given
    Ros2Options ros2Options; ///< from the environment, then the options
    QString environmentError; ///< a ROS_DOMAIN_ID that was not taken

private:
    QCommandLineOption m_graphs;
    QCommandLineOption m_domain;
    QCommandLineOption m_localhost;
    QString m_default;
};
