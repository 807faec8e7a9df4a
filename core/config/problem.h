// SPDX-License-Identifier: MIT
#pragma once

#include "config/bridgeconfig.h"

#include <QList>
#include <QMetaType>
#include <QString>

enum class Severity { Info, Warning, Error };

/// One finding about a config: where it is, what is wrong, and how to fix it.
struct Problem
{
    Severity severity = Severity::Error;
    QString code; ///< stable identifier of the rule, e.g. "duplicate-ros-topic"
    QString message; ///< what is wrong, naming the mapping
    QString fix; ///< how to fix it
    quint64 mappingId = 0; ///< the mapping it is about, 0 for settings or the file
    OptionScope scope = OptionScope::Broker; ///< for settings problems
    QString field; ///< the option path it is about, if any
    TextPos pos; ///< where in the file

    /// A problem about mapping `m` (none: the file or its settings), placed at its `field`.
    static Problem about(const Mapping* m, Severity severity, const QString& code, const QString& field,
                         const QString& message, const QString& fix);
    /// "FILE:LINE:COL: error: message (fix)", positions one-based; "FILE: error: …" when it has none.
    QString format(const QString& fileName) const;
    static QString severityName(Severity s);
};

bool hasErrors(const QList<Problem>& problems);
/// Whether two lists say the same, in the same order (severity, code, mapping, message and fix).
bool sameProblems(const QList<Problem>& a, const QList<Problem>& b);

Q_DECLARE_METATYPE(Problem)
