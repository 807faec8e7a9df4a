// SPDX-License-Identifier: MIT
#pragma once

#include "base/textpos.h"

#include <optional>
#include <QCoreApplication>
#include <QString>
#include <utility>

/// The one error type of Result: what is wrong, and where when a reader knows it (the file,
/// empty when the text came from elsewhere, and the place in it, invalid when the error is about
/// the whole text). A decoder's error is the message alone: `LocatedError {tr("…")}`, whose
/// toString() is that message.
struct LocatedError
{
    Q_DECLARE_TR_FUNCTIONS(LocatedError)
public:
    /// How the place is written: "line 3, column 7: …" (plans, configs) or "line 3: …" (rules).
    enum class Style { LineColumn, Line };

    QString message {}; ///< what is wrong, without the place
    TextPos pos {}; ///< zero-based, as yaml-cpp's marks; printed one-based
    QString file {};
    Style style = Style::LineColumn;
    /// What kind of error, for programs: "yaml-syntax", a YamlLimits code such as "yaml-too-deep",
    /// or empty (a reader's own error).
    QString code {};
    QString fix {}; ///< how to correct it, when the reader knows

    /// "FILE: line L, column C: message", each part present only when known.
    QString toString() const
    {
        QString text = message;
        if (pos.isValid())
            text = (style == Style::Line ? tr("line %1: %2").arg(pos.line + 1)
                                         : tr("line %1, column %2: %3").arg(pos.line + 1).arg(pos.column + 1))
                       .arg(message);
        return file.isEmpty() ? text : tr("%1: %2").arg(file, text);
    }
};

/// A value, or the error that kept a function from making it: what every function with a single
/// error returns (decoders, readers of files, writers). Functions that collect many problems
/// (validators) return their lists instead. Built from a value or a LocatedError.
template<typename T> class [[nodiscard]] Result
{
public:
    Result(T value)
        : m_value(std::move(value))
    { }
    Result(LocatedError error)
        : m_error(std::move(error))
    { }

    bool ok() const { return m_value.has_value(); }
    explicit operator bool() const { return ok(); }
    T& operator*() { return *m_value; }
    const T& operator*() const { return *m_value; }
    T* operator->() { return &*m_value; }
    const T* operator->() const { return &*m_value; }
    /// The value; only when ok().
    T& value() & { return *m_value; }
    const T& value() const& { return *m_value; }
    T&& value() && { return std::move(*m_value); }
    /// The value, or `fallback` when there is an error.
    T valueOr(T fallback) const& { return ok() ? *m_value : std::move(fallback); }
    T valueOr(T fallback) && { return ok() ? std::move(*m_value) : std::move(fallback); }
    /// The error; only when !ok().
    const LocatedError& error() const { return m_error; }

    /// The error with `file` named, when it has none yet.
    Result inFile(const QString& file) &&
    {
        if (!ok() && m_error.file.isEmpty())
            m_error.file = file;
        return std::move(*this);
    }

private:
    std::optional<T> m_value;
    LocatedError m_error;
};

/// A step that makes nothing but may fail: `Status()` (or `return {};`) is success.
template<> class [[nodiscard]] Result<void>
{
public:
    Result() = default;
    Result(LocatedError error)
        : m_error(std::move(error))
    { }
    bool ok() const { return !m_error.has_value(); }
    explicit operator bool() const { return ok(); }
    /// The error; an empty one when ok().
    const LocatedError& error() const
    {
        static const LocatedError none;
        return m_error ? *m_error : none;
    }

private:
    std::optional<LocatedError> m_error;
};

using Status = Result<void>;
