// SPDX-License-Identifier: MIT
// The Experiments page's files: plans opened and saved, folders opened, reports exported.
#include "widgets/experiment/experimentpage.h"

#include "files/atomicfile.h"
#include "files/regularfile.h"
#include "yaml/yamllimits.h"

#include <QComboBox>
#include <QDir>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QMessageBox>

using namespace Qt::StringLiterals;

Status ExperimentPage::openPlan(const QString& path)
{
    QByteArray text;
    if (const Result<ExperimentPlan> plan = ExperimentPlan::readFile(path, &text); !plan && text.isEmpty())
        return plan.error();
    // A plan with an error opens too: the editor is where it gets fixed. Path and folder first,
    // so that the plan is checked, and its folder's state and report read, once.
    m_planPath = path;
    if (folder().isEmpty())
        m_folder->setText(
            QDir::toNativeSeparators(QFileInfo(path).dir().filePath(QFileInfo(path).completeBaseName())));
    setPlanText(QString::fromUtf8(text));
    return {};
}

Status ExperimentPage::openFolder(const QString& directory)
{
    if (!ExperimentReport::isExperiment(directory))
        return LocatedError {tr("%1 is not an experiment's folder (it has no %2)")
                                 .arg(directory, ExperimentFolder::stateFileName())};
    m_folder->setText(QDir::toNativeSeparators(directory));
    return openPlan(ExperimentFolder(directory).planPath());
}

Status ExperimentPage::exportReport(const QString& path, const QString& format)
{
    if (!m_report)
        return LocatedError {tr("There is no report yet.")};
    const QString kind = format.isEmpty() ? QFileInfo(path).suffix().toLower() : format;
    const QList<ExperimentReport::Statistic> statistics {
        ExperimentReport::Statistic(m_statistic->currentData().toInt())};
    ReportFormats::Format f;
    if (!ReportFormats::parse(kind == u"htm"_s ? u"html"_s : kind, &f))
        return LocatedError {tr("Unknown report format '%1' (md, html, tex, csv, json, pdf).").arg(kind)};
    if (const Result<QByteArray> exported = m_report->exportTo(path, f, statistics); !exported)
        return exported.error();
    return {};
}

void ExperimentPage::chooseExport()
{
    const QString suggestion = QDir(folder()).filePath(u"report.pdf"_s);
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Export Report"), suggestion,
        tr("PDF (*.pdf);;Markdown (*.md);;HTML (*.html);;LaTeX (*.tex);;CSV (*.csv);;JSON (*.json)"));
    if (path.isEmpty())
        return;
    if (const Status exported = exportReport(path); !exported)
        QMessageBox::warning(this, tr("Export Report"), exported.error().toString());
    else
        m_status->setText(tr("Report written to %1").arg(QDir::toNativeSeparators(path)));
}

void ExperimentPage::chooseFolder()
{
    const QString dir = QFileDialog::getExistingDirectory(this, tr("Experiment Folder"), folder());
    if (!dir.isEmpty())
        setFolder(dir);
}

void ExperimentPage::choosePlan()
{
    const QString path = QFileDialog::getOpenFileName(this, tr("Open Plan"), QFileInfo(m_planPath).path(),
                                                      tr("Experiment plans (*.yaml *.yml);;All files (*)"));
    if (path.isEmpty())
        return;
    if (const Status opened = openPlan(path); !opened)
        QMessageBox::warning(this, tr("Open Plan"), opened.error().toString());
}

void ExperimentPage::savePlanAs()
{
    const QString path = QFileDialog::getSaveFileName(this, tr("Save Plan"), m_planPath,
                                                      tr("Experiment plans (*.yaml *.yml)"));
    if (path.isEmpty())
        return;
    if (const Status written = AtomicFile::write(path, planText().toUtf8()); !written)
        QMessageBox::warning(this, tr("Save Plan"), written.error().toString());
    else
        setPlanPath(path);
}

void ExperimentPage::loadExample(int index)
{
    const QString path = m_examples->itemData(index).toString();
    m_examples->setCurrentIndex(0);
    if (path.isEmpty())
        return;
    const Result<QByteArray> text = RegularFile::readHead(path, YamlLimits::maxBytes + 1);
    if (!text)
        return;
    setPlanText(QString::fromUtf8(*text));
    m_planPath.clear(); // an example is saved into the folder when it runs
    m_planEdited = true;
    const QString name = QFileInfo(path).completeBaseName();
    setFolder(QDir::home().filePath(u"bridgescope-experiments/"_s + name));
}
