// SPDX-License-Identifier: MIT
#include "fleetsource.h"

#include <memory>
#include <QDateTime>

using namespace Qt::StringLiterals;

FleetSource::FleetSource(QObject* parent)
    : QObject(parent)
    , m_client(new PrometheusClient(this))
{ }

void FleetSource::setServer(const QUrl& base, const QString& user, const QString& password)
{
    ++m_generation; // answers still coming from the old server are not this one's
    m_pending = 0;
    m_client->setServer(base, user, password);
    m_snapshot = {};
    m_hostsSeen.clear();
    m_totals.clear();
    m_error.clear();
}

bool FleetSource::isTotal(const QString& name)
{
    return name == "messages"_L1 || name == "bytes"_L1;
}

void FleetSource::refresh()
{
    if (m_pending > 0)
        return;
    const double now = double(QDateTime::currentMSecsSinceEpoch()) / 1000.0;
    const bool totals = m_totals.isEmpty() || !(now - m_totalsAt < m_totalsSeconds);
    auto queries = FleetSnapshotBuilder::queries();
    if (!totals)
        queries.removeIf([](const auto& query) { return isTotal(query.first); });
    m_answers.clear();
    m_pending = int(queries.size());
    const quint64 generation = m_generation;
    for (const auto& [name, promql] : queries) {
        m_client->query(
            promql,
            [this, name = name, generation, now, totals](const PrometheusAnswer& answer) {
                if (generation != m_generation)
                    return;
                m_answers.insert(name, answer);
                if (--m_pending == 0)
                    answered(now, totals);
            },
            now);
    }
}

void FleetSource::answered(double now, bool totals)
{
    ++m_refreshes;
    QString error;
    for (auto it = m_answers.cbegin(); it != m_answers.cend() && error.isEmpty(); ++it)
        if (!it->ok())
            error = it->error;
    if (error.isEmpty()) {
        m_error.clear();
        if (totals) {
            m_totals.clear();
            for (auto it = m_answers.cbegin(); it != m_answers.cend(); ++it)
                if (isTotal(it.key()))
                    m_totals.insert(it.key(), it.value());
            m_totalsAt = now;
        } else {
            m_answers.insert(m_totals);
        }
        m_snapshot = FleetSnapshotBuilder::build(m_answers, m_rules, now, &m_hostsSeen);
    } else {
        m_error = tr("cannot read the fleet from %1: %2")
                      .arg(m_client->server().toDisplayString(QUrl::RemoveUserInfo), error);
    }
    m_answers.clear();
    emit refreshed();
}

void FleetSource::history(const FleetLink& link, double now, double minutes, double stepSeconds,
                          std::function<void(const FleetHistory&)> done)
{
    const QString selector = u"host=%1,bridge=%2,link=%3,direction=%4"_s.arg(
        PrometheusClient::quoted(link.host), PrometheusClient::quoted(link.bridge),
        PrometheusClient::quoted(link.link), PrometheusClient::quoted(link.direction));
    // The table's window (FleetSnapshotBuilder::kRateWindowSeconds): the chart draws what it shows.
    const QString rate = u"rate(bridgescope_link_messages_total{%1,side=\"destination\"}%2)"_s.arg(
        selector, FleetSnapshotBuilder::rateRange());
    const QString p99 = u"1000 * histogram_quantile(0.99, sum by (le) "
                        "(rate(bridgescope_link_latency_seconds_bucket{%1}[1m])))"_s.arg(selector);
    auto result = std::make_shared<FleetHistory>();
    auto left = std::make_shared<int>(2);
    const auto take = [result, left, done](QList<PrometheusAnswer::Point>* into, const PrometheusAnswer& a) {
        if (!a.ok() && result->error.isEmpty())
            result->error = a.error;
        if (a.ok() && !a.series.isEmpty())
            *into = a.series.constFirst().points;
        if (--*left == 0)
            done(*result);
    };
    const double start = now - minutes * 60;
    m_client->queryRange(rate, start, now, stepSeconds,
                         [take, result](const PrometheusAnswer& a) { take(&result->destinationRateHz, a); });
    m_client->queryRange(p99, start, now, stepSeconds,
                         [take, result](const PrometheusAnswer& a) { take(&result->latencyP99Ms, a); });
}
