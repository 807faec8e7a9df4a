// SPDX-License-Identifier: MIT
#include "fleetview.h"

#include "fleet/fleetsource.h"
#include "mqtt/passwordstore.h"
#include "widgets/common/columnfitter.h"
#include "widgets/common/figuresortproxy.h"
#include "widgets/common/ratechart.h"
#include "widgets/common/viewsetup.h"
#include "widgets/links/fleetmodel.h"

#include <cmath>
#include <QDateTime>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPointer>
#include <QPushButton>
#include <QSettings>
#include <QSortFilterProxyModel>
#include <QSplitter>
#include <QTableView>
#include <QTimer>
#include <QVBoxLayout>

using namespace Qt::StringLiterals;

namespace {
const QString kUrlKey = u"links/prometheusUrl"_s;
const QString kUserKey = u"links/prometheusUser"_s;

QList<double> valuesOf(const QList<PrometheusAnswer::Point>& points)
{
    QList<double> values;
    values.reserve(points.size());
    for (const PrometheusAnswer::Point& p : points)
        values << (std::isfinite(p.value) ? p.value : 0.0);
    return values;
}
} // namespace

FleetView::FleetView(QWidget* parent)
    : QWidget(parent)
    , m_source(new FleetSource(this))
    , m_model(new FleetModel(this))
    , m_proxy(new FigureSortProxy(FleetModel::ValueRole, this))
    , m_passwords(new PasswordStore(this))
    , m_timer(new QTimer(this))
{
    setObjectName(u"fleetView"_s);
    m_model->setObjectName(u"fleetModel"_s);
    m_proxy->setSourceModel(m_model);
    m_table = new QTableView(this);
    m_table->setObjectName(u"fleetTable"_s);
    m_table->setModel(m_proxy);
    ViewSetup::records(m_table, FleetModel::HostColumn);
    m_table->setSortingEnabled(true);
    // The columns fit the rows shown and about as many around them (ColumnFitter grows them for
    // rows scrolled to), not a thousand rows' text measured at each refresh of a large fleet.
    m_table->horizontalHeader()->setResizeContentsPrecision(kFitRows);
    auto* fitter = new ColumnFitter(m_table);
    fitter->figures({FleetModel::StateColumn, FleetModel::SourceRateColumn, FleetModel::DestinationRateColumn,
                     FleetModel::LossColumn, FleetModel::P99Column});
    fitter->fit(FleetModel::HostColumn, 0.15);
    fitter->fit(FleetModel::BridgeColumn, 0.15);
    fitter->fill({FleetModel::LinkColumn, FleetModel::WhyColumn});

    auto* split = new QSplitter(Qt::Horizontal, this);
    split->addWidget(m_table);
    split->addWidget(createDetail());
    split->setStretchFactor(0, 4);
    split->setStretchFactor(1, 1);
    ViewSetup::initialSizes(split, {1000, 280});
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(createBar());
    layout->addWidget(m_status);
    layout->addWidget(split, 1);

    m_timer->setInterval(kRefreshMs);
    connect(m_timer, &QTimer::timeout, m_source, &FleetSource::refresh);
    connect(m_source, &FleetSource::refreshed, this, &FleetView::refreshed);
    connect(m_table->selectionModel(), &QItemSelectionModel::currentRowChanged, this,
            &FleetView::showHistory);
    connect(m_passwords, &PasswordStore::fetched, this,
            [this](const QString& key, const QString& password, bool, const QString&) {
                if (key == keyringKey(m_url->text(), m_user->text()) && !isRefreshing())
                    connectTo(m_url->text(), m_user->text(), password);
            });
    connect(m_passwords, &PasswordStore::stored, this, [this](const QString&, bool ok, const QString& error) {
        if (!ok) // said, never written anywhere else instead
            m_status->setText(m_status->text() + u' ' + tr("The password was not kept: %1.").arg(error));
    });
    const QSettings settings;
    m_url->setText(settings.value(kUrlKey).toString());
    m_user->setText(settings.value(kUserKey).toString());
}

FleetView::~FleetView() = default;

QWidget* FleetView::createBar()
{
    auto* bar = new QWidget(this);
    m_url = new QLineEdit(bar);
    m_url->setObjectName(u"fleetUrl"_s);
    m_url->setPlaceholderText(tr("http://prometheus:9090"));
    m_user = new QLineEdit(bar);
    m_user->setObjectName(u"fleetUser"_s);
    m_user->setPlaceholderText(tr("no basic auth"));
    m_password = new QLineEdit(bar);
    m_password->setObjectName(u"fleetPassword"_s);
    m_password->setEchoMode(QLineEdit::Password);
    m_password->setToolTip(tr("Kept in the system keyring, never in a file"));
    auto* connectButton = new QPushButton(tr("C&onnect"), bar);
    connectButton->setObjectName(u"fleetConnect"_s);
    connect(connectButton, &QPushButton::clicked, this,
            [this] { connectTo(m_url->text(), m_user->text(), m_password->text()); });
    connect(m_url, &QLineEdit::returnPressed, connectButton, &QPushButton::click);
    auto* row = new QHBoxLayout(bar);
    row->setContentsMargins(0, 0, 0, 0);
    const auto labelled = [&](const QString& text, QWidget* field, int stretch) {
        auto* label = new QLabel(text, bar);
        label->setBuddy(field);
        row->addWidget(label);
        row->addWidget(field, stretch);
    };
    labelled(tr("Prometheus &URL:"), m_url, 3);
    labelled(tr("U&ser:"), m_user, 1);
    labelled(tr("Pass&word:"), m_password, 1);
    row->addWidget(connectButton);
    m_status = new QLabel(tr("Choose the Prometheus server that scrapes the watches of the fleet."), this);
    m_status->setObjectName(u"fleetStatus"_s);
    m_status->setWordWrap(true);
    return bar;
}

QWidget* FleetView::createDetail()
{
    auto* pane = new QWidget(this);
    m_detailTitle = new QLabel(pane);
    m_detailTitle->setObjectName(u"fleetDetailTitle"_s);
    m_detailTitle->setWordWrap(true);
    m_rateChart = new RateChart(pane);
    m_rateChart->setObjectName(u"fleetRateChart"_s);
    m_latencyChart = new RateChart(pane);
    m_latencyChart->setObjectName(u"fleetLatencyChart"_s);
    auto* layout = new QVBoxLayout(pane);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_detailTitle);
    layout->addWidget(new QLabel(tr("Destination rate, last %1 minutes").arg(kHistoryMinutes), pane));
    layout->addWidget(m_rateChart, 1);
    layout->addWidget(new QLabel(tr("Latency p99, last %1 minutes").arg(kHistoryMinutes), pane));
    layout->addWidget(m_latencyChart, 1);
    return pane;
}

QString FleetView::keyringKey(const QString& url, const QString& user)
{
    return u"prometheus:"_s + url.trimmed() + u'|' + user;
}

bool FleetView::connectTo(const QString& url, const QString& user, const QString& password)
{
    const Result<QUrl> base = PrometheusClient::checkUrl(url);
    if (!base.ok()) {
        m_status->setText(base.error().message);
        return false;
    }
    m_url->setText(url.trimmed());
    m_user->setText(user);
    QSettings settings;
    settings.setValue(kUrlKey, url.trimmed());
    settings.setValue(kUserKey, user);
    if (!password.isEmpty())
        m_passwords->store(keyringKey(url, user), password);
    m_password->clear(); // held by the client only
    m_source->setServer(*base, user, password);
    m_model->setSnapshot({});
    m_status->setText(tr("Reading the fleet from %1…").arg(base->toDisplayString()));
    m_source->refresh();
    m_timer->start();
    return true;
}

void FleetView::connectToRemembered()
{
    if (m_url->text().isEmpty())
        return;
    if (m_user->text().isEmpty())
        connectTo(m_url->text());
    else
        m_passwords->fetch(keyringKey(m_url->text(), m_user->text())); // connects when it comes
}

void FleetView::stop()
{
    m_timer->stop();
}

bool FleetView::isRefreshing() const
{
    return m_timer->isActive();
}

void FleetView::refreshed()
{
    const FleetSnapshot& s = m_source->snapshot();
    const QString at = QDateTime::fromMSecsSinceEpoch(qint64(s.time * 1000)).toString(u"HH:mm:ss"_s);
    if (!m_source->error().isEmpty()) {
        m_status->setText(s.time > 0 ? tr("%1 (the links as of %2)").arg(m_source->error(), at)
                                     : m_source->error());
        return;
    }
    m_model->setSnapshot(s);
    int silent = 0;
    for (const FleetHost& h : s.hosts)
        silent += h.reporting ? 0 : 1;
    QString text = tr("Links: %1 on %2 hosts, %3 not reporting, as of %4")
                       .arg(s.links.size())
                       .arg(s.hosts.size())
                       .arg(silent)
                       .arg(at);
    if (s.droppedSeries > 0 || s.badSamples > 0)
        text += tr("; %1 series past the bound, %2 of the wrong form left out")
                    .arg(s.droppedSeries)
                    .arg(s.badSamples);
    m_status->setText(text);
    if (!m_table->currentIndex().isValid() && m_proxy->rowCount() > 0)
        m_table->setCurrentIndex(m_proxy->index(0, 0));
}

void FleetView::showHistory()
{
    const FleetLink* link = m_model->linkAt(m_proxy->mapToSource(m_table->currentIndex()).row());
    if (!link) {
        m_detailTitle->clear();
        return;
    }
    m_detailTitle->setText(u"%1 · %2\n%3"_s.arg(link->host, link->link, link->verdict.detail));
    const quint64 asked = ++m_historyAsked;
    QPointer<FleetView> self(this);
    m_source->history(*link, double(QDateTime::currentMSecsSinceEpoch()) / 1000.0, kHistoryMinutes, 1,
                      [self, asked](const FleetHistory& h) {
                          if (!self || asked != self->m_historyAsked)
                              return;
                          self->m_rateChart->setSamples(valuesOf(h.destinationRateHz), tr("Hz"));
                          self->m_latencyChart->setSamples(valuesOf(h.latencyP99Ms), tr("ms"));
                      });
}
