// SPDX-License-Identifier: MIT
#pragma once

#include "base/result.h"

#include <optional>
#include <QString>
#include <type_traits>
#include <utility>

/// A Result as a test checks it: the value (nullopt on an error) with the error's text in
/// `*error` (left as it was on success), so that a test compares the very message a caller
/// shows. Only tests take the text apart from the value; the code returns Result.
template<typename T, typename = std::enable_if_t<!std::is_void_v<T>>>
std::optional<T> noted(Result<T> result, QString* error)
{
    if (!result) {
        *error = result.error().toString();
        return std::nullopt;
    }
    return std::move(result).value();
}

/// For a step that makes nothing: whether it succeeded, the error's text in `*error` when not.
inline bool noted(const Result<void>& result, QString* error)
{
    if (!result)
        *error = result.error().toString();
    return result.ok();
}
