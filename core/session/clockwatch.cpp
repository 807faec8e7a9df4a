// SPDX-License-Identifier: MIT
#include "clockwatch.h"

#include "base/wallclock.h"
#include "mqtt/mqttclockprober.h"

using namespace Qt::StringLiterals;

ClockWatch::ClockWatch(Sink sink, QObject* parent)
    : QObject(parent)
    , m_sink(std::move(sink))
{
    m_check.setInterval(1000);
    connect(&m_check, &QTimer::timeout, this, &ClockWatch::tick);
}

ClockWatch::~ClockWatch() = default;

void ClockWatch::watch(const QStringList& named, const MqttProfile& profile)
{
    QStringList hosts;
    for (const QString& h : named)
        if (!h.isEmpty() && !hosts.contains(h))
            hosts << h;
    m_omitted = int(std::max<qsizetype>(0, hosts.size() - kMaxHosts));
    hosts = hosts.mid(0, kMaxHosts);
    if (profile.url.isEmpty())
        hosts.clear();
    // Another broker: every prober starts again on it.
    const bool sameBroker = profile.url == m_profile.url && profile.username == m_profile.username
        && profile.password == m_profile.password && profile.caFile == m_profile.caFile;
    m_profile = profile;
    for (auto it = m_probers.begin(); it != m_probers.end();) {
        if (sameBroker && hosts.contains(it->first)) {
            ++it;
            continue;
        }
        m_failures.erase(it->first);
        m_lastAnswerNs.erase(it->first);
        m_firstAnswerNs.erase(it->first);
        it = m_probers.erase(it);
    }
    for (const QString& host : std::as_const(hosts)) {
        if (m_probers.count(host))
            continue;
        auto prober = std::make_unique<MqttClockProber>(host, m_profile);
        connect(prober.get(), &ClockProber::estimateChanged, this, [this, host](const ClockEstimate& e) {
            if (e.probes < kMinProbes)
                return;
            const qint64 now = wallClockNs();
            m_failures.erase(host);
            m_lastAnswerNs[host] = now;
            m_firstAnswerNs.try_emplace(host, now);
            if (isSettled(host, e, now))
                m_sink(e);
        });
        connect(prober.get(), &ClockProber::failed, this, [this, host](const QString& why) {
            m_failures[host] = why;
            checkProblems();
        });
        prober->start();
        m_probers.emplace(host, std::move(prober));
    }
    if (m_probers.empty())
        m_check.stop();
    else if (!m_check.isActive())
        m_check.start();
    checkProblems();
}

QStringList ClockWatch::hosts() const
{
    QStringList out;
    for (const auto& [host, prober] : m_probers)
        out << host;
    return out;
}

const ClockProber* ClockWatch::prober(const QString& host) const
{
    const auto it = m_probers.find(host);
    return it == m_probers.end() ? nullptr : it->second.get();
}

void ClockWatch::tick()
{
    const qint64 now = wallClockNs();
    for (const auto& [host, prober] : m_probers)
        if (const ClockEstimate e = prober->estimate(now); e.isValid() && isSettled(host, e, now))
            m_sink(e);
    checkProblems();
}

bool ClockWatch::isSettled(const QString& host, const ClockEstimate& e, qint64 nowNs) const
{
    if (e.probes < kMinProbes)
        return false;
    const auto first = m_firstAnswerNs.find(host);
    return e.uncertaintyNs <= kSettledUncertaintyNs
        || (first != m_firstAnswerNs.end() && nowNs - first->second >= kSettleNs);
}

QString ClockWatch::syncText() const
{
    QStringList lines;
    for (const auto& [host, prober] : m_probers)
        if (prober->farSyncState().isReported())
            lines << host + u": "_s + prober->farSyncState().text();
    return lines.join(u'\n');
}

QString ClockWatch::problems() const
{
    return m_problems;
}

void ClockWatch::checkProblems()
{
    const qint64 now = wallClockNs();
    QStringList silent;
    QStringList stale;
    QStringList failed;
    for (const auto& [host, prober] : m_probers) {
        if (const auto f = m_failures.find(host); f != m_failures.end()) {
            failed << tr("%1 (%2)").arg(host, f->second);
            continue;
        }
        if (const auto last = m_lastAnswerNs.find(host); last != m_lastAnswerNs.end()) {
            if (now - last->second > kSilentNs)
                stale << tr("%1 for %2 s").arg(host).arg((now - last->second) / 1'000'000'000);
            continue;
        }
        const ClockProberCounters c = prober->counters();
        // Unanswered once the burst and its answers' time are over.
        const bool due = c.lost > 0 || c.sent > prober->options().burst;
        if (due && !prober->estimate(now).isValid())
            silent << host;
    }
    QStringList parts;
    if (!silent.isEmpty())
        parts << tr("No clock service answers for %1 on the broker: run `bridgescope clock serve --name NAME "
                    "--broker URL` on each host, or set one_clock: true for hosts that share a clock.")
                     .arg(silent.join(u", "_s));
    if (!stale.isEmpty())
        parts << tr("No answer from the clock service of %1: the estimate kept grows less certain with "
                    "time.")
                     .arg(stale.join(u", "_s));
    if (!failed.isEmpty())
        parts << tr("Clocks cannot be probed: %1.").arg(failed.join(u"; "_s));
    if (m_omitted > 0)
        parts << tr("%n more host(s) not probed (at most %1).", nullptr, m_omitted).arg(kMaxHosts);
    const QString text = parts.join(u' ');
    if (text != m_problems) {
        m_problems = text;
        emit problemsChanged();
    }
}
