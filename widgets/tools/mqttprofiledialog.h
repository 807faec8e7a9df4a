// SPDX-License-Identifier: MIT
#pragma once

#include "mqtt/mqttprofile.h"

#include <QDialog>

class QCheckBox;
class QComboBox;
class QLabel;
class QLineEdit;
class QSpinBox;

/// Edits a broker connection profile: URL, MQTT version, client id, keep-alive, session,
/// credentials, TLS files, subscriptions and history depth.
class MqttProfileDialog : public QDialog
{
    Q_OBJECT
public:
    explicit MqttProfileDialog(const MqttProfile& profile, QWidget* parent = nullptr);
    MqttProfile profile() const;
    /// Whether the password goes to the system keyring (it never goes anywhere else).
    bool rememberPassword() const;
    void accept() override;

private:
    QLineEdit* fileField(const QString& text, const QString& title);

    QLineEdit* m_name;
    QLineEdit* m_url;
    QComboBox* m_version;
    QLineEdit* m_clientId;
    QSpinBox* m_keepAlive;
    QCheckBox* m_clean;
    QLineEdit* m_user;
    QLineEdit* m_password;
    QCheckBox* m_remember;
    QLineEdit* m_ca;
    QLineEdit* m_cert;
    QLineEdit* m_key;
    QLineEdit* m_keyPassword;
    QCheckBox* m_verify;
    QLineEdit* m_filters;
    QCheckBox* m_sys;
    QSpinBox* m_history;
    QLabel* m_error;
};
