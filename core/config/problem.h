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

    /// "FILE:LINE:COL: error: message (fix)", positions one-based; "FILE: error: …" when it has none.
    QString format(const QString& fileName) const;
    static QString severityName(Severity s);
};

bool hasErrors(const QList<Problem>& problems);

Q_DECLARE_METATYPE(Problem)
