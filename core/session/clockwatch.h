// SPDX-License-Identifier: MIT
#pragma once

#include "clock/clockestimate.h"
#include "mqtt/mqttprofile.h"

#include <functional>
#include <map>
#include <memory>
#include <QCoreApplication>
#include <QObject>
#include <QStringList>
#include <QTimer>

class ClockProber;

/// Probes the clock service (`bridgescope clock serve`) of every host a measured pipeline names,
/// over the measured broker, and hands each estimate to the measurement. A pipeline on one clock,
/// without hosts, or a session without a broker probes nothing: watching needs the user's
/// pipeline with hosts on a connected broker, and stops completely when either goes.
class ClockWatch : public QObject
{
    Q_OBJECT
public:
    static constexpr int kMaxHosts = 16; ///< hosts probed at once; a pipeline naming more probes the first
    /// A measured host silent this long is said: its estimate ages (the uncertainty grows with time).
    static constexpr qint64 kSilentNs = 5'000'000'000;
    /// Answers an estimate needs before it corrects anything: the first ones, through a connection
    /// just made, are the slowest (and their uncertainty would stay the figures' for a whole window).
    static constexpr int kMinProbes = 4;
    /// An estimate looser than this waits, at most kSettleNs after the host's first answers, for a
    /// tighter one before it corrects anything: a slow start (a busy host, a connection still
    /// warming) would otherwise set the figures' interval for a whole window. After that, whatever
    /// it is, it is used and shown.
    static constexpr qint64 kSettledUncertaintyNs = 2'000'000;
    static constexpr qint64 kSettleNs = 10'000'000'000;

    using Sink = std::function<void(const ClockEstimate&)>;
    explicit ClockWatch(Sink sink, QObject* parent = nullptr);
    ~ClockWatch() override;

    /// Probes `hosts` (at most kMaxHosts, in order) on the broker of `profile`; probers of hosts no
    /// longer named stop, those still named go on. An empty list or broker URL stops every prober.
    void watch(const QStringList& hosts, const MqttProfile& profile);
    QStringList hosts() const;
    const ClockProber* prober(const QString& host) const;
    /// What keeps hosts unmeasured, for the page: "No clock service answers for cloud on the broker
    /// (run `bridgescope clock serve --name cloud --broker …` there)."; empty when every host answers
    /// (or when none is probed).
    QString problems() const;
    /// What each probed host says of its own clock (chrony, PTP), a line per host that reports it:
    /// "cloud: chrony, synchronised to 10.0.0.1: offset +0.012 ms, …".
    QString syncText() const;
    /// Hosts named beyond kMaxHosts, not probed.
    int omittedHosts() const { return m_omitted; }

signals:
    void problemsChanged();

private:
    void checkProblems();
    /// Whether `host`'s estimate `e` may correct figures now (kMinProbes, then kSettledUncertaintyNs
    /// or kSettleNs).
    bool isSettled(const QString& host, const ClockEstimate& e, qint64 nowNs) const;
    /// Once a second: every measured host's estimate as of now (its uncertainty grows with the time
    /// since its best probe, so a silent service's estimate is handed on less certain), then the problems.
    void tick();

    Sink m_sink;
    MqttProfile m_profile;
    std::map<QString, std::unique_ptr<ClockProber>> m_probers; ///< host -> its prober
    std::map<QString, QString> m_failures; ///< host -> why its transport failed
    std::map<QString, qint64> m_lastAnswerNs; ///< host -> when its latest estimate came (our wall clock)
    std::map<QString, qint64> m_firstAnswerNs; ///< host -> when its first estimate came (our wall clock)
    QTimer m_check; ///< ages the estimates and looks for hosts that do not answer
    QString m_problems;
    int m_omitted = 0;
};
