// SPDX-License-Identifier: MIT
#pragma once

#include "base/result.h"
#include "topics/topicgraph.h"

#include <optional>
#include <QCoreApplication>
#include <QList>
#include <QMetaType>
#include <QString>
#include <QStringList>
#include <QVariant>

/// The ROS master's XML-RPC API, spoken directly over TCP with a deadline on every call.
///
/// It needs no roscpp (which allows one master per process and waits for it without end), so a
/// dead or unreachable master costs at most the timeout, and the master can change at run time.
/// Calls block: use them on a worker thread.
class RosMasterApi
{
    Q_DECLARE_TR_FUNCTIONS(RosMasterApi)
public:
    explicit RosMasterApi(const QString& masterUri, const QString& callerId = QStringLiteral("/bridgescope"));

    /// Calls `method` and returns the master's value (the third element of [code, status, value]).
    Result<QVariant> call(const QString& method, const QVariantList& params, int timeoutMs) const;
    /// Calls `method` and returns the whole answer [code, status, value], a refusal (code != 1)
    /// included; an error when no answer came within `timeoutMs` or it was not one.
    Result<QVariantList> answer(const QString& method, const QVariantList& params, int timeoutMs) const;
    /// The most an answer may hold: a bigger one (a hostile server that never stops sending) is
    /// an error, not memory. A master's getSystemState of 100,000 topics is about 20 MiB.
    static constexpr qsizetype kMaxAnswerBytes = 256 * 1024 * 1024;
    Result<TopicGraph> graph(int timeoutMs) const;
    /// The master's last answers about the graph, byte for byte.
    struct GraphAnswers
    {
        QByteArray state; ///< getSystemState
        QByteArray types; ///< getTopicTypes
    };
    /// The graph, or nothing when the master answered byte for byte what `*previous` holds (an
    /// unchanged graph of 10,000 topics is not parsed again); `*previous` then holds the answers.
    Result<std::optional<TopicGraph>> graphIfChanged(int timeoutMs, GraphAnswers* previous) const;
    /// The body of the HTTP answer to `method`, not decoded.
    Result<QByteArray> rawAnswer(const QString& method, const QVariantList& params, int timeoutMs) const;
    Result<qint64> pid(int timeoutMs) const;

    /// An XML-RPC request body; a response body parsed into QVariant (arrays become QVariantList).
    static QByteArray encodeCall(const QString& method, const QVariantList& params);
    static Result<QVariant> decodeResponse(const QByteArray& body);
    /// http://host:port/ from ROS_MASTER_URI (default http://localhost:11311/).
    static QString defaultMasterUri();

private:
    static Result<QVariantList> tripleOf(const QString& method, const QByteArray& body);
    static Result<QVariant> valueOf(const QString& method, const QByteArray& body);
    static TopicGraph graphOf(const QVariant& state, const QVariant& types);
    QString m_uri;
    QString m_callerId;
};
