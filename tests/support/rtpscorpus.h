// SPDX-License-Identifier: MIT
#pragma once

// Hostile datagrams for a ROS 2 domain: Fast DDS's regression datagrams and Cyclone DDS's RTPS
// fuzzing seeds (tests/data/rtps/README.md), sent to the domain's RTPS ports on 127.0.0.1, and a
// seeded random RTPS flood.

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QList>
#include <QRandomGenerator>
#include <QTest>
#include <QUdpSocket>

namespace RtpsCorpus {

/// The domain the hostile tests use: one no other test picks, so that their datagrams reach only
/// the participants of the test that sends them.
inline constexpr int kFirstDomain = 231;
inline constexpr int kLastDomain = 232;

/// The RTPS ports of a domain (PB 7400, DG 250, PG 2, d0..d3 0, 10, 1, 11): discovery multicast
/// and user multicast, and the unicast ports of the first participant indices.
inline QList<quint16> ports(int domain)
{
    const int base = 7400 + 250 * domain;
    QList<quint16> out {quint16(base), quint16(base + 1)};
    for (int i = 0; i < 4; ++i)
        out << quint16(base + 10 + 2 * i) << quint16(base + 11 + 2 * i);
    return out;
}

/// The datagrams of one project's folder ("fastdds", "cyclonedds"), by name.
inline QList<QByteArray> load(const QString& project)
{
    QList<QByteArray> out;
    const QDir dir(QStringLiteral(BRIDGESCOPE_RTPS_CORPUS) + u'/' + project);
    const QStringList files = dir.entryList(QDir::Files, QDir::Name);
    for (const QString& f : files) {
        QFile file(dir.filePath(f));
        if (!f.endsWith(QLatin1String(".md")) && file.open(QIODevice::ReadOnly))
            out << file.readAll();
    }
    return out;
}

/// Sends every datagram three times to every RTPS port of the domain, then `flood` random ones
/// ("RTPS" and a random rest); the event loop runs meanwhile. Returns how many were sent.
inline int send(int domain, const QList<QByteArray>& datagrams, int flood)
{
    QUdpSocket socket;
    int sent = 0;
    const QList<quint16> all = ports(domain);
    for (qsizetype i = 0; i < datagrams.size(); ++i) {
        const QByteArray& d = datagrams[i];
        for (int round = 0; round < 3; ++round)
            for (quint16 port : all)
                if (socket.writeDatagram(d, QHostAddress::LocalHost, port) == d.size())
                    ++sent;
        // the first ten (Fast DDS's) each get time to act; the rest a moment now and then
        if (i < 10 || i % 16 == 0)
            QTest::qWait(i < 10 ? 100 : 20);
    }
    QRandomGenerator random(20261127);
    for (int i = 0; i < flood; ++i) {
        QByteArray d(int(random.bounded(8, 600)), Qt::Uninitialized);
        for (char& c : d)
            c = char(random.bounded(256));
        d = QByteArray("RTPS\x02\x01\x01\x10", 8) + d;
        if (socket.writeDatagram(d, QHostAddress::LocalHost, all[int(random.bounded(all.size()))]) == d.size())
            ++sent;
        if (i % 200 == 0)
            QCoreApplication::processEvents();
    }
    return sent;
}

} // namespace RtpsCorpus
