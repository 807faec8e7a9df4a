// SPDX-License-Identifier: MIT
#pragma once

#include <memory>
#include <QProcess>
#include <QString>
#include <QStringList>

/// What a command run inside one of the lab's hosts did.
struct LabRun
{
    bool finished = false; ///< false: it did not end within its time (it was killed)
    int exitCode = -1;
    QString out;
    QString err;
};

/// Two "hosts" on this machine for the tests of experiments across hosts (issue 43): two network
/// namespaces with per-run names (bs-lab-<pid>-<start>-<n>-v / -c) joined by a veth pair with
/// private per-run addresses, `lo` up in each, and in each an sshd listening only on its veth
/// address and its lo, with a per-run host key and a per-run client key for root (no passwords).
///
/// Everything is torn down by down() (or the destructor) and also when the test process dies,
/// however it dies: a guard process outside the test's process group reads a pipe from the test
/// and, when the pipe closes, kills every process left in both namespaces, deletes them and
/// removes the lab's folder. up() also removes the namespaces of earlier runs whose process is
/// gone (in case their guard was killed too).
///
/// Needs root, `ip netns` and /usr/sbin/sshd; up() says why not in skipReason() where the machine
/// cannot (the test then QSKIPs, see TWOHOSTLAB_UP_OR_SKIP).
class TwoHostLab
{
public:
    enum Side { Vehicle = 0, Cloud = 1 };

    TwoHostLab();
    ~TwoHostLab();
    TwoHostLab(const TwoHostLab&) = delete;
    TwoHostLab& operator=(const TwoHostLab&) = delete;

    /// Builds the lab. False with skipReason() set when this machine cannot (not root, no
    /// namespaces, no sshd), or with errorString() set when building it failed.
    bool up();
    /// Tears everything down and waits until it is gone. Idempotent.
    void down();
    bool isUp() const { return m_up; }
    QString skipReason() const { return m_skipReason; }
    QString errorString() const { return m_error; }

    QString netns(Side side) const;
    QString address(Side side) const; ///< the side's veth IPv4 address (10.X.Y.1 or .2)
    QString sshUrl(Side side) const; ///< ssh://root@ADDRESS
    QString clientKey() const; ///< the per-run private key authorized on both sides
    QString knownHosts() const; ///< both sides' host keys, by their veth and lo addresses
    /// An executable that runs OpenSSH inside `from`'s namespace with the lab's client config
    /// (key, known hosts, BatchMode); give it to RemoteHostOptions::sshProgram.
    QString sshProgram(Side from = Vehicle) const;
    /// An address on the veth's subnet side that drops every packet silently (connects time out).
    QString silentAddress() const;

    /// argv run inside `side`'s namespace (ip netns exec NS argv...).
    QStringList inNamespace(Side side, const QStringList& argv) const;
    /// Runs argv inside `side`'s namespace and waits at most timeoutMs (then kills it).
    LabRun run(Side side, const QStringList& argv, int timeoutMs = 10000) const;
    /// Starts a long-running argv inside `side`'s namespace (a broker on one side, a clock
    /// service), its output in the lab's folder as NAME.log; it gets SIGTERM if the test process
    /// dies, and the lab's teardown kills what is left. Null with errorString() when it does not start.
    std::unique_ptr<QProcess> startProcess(Side side, const QString& name, const QStringList& argv);
    /// The log of a process startProcess() started.
    QString log(const QString& name) const;
    /// Limits the rate out of `side`'s veth with tc tbf (e.g. "10mbit"); false with errorString().
    bool setRate(Side side, const QString& rate);
    /// Pids of every process inside `side`'s namespace.
    QList<qint64> pids(Side side) const;
    /// Pids of sshd listeners the lab started (from their pid files), 0 where none.
    qint64 sshdPid(Side side) const;

    /// Every bs-lab-* namespace on the machine now.
    static QStringList labNamespaces();
    /// Removes namespaces of lab runs whose process is gone (killing what is left in them).
    static int removeStale();

private:
    bool canRun();
    bool makeKeys();
    bool makeNetwork();
    bool startSshd(Side side);
    bool startGuard();
    bool fail(const QString& what);
    QString path(const QString& name) const;

    bool m_up = false;
    QString m_skipReason;
    QString m_error;
    QString m_dir;
    QString m_names[2];
    QString m_addresses[2];
    QString m_silent;
    std::unique_ptr<QProcess> m_guard;
};

/// Builds `lab` or ends the test: QSKIP with the reason where the machine cannot, QFAIL otherwise.
#define TWOHOSTLAB_UP_OR_SKIP(lab)                                                                           \
    do {                                                                                                     \
        if (!(lab).up()) {                                                                                   \
            if (!(lab).skipReason().isEmpty())                                                               \
                QSKIP(qPrintable(u"two-host lab unavailable: " + (lab).skipReason()));                       \
            QFAIL(qPrintable(u"two-host lab: " + (lab).errorString()));                                      \
        }                                                                                                    \
    } while (false)
