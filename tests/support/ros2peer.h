// SPDX-License-Identifier: MIT
#pragma once

// A ROS 2 node on the wire, built on Cyclone DDS (tests/ros2peer) and speaking as
// rmw_cyclonedds_cpp does: a process and a DDS stack of its own, not Bridgescope's raw-type
// participant, so that what the tests see is what such a node puts on the wire. (Bridgescope runs
// on Cyclone DDS too since issue 31: interoperability with Fast DDS nodes is not what these show.)

#include <memory>
#include <QElapsedTimer>
#include <QProcess>
#include <QStringList>
#include <QTest>
#include <QUdpSocket>

class Ros2Peer
{
public:
    /// A domain no other test on this host uses now: its first participant's discovery port is
    /// free. Tests pick from their own range so that parallel tests do not meet.
    static int freeDomain(int first, int last)
    {
        const int span = last - first + 1;
        const int start = int(QCoreApplication::applicationPid() % span);
        for (int i = 0; i < span; ++i) {
            const int domain = first + (start + i) % span;
            QUdpSocket probe;
            // RTPS: 7400 + 250 * domain, +10 for participant 0's metatraffic unicast
            if (probe.bind(QHostAddress::LocalHost, quint16(7400 + 250 * domain + 10)))
                return domain;
        }
        return first;
    }

    Ros2Peer(int domain, const QStringList& args)
    {
        m_process.setProcessChannelMode(QProcess::SeparateChannels);
        m_process.start(QStringLiteral(ROS2PEER),
                        QStringList {QStringLiteral("--domain"), QString::number(domain)} + args);
    }
    ~Ros2Peer() { terminate(); }

    /// Waits until the peer printed a line starting with `prefix` (all its output is kept).
    bool waitFor(const QString& prefix, int timeoutMs = 15000)
    {
        QElapsedTimer t;
        t.start();
        while (t.elapsed() < timeoutMs) {
            read();
            for (const QString& l : std::as_const(m_lines))
                if (l.startsWith(prefix))
                    return true;
            if (m_process.state() == QProcess::NotRunning && !m_process.bytesAvailable())
                return false;
            QTest::qWait(20);
        }
        return false;
    }
    QStringList lines()
    {
        read();
        return m_lines;
    }
    QString errors() { return QString::fromUtf8(m_process.readAllStandardError()); }
    /// SIGTERM: the peer deletes its entities, so DDS says goodbye.
    void terminate()
    {
        if (m_process.state() == QProcess::NotRunning)
            return;
        m_process.terminate();
        if (!m_process.waitForFinished(10000)) {
            m_process.kill();
            m_process.waitForFinished(2000);
        }
    }
    /// SIGKILL: the participant vanishes without a word; only its lease tells.
    void kill()
    {
        m_process.kill();
        m_process.waitForFinished(5000);
    }
    qint64 pid() const { return m_process.processId(); }

private:
    void read()
    {
        while (m_process.canReadLine())
            m_lines << QString::fromUtf8(m_process.readLine()).trimmed();
    }
    QProcess m_process;
    QStringList m_lines;
};
