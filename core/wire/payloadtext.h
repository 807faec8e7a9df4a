// SPDX-License-Identifier: MIT
#pragma once

#include <QByteArray>
#include <QCoreApplication>
#include <QString>

/// A payload made readable: as text, pretty JSON or hex, cut for display when large (and saying
/// so). What is stored is never changed.
class PayloadText
{
    Q_DECLARE_TR_FUNCTIONS(PayloadText)
public:
    enum class Mode { Auto, Text, Json, Hex };
    struct Rendered
    {
        QString text;
        QString note; ///< size, and whether and where the view is cut
        Mode mode = Mode::Text; ///< what Auto chose
    };
    static Rendered render(const QByteArray& payload, Mode mode, qsizetype limitBytes = 64 * 1024);
    static bool isText(const QByteArray& payload);
    static QString hexDump(const QByteArray& bytes);
};
