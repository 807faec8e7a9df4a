// SPDX-License-Identifier: MIT
#pragma once

#include <QByteArray>
#include <QString>

/// Keeps credentials out of what Bridgescope stores, logs and reports.
namespace Secrets {
/// What replaces a secret value.
inline constexpr char kRedacted[] = "<redacted>";

/// `url` without the user and password of its authority (`tcp://alice:pw@host` -> `tcp://host`).
QString urlWithoutCredentials(const QString& url);

/// The YAML text with the value of every key that holds a secret (`pass`, `password`,
/// `key_password`, `passphrase`, `secret`, `token`, ... in block or flow style, block scalars
/// included) replaced by "<redacted>"; everything else, comments and layout, is kept. `changed`
/// tells whether anything was replaced.
QByteArray redactYaml(const QByteArray& yaml, bool* changed = nullptr);
} // namespace Secrets
