// SPDX-License-Identifier: MIT
#pragma once

#include "twohostlab.h"

#include <memory>
#include <optional>
#include <QElapsedTimer>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>

/// The clock service across the two-host lab (issue 43): `bridgescope clock serve --name cloud`
/// inside the cloud's namespace, its clock `offsetMs` ahead, probed by `bridgescope clock probe`
/// inside the vehicle's, over UDP on the veth, or through a mosquitto on the vehicle's side. Shared
/// by tst_twohostclocks and bench_twohostclocks.
namespace TwoHostClocks {

struct Estimate
{
    double offsetMs = 0;
    double uncertaintyMs = -1;
    double bestRoundTripMs = 0;
};

/// A mosquitto inside the vehicle's namespace, listening on the vehicle's veth address.
class VehicleBroker
{
public:
    explicit VehicleBroker(const TwoHostLab& lab, quint16 port = 18830)
        : m_url(QStringLiteral("tcp://%1:%2").arg(lab.address(TwoHostLab::Vehicle)).arg(port))
    {
        QFile conf(m_dir.filePath(QStringLiteral("mosquitto.conf")));
        if (!conf.open(QIODevice::WriteOnly))
            return;
        conf.write(QStringLiteral("listener %1 %2\nallow_anonymous true\n")
                       .arg(port)
                       .arg(lab.address(TwoHostLab::Vehicle))
                       .toUtf8());
        conf.close();
        const QStringList argv
            = lab.inNamespace(TwoHostLab::Vehicle, {QStringLiteral("mosquitto"), QStringLiteral("-c"), conf.fileName()});
        m_process.start(argv.first(), argv.mid(1));
        m_process.waitForStarted(5000);
    }
    ~VehicleBroker()
    {
        m_process.terminate();
        if (!m_process.waitForFinished(5000))
            m_process.kill();
    }
    QString url() const { return m_url; }

private:
    QTemporaryDir m_dir;
    QString m_url;
    QProcess m_process;
};

/// `clock serve --name cloud` in the cloud's namespace, on its veth address (UDP port 0: one is
/// picked and read from its output) and, with `brokerUrl`, on that broker too.
class CloudService
{
public:
    CloudService(const TwoHostLab& lab, const QString& program, double offsetMs, const QString& brokerUrl = {})
    {
        QStringList args {program,
                          QStringLiteral("clock"),
                          QStringLiteral("serve"),
                          QStringLiteral("--name"),
                          QStringLiteral("cloud"),
                          QStringLiteral("--udp"),
                          lab.address(TwoHostLab::Cloud) + QStringLiteral(":0"),
                          QStringLiteral("--clock-offset-ms"),
                          QString::number(offsetMs)};
        if (!brokerUrl.isEmpty())
            args << QStringLiteral("--broker") << brokerUrl;
        const QStringList argv = lab.inNamespace(TwoHostLab::Cloud, args);
        m_process.start(argv.first(), argv.mid(1));
        const QRegularExpression port(QStringLiteral("UDP [0-9.]+:(\\d+)"));
        QElapsedTimer t;
        t.start();
        while (t.elapsed() < 10000) {
            m_out += QString::fromUtf8(m_process.readAllStandardOutput());
            const QRegularExpressionMatch m = port.match(m_out);
            const bool mqttReady = brokerUrl.isEmpty() || m_out.contains(QStringLiteral("MQTT: connected"));
            if (m.hasMatch() && mqttReady) {
                m_udp = lab.address(TwoHostLab::Cloud) + u':' + m.captured(1);
                break;
            }
            if (!m_process.waitForReadyRead(200) && m_process.state() == QProcess::NotRunning)
                break;
        }
    }
    ~CloudService()
    {
        m_process.terminate();
        if (!m_process.waitForFinished(5000))
            m_process.kill();
    }
    /// ADDRESS:PORT of its UDP probe port; empty when it did not start.
    QString udp() const { return m_udp; }
    QString output() const { return m_out + QString::fromUtf8(m_process.readAllStandardError()); }

private:
    mutable QProcess m_process;
    QString m_out;
    QString m_udp;
};

/// `clock probe --json` from the vehicle's namespace: over UDP to `udp`, or through `brokerUrl`.
inline std::optional<Estimate> probe(const TwoHostLab& lab, const QString& program, const QString& udp,
                                     const QString& brokerUrl, int count, QString* why)
{
    QStringList args {program, QStringLiteral("clock"), QStringLiteral("probe")};
    if (brokerUrl.isEmpty())
        args << QStringLiteral("--udp") << udp;
    else
        args << QStringLiteral("--broker") << brokerUrl << QStringLiteral("--host") << QStringLiteral("cloud");
    args << QStringLiteral("--count") << QString::number(count) << QStringLiteral("--json");
    const LabRun r = lab.run(TwoHostLab::Vehicle, args, 60000);
    const QJsonObject o = QJsonDocument::fromJson(r.out.toUtf8()).object();
    if (r.exitCode != 0 || !o.contains(QStringLiteral("offset_ms"))) {
        *why = QStringLiteral("clock probe: exit %1: %2 %3").arg(r.exitCode).arg(r.out, r.err);
        return std::nullopt;
    }
    return Estimate {o.value(QStringLiteral("offset_ms")).toDouble(), o.value(QStringLiteral("uncertainty_ms")).toDouble(),
                     o.value(QStringLiteral("best_round_trip_ms")).toDouble()};
}
} // namespace TwoHostClocks
