// SPDX-License-Identifier: MIT
#include "reportspage.h"

#include "files/atomicfile.h"
#include "record/runfile.h"
#include "report/report.h"
#include "report/runloader.h"
#include "widgets/common/droppedfiles.h"

#include <algorithm>
#include <QCheckBox>
#include <QComboBox>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QEventLoop>
#include <QFileDialog>
#include <QFileInfo>
#include <QFontDatabase>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMessageBox>
#include <QMimeData>
#include <QPainter>
#include <QPlainTextEdit>
#include <QProgressBar>
#include <QProgressDialog>
#include <QPushButton>
#include <QSpinBox>
#include <QSplitter>
#include <QStackedWidget>
#include <QSvgRenderer>
#include <QTextBrowser>
#include <QTimer>
#include <QVBoxLayout>

using namespace Qt::StringLiterals;

ReportsPage::ReportsPage(QWidget* parent)
    : QWidget(parent)
    , m_inputs(new QListWidget(this))
    , m_format(new QComboBox(this))
    , m_pipeline(new QLineEdit(this))
    , m_window(new QSpinBox(this))
    , m_join(new QCheckBox(tr("&Join the inputs into one run"), this))
    , m_perSample(new QCheckBox(tr("CSV: stage latencies in ms, one row per sample"), this))
    , m_title(new QLineEdit(this))
    , m_previewStack(new QStackedWidget(this))
    , m_text(new QPlainTextEdit(this))
    , m_rich(new QTextBrowser(this))
    , m_progress(new QProgressBar(this))
    , m_status(new QLabel(this))
    , m_debounce(new QTimer(this))
{
    setObjectName(u"reportsPage"_s);
    m_join->setObjectName(u"joinBox"_s);
    setAcceptDrops(true); // files dropped anywhere on the page are added
    auto* split = new QSplitter(Qt::Horizontal, this);
    split->addWidget(createSettingsPane());
    split->addWidget(createPreviewPane());
    split->setStretchFactor(0, 2);
    split->setStretchFactor(1, 5);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(split);

    // Any change of a field computes the preview again, once the typing pauses.
    m_debounce->setSingleShot(true);
    m_debounce->setInterval(300);
    connect(m_debounce, &QTimer::timeout, this, &ReportsPage::startPreview);
    connect(m_format, &QComboBox::currentIndexChanged, this, &ReportsPage::schedulePreview);
    connect(m_pipeline, &QLineEdit::textChanged, this, &ReportsPage::schedulePreview);
    connect(m_window, &QSpinBox::valueChanged, this, &ReportsPage::schedulePreview);
    connect(m_join, &QCheckBox::toggled, this, &ReportsPage::schedulePreview);
    connect(m_perSample, &QCheckBox::toggled, this, &ReportsPage::schedulePreview);
    connect(m_title, &QLineEdit::textChanged, this, &ReportsPage::schedulePreview);
    m_status->setText(tr("Add runs, suite CSV files or bags to report on."));
}

/// The inputs with their buttons, the report's fields and the export button.
QWidget* ReportsPage::createSettingsPane()
{
    auto* pane = new QWidget(this);
    auto* layout = new QVBoxLayout(pane);
    layout->setContentsMargins(0, 0, 0, 0);
    auto* inputsLabel = new QLabel(tr("&Inputs:"), pane);
    inputsLabel->setBuddy(m_inputs);
    layout->addWidget(inputsLabel);
    layout->addWidget(m_inputs, 1);
    layout->addLayout(createInputButtons());
    layout->addLayout(createForm());

    auto* exportButton = new QPushButton(tr("&Export…"), this);
    exportButton->setDefault(true);
    exportButton->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_E));
    exportButton->setToolTip(tr("Write the report to a file (Ctrl+E)"));
    connect(exportButton, &QPushButton::clicked, this, &ReportsPage::chooseExport);
    layout->addWidget(exportButton);
    return pane;
}

QLayout* ReportsPage::createInputButtons()
{
    m_inputs->setObjectName(u"reportInputs"_s);
    m_inputs->setSelectionMode(QAbstractItemView::ExtendedSelection);
    m_inputs->setToolTip(
        tr("Runs, suite timestamp CSV files and ROS bags; several are compared side by side"));
    auto* del = new QAction(this);
    del->setShortcut(QKeySequence::Delete);
    del->setShortcutContext(Qt::WidgetShortcut);
    m_inputs->addAction(del);
    connect(del, &QAction::triggered, this, &ReportsPage::removeSelected);

    auto* add = new QPushButton(tr("&Add…"), this);
    auto* remove = new QPushButton(tr("&Remove"), this);
    auto* up = new QPushButton(tr("&Up"), this);
    auto* down = new QPushButton(tr("Do&wn"), this);
    connect(add, &QPushButton::clicked, this, &ReportsPage::chooseInputs);
    connect(remove, &QPushButton::clicked, this, &ReportsPage::removeSelected);
    connect(up, &QPushButton::clicked, this, [this] { moveSelected(-1); });
    connect(down, &QPushButton::clicked, this, [this] { moveSelected(+1); });
    auto* buttons = new QHBoxLayout;
    for (QPushButton* b : {add, remove, up, down})
        buttons->addWidget(b);
    buttons->addStretch();
    return buttons;
}

QLayout* ReportsPage::createForm()
{
    for (const ReportFormats::Entry& f : ReportFormats::formats())
        m_format->addItem(f.title, int(f.format));
    m_pipeline->setPlaceholderText(tr("optional; otherwise each input's own pipeline"));
    m_pipeline->setClearButtonEnabled(true);
    m_window->setRange(0, 100'000'000);
    m_window->setSpecialValueText(tr("whole run"));
    m_window->setSuffix(tr(" samples"));
    m_title->setPlaceholderText(tr("from the run names"));

    auto* browsePipeline = new QPushButton(tr("&Browse…"), this);
    connect(browsePipeline, &QPushButton::clicked, this, &ReportsPage::choosePipeline);
    auto* pipelineRow = new QHBoxLayout;
    pipelineRow->addWidget(m_pipeline, 1);
    pipelineRow->addWidget(browsePipeline);
    auto* form = new QFormLayout;
    form->addRow(tr("&Format:"), m_format);
    auto* pipelineLabel = new QLabel(tr("&Pipeline:"), this); // its buddy is the field, not the row
    pipelineLabel->setBuddy(m_pipeline);
    form->addRow(pipelineLabel, pipelineRow);
    form->addRow(tr("W&indow:"), m_window);
    form->addRow(tr("&Title:"), m_title);
    form->addRow(QString(), m_join);
    form->addRow(QString(), m_perSample);
    return form;
}

/// The status with the progress of a running report, above the preview (text or rich).
QWidget* ReportsPage::createPreviewPane()
{
    m_text->setReadOnly(true);
    m_text->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    m_text->setLineWrapMode(QPlainTextEdit::NoWrap);
    m_text->setObjectName(u"reportText"_s);
    m_rich->setObjectName(u"reportRich"_s);
    m_previewStack->addWidget(m_text);
    m_previewStack->addWidget(m_rich);
    m_progress->setRange(0, 100);
    m_progress->setVisible(false);
    m_progress->setMaximumWidth(200);

    auto* pane = new QWidget(this);
    auto* layout = new QVBoxLayout(pane);
    layout->setContentsMargins(0, 0, 0, 0);
    auto* statusRow = new QHBoxLayout;
    statusRow->addWidget(m_status, 1);
    statusRow->addWidget(m_progress);
    layout->addLayout(statusRow);
    layout->addWidget(m_previewStack, 1);
    return pane;
}

ReportsPage::~ReportsPage() = default; // a running job cancels and waits for its worker

void ReportsPage::addInputs(const QStringList& paths)
{
    for (const QString& p : paths) {
        if (p.isEmpty() || inputs().contains(p))
            continue;
        auto* item = new QListWidgetItem(QFileInfo(p).fileName(), m_inputs);
        item->setData(Qt::UserRole, p);
        item->setToolTip(p);
    }
    schedulePreview();
}

QStringList ReportsPage::inputs() const
{
    QStringList out;
    for (int i = 0; i < m_inputs->count(); ++i)
        out << m_inputs->item(i)->data(Qt::UserRole).toString();
    return out;
}

void ReportsPage::setFormat(ReportFormats::Format format)
{
    m_format->setCurrentIndex(m_format->findData(int(format)));
}

ReportFormats::Format ReportsPage::format() const
{
    return ReportFormats::Format(m_format->currentData().toInt());
}

void ReportsPage::setPipelineFile(const QString& path)
{
    m_pipeline->setText(path);
}

bool ReportsPage::isBusy() const
{
    return m_job != nullptr || m_debounce->isActive();
}

QString ReportsPage::previewText() const
{
    return m_preview;
}

Result<ReportJob::Request> ReportsPage::request() const
{
    ReportJob::Request r;
    r.inputs = inputs();
    if (!m_pipeline->text().trimmed().isEmpty()) {
        Result<Pipeline> pipeline = Pipeline::readFile(m_pipeline->text().trimmed());
        if (!pipeline)
            return pipeline.error();
        r.pipeline = std::move(pipeline).value();
    }
    r.options.window = m_window->value();
    r.options.join = m_join->isChecked();
    r.options.skipBadRows = true; // the preview says what was skipped rather than refusing
    r.options.title = m_title->text().trimmed();
    return r;
}

Result<QByteArray> ReportsPage::render(const Report& report, ReportFormats::Format format) const
{
    if (format == ReportFormats::Format::Csv && report.isComparison()) {
        // The page names its own checkbox, not the command line's --join.
        return LocatedError {tr("a CSV file holds a single run: give one input, or tick “%1”")
                                 .arg(QString(m_join->text()).remove(u'&'))};
    }
    return ReportFormats::render(report, format, m_perSample->isChecked());
}

void ReportsPage::schedulePreview()
{
    m_perSample->setEnabled(format() == ReportFormats::Format::Csv);
    m_debounce->start();
}

void ReportsPage::startPreview()
{
    if (m_job) {
        // One computation at a time: cancel the running one and start again when it ends.
        m_job->cancel();
        m_again = true;
        return;
    }
    if (inputs().isEmpty()) {
        m_preview.clear();
        m_text->clear();
        m_rich->clear();
        m_status->setText(tr("Add runs, suite CSV files or bags to report on."));
        emit previewUpdated();
        return;
    }
    Result<ReportJob::Request> r = request();
    if (!r) {
        showPreview(nullptr, r.error().toString());
        return;
    }
    m_job = new ReportJob(std::move(*r), this);
    m_progress->setValue(0);
    m_progress->setVisible(true);
    m_status->setText(tr("Computing…"));
    connect(m_job, &ReportJob::progress, m_progress, &QProgressBar::setValue);
    connect(m_job, &ReportJob::finished, this,
            [this](const std::shared_ptr<Report>& report, const QString& why, const QStringList&) {
                m_job->deleteLater();
                m_job = nullptr;
                m_progress->setVisible(false);
                if (m_again) {
                    m_again = false;
                    startPreview();
                    return;
                }
                showPreview(report, why);
            });
    m_job->start();
}

void ReportsPage::showPreview(const std::shared_ptr<Report>& report, const QString& error)
{
    if (!report) {
        m_preview.clear();
        m_text->setPlainText(error);
        m_previewStack->setCurrentWidget(m_text);
        m_status->setText(tr("The report cannot be made: %1").arg(error));
        emit previewUpdated();
        return;
    }
    const ReportFormats::Format f = format();
    if (ReportFormats::entry(f).richPreview) {
        // Rich text cannot show inline SVG: the figure comes as an image rendered from it.
        QSvgRenderer svg(ReportFormats::ecdfSvg(*report));
        QImage figure(QSize(720, 400) * 2, QImage::Format_ARGB32_Premultiplied);
        figure.fill(Qt::white);
        QPainter painter(&figure);
        svg.render(&painter);
        painter.end();
        m_rich->document()->addResource(QTextDocument::ImageResource, QUrl(u"bridgescope:ecdf.png"_s),
                                        figure);
        m_preview = ReportFormats::htmlBody(*report, true)
            + u"<p><img src=\"bridgescope:ecdf.png\" width=\"720\"/></p>"_s;
        m_rich->setHtml(m_preview);
        m_previewStack->setCurrentWidget(m_rich);
    } else {
        const Result<QByteArray> text = render(*report, f);
        m_preview = text ? QString::fromUtf8(*text) : text.error().toString();
        m_text->setPlainText(m_preview);
        m_previewStack->setCurrentWidget(m_text);
    }
    qint64 samples = 0;
    for (const auto& run : report->runs())
        samples += run->engine->samples();
    m_status->setText(
        tr("%1: %2 runs, %3 complete samples").arg(report->title()).arg(report->runs().size()).arg(samples));
    emit previewUpdated();
}

void ReportsPage::dragEnterEvent(QDragEnterEvent* event)
{
    // Measurements only: anything else goes on to the window, which opens it where it belongs.
    const QStringList files = droppedFiles(event->mimeData());
    if (!files.isEmpty() && std::all_of(files.cbegin(), files.cend(), RunLoader::isMeasurement))
        event->acceptProposedAction();
    else
        event->ignore();
}

void ReportsPage::dropEvent(QDropEvent* event)
{
    QStringList files = droppedFiles(event->mimeData());
    files.removeIf([](const QString& f) { return !RunLoader::isMeasurement(f); });
    if (files.isEmpty())
        return;
    event->acceptProposedAction();
    emit measurementsDropped(files);
}

Status ReportsPage::exportTo(const QString& path)
{
    Result<ReportJob::Request> r = request();
    if (!r)
        return r.error();
    // A window-modal progress dialog over a local event loop: the page stays painted, the rest of
    // the window keeps running, and Cancel reaches the job.
    ReportJob job(std::move(*r));
    QProgressDialog progress(tr("Computing the report…"), tr("Cancel"), 0, 100, this);
    progress.setWindowModality(Qt::WindowModal);
    progress.setMinimumDuration(500);
    QEventLoop loop;
    std::shared_ptr<Report> report;
    QString why;
    // The Cancel button emits canceled(); QProgressDialog::cancel() (Escape, or a caller) only sets
    // wasCanceled(), which each progress step looks at.
    connect(&progress, &QProgressDialog::canceled, &job, &ReportJob::cancel);
    connect(&job, &ReportJob::progress, &progress, [&progress, &job](int percent) {
        if (progress.wasCanceled())
            job.cancel();
        else
            progress.setValue(percent);
    });
    connect(&job, &ReportJob::finished, &loop,
            [&](const std::shared_ptr<Report>& result, const QString& failure, const QStringList&) {
                report = result;
                why = failure;
                loop.quit();
            });
    job.start();
    loop.exec();
    progress.reset();
    if (!report)
        return LocatedError {job.isCancelled() ? tr("cancelled; nothing written") : why};
    const Result<QByteArray> bytes = render(*report, format());
    if (!bytes)
        return bytes.error();
    if (bytes->isEmpty())
        return LocatedError {}; // nothing to write, and nothing wrong to say
    return AtomicFile::write(path, *bytes, false);
}

void ReportsPage::chooseInputs()
{
    const QStringList paths = QFileDialog::getOpenFileNames(
        this, tr("Add Inputs"), QString(),
        tr("Runs, suite CSV and bags (*.%1 *.csv *.bag);;All files (*)").arg(RunFile::suffix()));
    addInputs(paths);
}

void ReportsPage::choosePipeline()
{
    const QString path = QFileDialog::getOpenFileName(this, tr("Pipeline"), m_pipeline->text(),
                                                      tr("Pipelines (*.yaml *.yml);;All files (*)"));
    if (!path.isEmpty())
        m_pipeline->setText(path);
}

void ReportsPage::chooseExport()
{
    const ReportFormats::Format f = format();
    const QString suffix = ReportFormats::suffix(f);
    const QString suggestion
        = (inputs().size() == 1 ? QFileInfo(inputs().first()).completeBaseName() : u"comparison"_s)
        + u"-report."_s + suffix;
    const QString path = QFileDialog::getSaveFileName(this, tr("Export Report"), suggestion,
                                                      tr("%1 files (*.%2)").arg(suffix.toUpper(), suffix));
    if (path.isEmpty())
        return;
    if (const Status exported = exportTo(path); !exported)
        QMessageBox::warning(this, tr("Export Report"), exported.error().toString());
    else
        m_status->setText(tr("Written: %1").arg(path));
}

void ReportsPage::removeSelected()
{
    qDeleteAll(m_inputs->selectedItems());
    schedulePreview();
}

void ReportsPage::moveSelected(int delta)
{
    const int row = m_inputs->currentRow();
    const int to = row + delta;
    if (row < 0 || to < 0 || to >= m_inputs->count())
        return;
    QListWidgetItem* item = m_inputs->takeItem(row);
    m_inputs->insertItem(to, item);
    m_inputs->setCurrentRow(to);
    schedulePreview();
}
