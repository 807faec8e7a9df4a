// SPDX-License-Identifier: MIT
#pragma once

#include <QDir>
#include <QProcess>
#include <QString>

/// A certificate authority, a server certificate for 127.0.0.1/localhost and a client
/// certificate, made with the openssl command line in a test's directory.
struct TlsFiles
{
    QString ca, caKey, serverCert, serverKey, clientCert, clientKey, otherCa;
    QString error;

    bool make(const QString& dir)
    {
        const QDir d(dir);
        ca = d.filePath(QStringLiteral("ca.pem"));
        caKey = d.filePath(QStringLiteral("ca.key"));
        serverCert = d.filePath(QStringLiteral("server.pem"));
        serverKey = d.filePath(QStringLiteral("server.key"));
        clientCert = d.filePath(QStringLiteral("client.pem"));
        clientKey = d.filePath(QStringLiteral("client.key"));
        otherCa = d.filePath(QStringLiteral("other-ca.pem"));
        const QString ext = d.filePath(QStringLiteral("san.ext"));
        QFile f(ext);
        if (!f.open(QIODevice::WriteOnly))
            return fail(QStringLiteral("cannot write ") + ext);
        f.write("subjectAltName=IP:127.0.0.1,DNS:localhost\n");
        f.close();
        const QString days = QStringLiteral("2");
        return run({QStringLiteral("req"), QStringLiteral("-x509"), QStringLiteral("-newkey"),
                    QStringLiteral("rsa:2048"), QStringLiteral("-nodes"), QStringLiteral("-keyout"), caKey,
                    QStringLiteral("-out"), ca, QStringLiteral("-days"), days, QStringLiteral("-subj"),
                    QStringLiteral("/CN=Bridgescope Test CA")})
            && run({QStringLiteral("req"), QStringLiteral("-x509"), QStringLiteral("-newkey"),
                    QStringLiteral("rsa:2048"), QStringLiteral("-nodes"), QStringLiteral("-keyout"),
                    d.filePath(QStringLiteral("other.key")), QStringLiteral("-out"), otherCa,
                    QStringLiteral("-days"), days, QStringLiteral("-subj"),
                    QStringLiteral("/CN=Somebody Else")})
            && signedCert(dir, QStringLiteral("server"), QStringLiteral("/CN=localhost"), ext, serverKey,
                          serverCert)
            && signedCert(dir, QStringLiteral("client"), QStringLiteral("/CN=bridgescope-client"), QString(),
                          clientKey, clientCert);
    }

private:
    bool fail(const QString& why)
    {
        error = why;
        return false;
    }

    bool run(const QStringList& args)
    {
        QProcess p;
        p.start(QStringLiteral("openssl"), args);
        if (!p.waitForFinished(60000) || p.exitCode() != 0)
            return fail(QStringLiteral("openssl %1: %2")
                            .arg(args.join(u' '), QString::fromLocal8Bit(p.readAllStandardError())));
        return true;
    }

    bool signedCert(const QString& dir, const QString& name, const QString& subject, const QString& ext,
                    const QString& key, const QString& cert)
    {
        const QString csr = QDir(dir).filePath(name + QStringLiteral(".csr"));
        QStringList sign = {QStringLiteral("x509"),
                            QStringLiteral("-req"),
                            QStringLiteral("-in"),
                            csr,
                            QStringLiteral("-CA"),
                            ca,
                            QStringLiteral("-CAkey"),
                            caKey,
                            QStringLiteral("-CAcreateserial"),
                            QStringLiteral("-out"),
                            cert,
                            QStringLiteral("-days"),
                            QStringLiteral("2")};
        if (!ext.isEmpty())
            sign << QStringLiteral("-extfile") << ext;
        return run({QStringLiteral("req"), QStringLiteral("-newkey"), QStringLiteral("rsa:2048"),
                    QStringLiteral("-nodes"), QStringLiteral("-keyout"), key, QStringLiteral("-out"), csr,
                    QStringLiteral("-subj"), subject})
            && run(sign);
    }
};
