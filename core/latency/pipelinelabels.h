// SPDX-License-Identifier: MIT
#pragma once

#include <QCoreApplication>
#include <QString>
#include <QStringList>

/// How a pipeline's topics and stages are named for people: without the prefix all topics share,
/// a stage between components by the components ("mqtt_interface_vehicle → mqtt_interface_cloud"),
/// one within a component by its topics ("mqtt_interface_vehicle/pointcloud (in → out)"), and the
/// long form wherever the short one would name two stages alike. Computed once, in one pass over
/// the topics (Pipeline keeps one per topic list).
class PipelineLabels
{
    Q_DECLARE_TR_FUNCTIONS(PipelineLabels)
public:
    PipelineLabels() = default;
    explicit PipelineLabels(const QStringList& topics);

    /// The label of stage i (stamp i to stamp i+1); empty when there is no such stage.
    QString stageLabel(int stage) const { return m_stageLabels.value(stage); }
    /// The stage's two topics without their common prefix.
    QString longStageLabel(int stage) const;
    /// The first name part after the common prefix ("mqtt_interface_vehicle").
    QString component(int topicIndex) const;
    /// The topic without the prefix all topics share.
    QString shortTopic(int topicIndex) const;

private:
    QStringList m_topics;
    qsizetype m_prefix = 0; ///< length of the prefix all topics share, up to a '/'
    QStringList m_stageLabels;
};
