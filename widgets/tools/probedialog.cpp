// SPDX-License-Identifier: MIT
#include "probedialog.h"

#include "latency/latencyseriesset.h"
#include "widgets/common/ecdfchart.h"
#include "widgets/common/viewsetup.h"

#include <cmath>
#include <QAbstractAxis>
#include <QChart>
#include <QChartView>
#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>
#include <QTableWidget>
#include <QThread>
#include <QValueAxis>
#include <QVBoxLayout>

using namespace Qt::StringLiterals;

namespace {
constexpr int kPollMs = 200;

QString defaultBroker()
{
    return u"tcp://127.0.0.1:1883"_s;
}

/// A caption above a value, both in one grid column.
QLabel* addFigure(QGridLayout* grid, int column, const QString& caption, QWidget* parent)
{
    auto* name = new QLabel(caption, parent);
    name->setStyleSheet(u"color: palette(mid)"_s);
    auto* value = new QLabel(u"–"_s, parent);
    QFont font = value->font();
    if (font.pointSizeF() > 0) {
        font.setPointSizeF(font.pointSizeF() * 1.25);
        value->setFont(font);
    }
    value->setTextInteractionFlags(Qt::TextSelectableByMouse);
    grid->addWidget(name, 0, column);
    grid->addWidget(value, 1, column);
    return value;
}
} // namespace

ProbeDialog::ProbeDialog(QWidget* parent)
    : QDialog(parent)
    , m_probe(new LinkProbe(this))
    , m_broker(new QLineEdit(this))
    , m_size(new QSpinBox(this))
    , m_rate(new QDoubleSpinBox(this))
    , m_qos(new QComboBox(this))
    , m_count(new QSpinBox(this))
    , m_sweep(new QCheckBox(tr("S&weep the rate up to the link's limit"), this))
    , m_viaEcho(new QCheckBox(tr("Back &via an echo client"), this))
    , m_start(new QPushButton(tr("&Start"), this))
    , m_stop(new QPushButton(tr("S&top"), this))
    , m_status(new QLabel(this))
    , m_error(new QLabel(this))
    , m_countsTitle(new QLabel(this))
    , m_statsTitle(new QLabel(this))
    , m_sweepGroup(new QGroupBox(tr("Sweep"), this))
    , m_steps(new QTableWidget(0, 4, this))
    , m_sweepResult(new QLabel(this))
    , m_chart(new EcdfChart(this))
{
    setWindowTitle(tr("Link Probe"));
    setObjectName(u"probeDialog"_s);
    m_rate->setObjectName(u"rate"_s);
    m_count->setObjectName(u"count"_s);
    m_sweep->setObjectName(u"sweep"_s);
    m_start->setObjectName(u"startButton"_s);
    m_stop->setObjectName(u"stopButton"_s);
    m_sweepResult->setObjectName(u"sweepResult"_s);

    auto* top = new QHBoxLayout;
    top->addLayout(createSettingsColumn(), 0);
    top->addSpacing(12);
    top->addLayout(createResultsColumn(), 1);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(top, 1);
    layout->addWidget(buttons);
    connect(buttons, &QDialogButtonBox::rejected, this, &ProbeDialog::reject);
    connectProbe();

    setProfile(MqttProfile::fromUrl(defaultBroker()));
    showChart({});
    resize(1000, 640);
}

QLayout* ProbeDialog::createSettingsColumn()
{
    auto* column = new QVBoxLayout;
    column->addLayout(createSettingsForm());

    m_start->setDefault(true);
    m_stop->setEnabled(false);
    auto* runRow = new QHBoxLayout;
    runRow->addWidget(m_start);
    runRow->addWidget(m_stop);
    runRow->addStretch(1);
    column->addLayout(runRow);

    m_status->setWordWrap(true);
    m_status->setText(tr("Round trips from this computer through the broker and back."));
    m_error->setObjectName(u"probeError"_s);
    m_error->setWordWrap(true);
    m_error->setStyleSheet(u"color: #b00020"_s);
    m_error->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_error->hide();
    column->addWidget(m_status);
    column->addWidget(m_error);

    m_steps->setHorizontalHeaderLabels({tr("Rate Hz"), tr("Sent Hz"), tr("Median ms"), tr("Lost %")});
    ViewSetup::records(m_steps);
    m_steps->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    m_steps->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    m_steps->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_sweepResult->setWordWrap(true);
    auto* sweepLayout = new QVBoxLayout(m_sweepGroup);
    sweepLayout->addWidget(m_steps, 1);
    sweepLayout->addWidget(m_sweepResult);
    m_sweepGroup->setVisible(false);
    column->addWidget(m_sweepGroup, 1);
    column->addStretch(0);
    return column;
}

QLayout* ProbeDialog::createSettingsForm()
{
    m_broker->setObjectName(u"broker"_s);
    m_broker->setPlaceholderText(defaultBroker());
    m_broker->setToolTip(tr("tcp://, ssl://, mqtt://, mqtts://, ws:// or wss://, with the port"));
    m_size->setRange(LinkProbeOptions::kHeaderBytes, LinkProbeOptions::kMaxPayloadBytes);
    m_size->setValue(1024);
    m_size->setSuffix(tr(" B"));
    m_size->setToolTip(
        tr("The whole payload, its %1-byte header included").arg(LinkProbeOptions::kHeaderBytes));
    m_rate->setRange(0.1, 1e6);
    m_rate->setDecimals(1);
    m_rate->setValue(10);
    m_rate->setSuffix(tr(" Hz"));
    m_rate->setToolTip(tr("The rate of a plain run; the first step of a sweep"));
    m_qos->addItem(tr("0: at most once"), 0);
    m_qos->addItem(tr("1: at least once"), 1);
    m_qos->addItem(tr("2: exactly once"), 2);
    m_qos->setToolTip(tr("QoS 1 and 2 round trips include TCP's delayed acknowledgements"));
    m_count->setRange(1, 100'000'000);
    m_count->setValue(100);
    m_count->setSuffix(tr(" messages"));
    m_sweep->setToolTip(tr("Raises the rate by 1.5x per step (about a second each) until more than 1 % is "
                           "lost, the round trip grows tenfold or the sender falls behind"));
    m_viaEcho->setToolTip(tr("Listen on …/pong for the copies of `bridgescope probe --echo` running on the "
                             "other host, instead of on …/ping for the broker's own"));

    auto* form = new QFormLayout;
    form->addRow(tr("&Broker:"), m_broker);
    form->addRow(tr("Payload si&ze:"), m_size);
    form->addRow(tr("&Rate:"), m_rate);
    form->addRow(tr("&QoS:"), m_qos);
    form->addRow(tr("Cou&nt:"), m_count);
    form->addRow(QString(), m_sweep);
    form->addRow(QString(), m_viaEcho);
    return form;
}

QLayout* ProbeDialog::createResultsColumn()
{
    auto* counts = new QGridLayout;
    m_figures[Sent] = addFigure(counts, 0, tr("Sent"), this);
    m_figures[Received] = addFigure(counts, 1, tr("Received"), this);
    m_figures[Lost] = addFigure(counts, 2, tr("Lost"), this);
    m_figures[OutOfOrder] = addFigure(counts, 3, tr("Out of order"), this);
    auto* stats = new QGridLayout;
    m_figures[Mean] = addFigure(stats, 0, tr("Mean"), this);
    m_figures[Median] = addFigure(stats, 1, tr("Median"), this);
    m_figures[Std] = addFigure(stats, 2, tr("Std"), this);
    m_figures[Min] = addFigure(stats, 3, tr("Min"), this);
    m_figures[Max] = addFigure(stats, 4, tr("Max"), this);
    m_figures[P99] = addFigure(stats, 5, u"p99"_s, this);
    for (QGridLayout* grid : {counts, stats})
        for (int c = 0; c < grid->columnCount(); ++c)
            grid->setColumnStretch(c, 1);
    QFont bold = m_statsTitle->font();
    bold.setBold(true);
    m_countsTitle->setFont(bold);
    m_statsTitle->setFont(bold);
    showTitles(QString());

    m_chart->setMinimumSize(420, 300);
    auto* column = new QVBoxLayout;
    column->addWidget(m_countsTitle);
    column->addLayout(counts);
    column->addSpacing(6);
    column->addWidget(m_statsTitle);
    column->addLayout(stats);
    column->addWidget(m_chart, 1);
    return column;
}

void ProbeDialog::connectProbe()
{
    connect(m_start, &QPushButton::clicked, this, &ProbeDialog::start);
    connect(m_stop, &QPushButton::clicked, this, &ProbeDialog::stop);
    connect(m_sweep, &QCheckBox::toggled, this, [this](bool on) {
        m_count->setEnabled(!on && !m_running);
        m_sweepGroup->setVisible(on || m_steps->rowCount() > 0);
    });
    connect(m_probe, &LinkProbe::connected, this, [this](const QString& clientId) {
        m_status->setText(
            tr("Connected as %1; sending on %2.").arg(clientId, LinkProbe::pingTopic(clientId)));
    });
    connect(m_probe, &LinkProbe::stepFinished, this, &ProbeDialog::onStepFinished);
    connect(m_probe, &LinkProbe::finished, this, &ProbeDialog::onFinished);
    m_poll.setInterval(kPollMs);
    connect(&m_poll, &QTimer::timeout, this, &ProbeDialog::poll);
}

ProbeDialog::~ProbeDialog() = default;

void ProbeDialog::setProfile(const MqttProfile& profile)
{
    m_profile = profile;
    m_profile.clientId.clear(); // a fixed id would throw the Discover page's connection off the broker
    m_broker->setText(profile.url);
}

LinkProbeOptions ProbeDialog::options() const
{
    LinkProbeOptions o;
    const QString url = m_broker->text().trimmed();
    o.profile = url == m_profile.url ? m_profile : MqttProfile::fromUrl(url);
    o.payloadBytes = m_size->value();
    o.rateHz = m_rate->value();
    o.qos = m_qos->currentData().toInt();
    o.count = m_count->value();
    o.viaEcho = m_viaEcho->isChecked();
    o.maxRateHz = std::max(o.maxRateHz, o.rateHz);
    o.keepArrivals = true;
    return o;
}

void ProbeDialog::start()
{
    if (m_running)
        return;
    const LinkProbeOptions o = options();
    m_series = std::make_unique<LatencySeriesSet>(); // each step whole, like the command's statistics
    m_chart->setSource(m_series.get());
    m_stepSeries.clear();
    m_step = -1;
    m_drawn = ~quint64(0);
    m_sweepRun = m_sweep->isChecked();
    m_steps->setRowCount(0);
    m_sweepResult->clear();
    m_sweepGroup->setVisible(m_sweepRun);
    m_error->hide();
    m_error->clear();
    showCounts(0, 0, u"–"_s, 0);
    showStats(LatencyStats());
    showTitles(QString());
    showChart({});
    m_status->setText(tr("Connecting to %1…").arg(o.profile.url));
    setRunning(true);
    if (m_sweepRun)
        m_probe->startSweep(o);
    else
        m_probe->start(o);
    m_poll.start();
}

void ProbeDialog::stop()
{
    if (!m_running)
        return;
    m_probe->stop();
    m_stop->setEnabled(false);
    m_status->setText(tr("Stopping…"));
}

void ProbeDialog::reject()
{
    // Closing stops the probe; its result still arrives and is shown when the dialog opens again.
    stop();
    QDialog::reject();
}

void ProbeDialog::setRunning(bool running)
{
    m_running = running;
    const QList<QWidget*> inputs = {m_broker, m_size, m_rate, m_qos, m_sweep, m_viaEcho};
    for (QWidget* w : inputs)
        w->setEnabled(!running);
    m_count->setEnabled(!running && !m_sweep->isChecked());
    m_start->setEnabled(!running);
    m_stop->setEnabled(running);
    if (running)
        m_stop->setFocus();
    else
        m_start->setFocus();
}

QString ProbeDialog::seriesOf(int step, double rateHz)
{
    if (step >= int(m_stepSeries.size()))
        m_stepSeries.resize(std::size_t(step) + 1);
    QString& name = m_stepSeries[std::size_t(step)];
    if (name.isEmpty()) // a step too short for any tick to see it running has no rate here
        name = rateHz > 0 ? hz(rateHz) : tr("step %1").arg(step + 1);
    return name;
}

void ProbeDialog::poll()
{
    Q_ASSERT(QThread::currentThread() == thread());
    LinkProbeProgress p = m_probe->takeProgress();
    if (p.step < 0)
        return;
    // Every round trip of a step lands in that step's series, also the ones of a step just ended.
    int last = -1;
    QString name;
    for (const auto& [step, rttNs] : p.rttNs) {
        if (step != last) {
            name = seriesOf(step, step == p.step ? p.rateHz : 0);
            last = step;
        }
        m_series->add(name, rttNs);
    }
    const QString id = LatencySeriesSet::idOf(seriesOf(p.step, p.rateHz));
    if (p.step != m_step) {
        m_step = p.step;
        showTitles(hz(p.rateHz));
        if (m_sweepRun)
            m_status->setText(tr("Step %1: sending at %2…").arg(p.step + 1).arg(hz(p.rateHz)));
        else
            m_status->setText(tr("Sending %1 messages at %2…").arg(m_count->value()).arg(hz(p.rateHz)));
    }
    const qint64 inFlight = p.sent - p.received;
    showCounts(p.sent, p.received, tr("%1 in flight").arg(inFlight), p.outOfOrder);
    QStringList ids = m_chart->series();
    if (const int series = m_series->ecdfIndex(id); series >= 0) {
        showStats(m_series->ecdfSeries(series).stats());
        ids = QStringList {id};
    }
    if (ids != m_chart->series() || m_series->revision() != m_drawn) {
        m_drawn = m_series->revision();
        showChart(ids);
    }
}

void ProbeDialog::showChart(const QStringList& ids)
{
    m_chart->setSeries(ids);
    m_chart->refresh();
    // The chart is the Measure page's: give it the probe's words, and no room left of zero (its
    // margin around the data may start below it; a round trip cannot).
    for (QChartView* view : m_chart->views()) {
        QChart* chart = view->chart();
        for (QAbstractAxis* axis : chart->axes(Qt::Horizontal)) {
            axis->setTitleText(tr("round trip [ms]"));
            if (auto* linear = qobject_cast<QValueAxis*>(axis); linear && linear->min() < 0) {
                linear->setMin(0);
                linear->applyNiceNumbers(); // round ticks again
            }
        }
        if (m_chart->series().isEmpty() || !m_series || m_series->ecdfIndex(m_chart->series().first()) < 0)
            chart->setTitle(m_running ? tr("Waiting for the first round trip…")
                                      : tr("Start the probe to plot the ECDF of its round trips"));
        else
            chart->setTitle(QString());
    }
}

void ProbeDialog::onStepFinished(const LinkProbeStep& step)
{
    Q_ASSERT(QThread::currentThread() == thread());
    addStepRow(step, false);
}

void ProbeDialog::onFinished(const LinkProbeReport& report)
{
    Q_ASSERT(QThread::currentThread() == thread());
    m_poll.stop();
    poll(); // the round trips that came back since the last tick
    setRunning(false);
    const LinkProbeStep* summary = report.summary();
    if (summary) {
        showCounts(summary->sent, summary->received,
                   tr("%1 (%2 %)").arg(summary->lost).arg(summary->lossPercent(), 0, 'f', 1),
                   summary->outOfOrder);
        showStats(summary->rtt);
        showTitles(hz(summary->rateHz));
    }
    if (report.sweep) {
        m_steps->setRowCount(0);
        for (std::size_t i = 0; i < report.steps.size(); ++i)
            addStepRow(report.steps[i], int(i) == report.best);
        if (report.best >= 0)
            m_sweepResult->setText(
                tr("Highest sustainable rate: <b>%1</b>, <b>%2 MB/s</b><br>The sweep ended: %3.")
                    .arg(hz(report.maxRateHz()), locale().toString(report.throughputMBs(), 'f', 2),
                         report.sweepEnd.toHtmlEscaped()));
        else
            m_sweepResult->setText(
                tr("No sustainable rate.<br>The sweep ended: %1.").arg(report.sweepEnd.toHtmlEscaped()));
        // The best step beside the one that was too much for the link.
        QStringList ids;
        for (const int step : {report.best, int(report.steps.size()) - 1})
            if (step >= 0 && step < int(m_stepSeries.size()) && !m_stepSeries[std::size_t(step)].isEmpty()
                && !ids.contains(LatencySeriesSet::idOf(m_stepSeries[std::size_t(step)])))
                ids << LatencySeriesSet::idOf(m_stepSeries[std::size_t(step)]);
        showChart(ids);
    } else {
        showChart(m_chart->series());
    }
    if (!report.error.isEmpty()) {
        showError(report.error);
        m_status->setText(report.received() > 0
                              ? tr("Stopped by an error after %1 round trips.").arg(report.received())
                              : tr("The probe could not run."));
    } else if (report.sweep) {
        const int steps = int(report.steps.size());
        m_status->setText(report.interrupted ? tr("Sweep stopped after %n step(s).", nullptr, steps)
                                             : tr("Sweep done: %n step(s).", nullptr, steps));
    } else if (summary) {
        m_status->setText(
            report.interrupted
                ? tr("Stopped: %1 of %2 messages came back.").arg(summary->received).arg(summary->sent)
                : tr("Done: %1 of %2 messages came back.").arg(summary->received).arg(summary->sent));
    }
    emit probeFinished(report);
}

void ProbeDialog::addStepRow(const LinkProbeStep& step, bool best)
{
    const int row = m_steps->rowCount();
    m_steps->insertRow(row);
    const QStringList cells
        = {locale().toString(step.rateHz, 'f', 1), locale().toString(step.sentRateHz, 'f', 1),
           ms(step.rtt.median), locale().toString(step.lossPercent(), 'f', 1)};
    for (int c = 0; c < cells.size(); ++c) {
        auto* item = new QTableWidgetItem(cells[c]);
        item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
        if (best) {
            QFont font = item->font();
            font.setBold(true);
            item->setFont(font);
            item->setToolTip(tr("The highest sustainable rate"));
        }
        m_steps->setItem(row, c, item);
    }
    m_steps->scrollToBottom();
}

void ProbeDialog::showCounts(qint64 sent, qint64 received, const QString& lost, qint64 outOfOrder)
{
    m_figures[Sent]->setText(locale().toString(sent));
    m_figures[Received]->setText(locale().toString(received));
    m_figures[Lost]->setText(lost);
    m_figures[OutOfOrder]->setText(locale().toString(outOfOrder));
}

void ProbeDialog::showStats(const LatencyStats& stats)
{
    const std::pair<Figure, double> values[] = {{Mean, stats.mean}, {Median, stats.median}, {Std, stats.std},
                                                {Min, stats.min},   {Max, stats.max},       {P99, stats.p99}};
    for (const auto& [figure, value] : values)
        m_figures[figure]->setText(ms(value));
}

void ProbeDialog::showTitles(const QString& rate)
{
    m_countsTitle->setText(rate.isEmpty() ? tr("Messages") : tr("Messages at %1").arg(rate));
    m_statsTitle->setText(rate.isEmpty() ? tr("Round trip [ms]") : tr("Round trip at %1 [ms]").arg(rate));
}

void ProbeDialog::showError(const QString& error)
{
    m_error->setText(error);
    m_error->show();
}

QString ProbeDialog::hz(double value) const
{
    return tr("%1 Hz").arg(locale().toString(value, 'f', 1));
}

QString ProbeDialog::ms(double value) const
{
    return std::isfinite(value) ? locale().toString(value, 'f', 3) : u"–"_s;
}
