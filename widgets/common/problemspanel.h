// SPDX-License-Identifier: MIT
#pragma once

#include "config/bridgeconfig.h"

#include <QWidget>

class ConfigDocument;
class ProblemModel;
class QLabel;
class QTreeView;

/// The list of validation problems; activating one jumps to the mapping or setting it is about.
class ProblemsPanel : public QWidget
{
    Q_OBJECT
public:
    explicit ProblemsPanel(ConfigDocument* document, QWidget* parent = nullptr);
    ProblemModel* model() const { return m_model; }

signals:
    void mappingProblemActivated(quint64 mappingId, const QString& field);
    void settingsProblemActivated(OptionScope scope, const QString& field);

private:
    ProblemModel* m_model;
    QTreeView* m_view;
    QLabel* m_title;
};
