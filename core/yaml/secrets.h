// SPDX-License-Identifier: MIT
#pragma once

#include <QByteArray>
#include <QString>

/// Keeps credentials out of what Bridgescope stores, logs and reports.
namespace Secrets {
/// What replaces a secret value.
inline constexpr char kRedacted[] = "<redacted>";

/// Whether a YAML key names a secret, as a whole word at its end: "pass", "password",
/// "key_password", "passphrase", "secret", "client_secret", "token", "api_key", "tls.password"
/// (not "passive", "bypass", "pass_count").
bool isSecretKey(const QString& key);

/// `url` without the user and password of its authority (`tcp://alice:pw@host` -> `tcp://host`).
/// For tcp, ssl, mqtt and mqtts, which have no path, the user info runs to the last '@', so that
/// a password with an unencoded '/', '?' or '#' is taken out too.
QString urlWithoutCredentials(const QString& url);
/// `url` as an error message may show it: everything between "://" and its last '@' replaced by
/// "<redacted>", whatever the URL's syntax. For a URL that failed to parse, which may hold a
/// password the parser did not recognise.
QString redactedUrl(const QString& url);

/// What a config that is not YAML is stored as: a YAML comment, nothing of the text.
inline constexpr char kNotYaml[]
    = "not stored: the bridge config is not valid YAML, so its credentials could not be found";

/// The YAML text with the value of every key that holds a secret (`pass`, `password`,
/// `key_password`, `passphrase`, `secret`, `token`, ...) replaced by "<redacted>", found through
/// yaml-cpp's parse of the text (quoting, escapes, continued lines, complex keys and aliases are
/// read as YAML reads them) and written anew by its emitter; a text without any secret is returned
/// as it is (comments and layout kept). A text that does not parse (or passes YamlLimits) becomes a
/// comment saying so (`parsed` false). `changed` tells whether anything was replaced or dropped.
QByteArray redactYaml(const QByteArray& yaml, bool* changed = nullptr, bool* parsed = nullptr);
} // namespace Secrets
