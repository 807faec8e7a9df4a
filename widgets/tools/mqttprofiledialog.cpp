// SPDX-License-Identifier: MIT
#include "mqttprofiledialog.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QSpinBox>
#include <QToolButton>
#include <QVBoxLayout>

using namespace Qt::StringLiterals;

MqttProfileDialog::MqttProfileDialog(const MqttProfile& p, QWidget* parent)
    : QDialog(parent)
{
    setWindowTitle(tr("Broker Connection"));
    auto* form = new QFormLayout;
    m_name = new QLineEdit(p.name, this);
    m_url = new QLineEdit(p.url, this);
    m_url->setPlaceholderText(u"tcp://localhost:1883"_s);
    m_url->setToolTip(tr("tcp://, mqtt:// (plain), ssl://, mqtts:// (TLS), ws://, wss:// (WebSocket)"));
    m_version = new QComboBox(this);
    m_version->addItem(u"MQTT 3.1.1"_s, 4);
    m_version->addItem(u"MQTT 5"_s, 5);
    m_version->setCurrentIndex(p.mqttVersion == 5 ? 1 : 0);
    m_clientId = new QLineEdit(p.clientId, this);
    m_clientId->setPlaceholderText(tr("random bridgescope-… id"));
    m_keepAlive = new QSpinBox(this);
    m_keepAlive->setRange(1, 65535);
    m_keepAlive->setSuffix(tr(" s"));
    m_keepAlive->setValue(p.keepAliveSeconds);
    m_clean = new QCheckBox(tr("Start a clean session"), this);
    m_clean->setChecked(p.cleanSession);
    m_user = new QLineEdit(p.username, this);
    m_password = new QLineEdit(p.password, this);
    m_password->setEchoMode(QLineEdit::Password);
    m_remember = new QCheckBox(tr("Keep the password in the system keyring (never in a file)"), this);
    m_ca = fileField(p.caFile, tr("CA certificate"));
    m_cert = fileField(p.certFile, tr("Client certificate"));
    m_key = fileField(p.keyFile, tr("Client key"));
    m_keyPassword = new QLineEdit(p.keyPassword, this);
    m_keyPassword->setEchoMode(QLineEdit::Password);
    m_verify = new QCheckBox(tr("Verify the broker's certificate and host name"), this);
    m_verify->setChecked(p.verifyServer);
    m_filters = new QLineEdit(p.filters.join(u", "_s), this);
    m_filters->setToolTip(tr("Topic filters to subscribe, separated by commas; # subscribes to everything."));
    m_sys = new QCheckBox(tr("Also subscribe $SYS/# (broker statistics)"), this);
    m_sys->setChecked(p.brokerStatistics);
    m_history = new QSpinBox(this);
    m_history->setRange(1, 10000);
    m_history->setValue(p.historyDepth);
    m_history->setSuffix(tr(" messages per topic"));

    form->addRow(tr("&Name:"), m_name);
    form->addRow(tr("&URL:"), m_url);
    form->addRow(tr("&Protocol:"), m_version);
    form->addRow(tr("&Client id:"), m_clientId);
    form->addRow(tr("&Keep-alive:"), m_keepAlive);
    form->addRow(QString(), m_clean);
    form->addRow(tr("&User:"), m_user);
    form->addRow(tr("Pass&word:"), m_password);
    form->addRow(QString(), m_remember);
    form->addRow(tr("C&A file:"), m_ca->parentWidget());
    form->addRow(tr("Cer&tificate:"), m_cert->parentWidget());
    form->addRow(tr("&Key file:"), m_key->parentWidget());
    form->addRow(tr("Key pass&word:"), m_keyPassword);
    form->addRow(QString(), m_verify);
    form->addRow(tr("&Subscribe:"), m_filters);
    form->addRow(QString(), m_sys);
    form->addRow(tr("&History:"), m_history);

    m_error = new QLabel(this);
    m_error->setWordWrap(true);
    m_error->setStyleSheet(u"color: #b00020"_s);
    m_error->hide();
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* v = new QVBoxLayout(this);
    v->addLayout(form);
    v->addWidget(m_error);
    v->addWidget(buttons);
}

QLineEdit* MqttProfileDialog::fileField(const QString& text, const QString& title)
{
    auto* box = new QWidget(this);
    auto* h = new QHBoxLayout(box);
    h->setContentsMargins(0, 0, 0, 0);
    auto* edit = new QLineEdit(text, box);
    auto* browse = new QToolButton(box);
    browse->setText(u"…"_s);
    browse->setToolTip(tr("Choose a file"));
    connect(browse, &QToolButton::clicked, this, [this, edit, title] {
        const QString file = QFileDialog::getOpenFileName(this, title, edit->text());
        if (!file.isEmpty())
            edit->setText(file);
    });
    h->addWidget(edit, 1);
    h->addWidget(browse);
    return edit;
}

MqttProfile MqttProfileDialog::profile() const
{
    // user:password@ typed into the URL fill the fields (when empty) and leave the URL.
    MqttProfile p = MqttProfile::fromUrl(m_url->text().trimmed());
    // A name copied from a URL with credentials would show (and be logged) with them.
    p.name = m_name->text().trimmed().isEmpty() ? p.url : MqttProfile::withoutCredentials(m_name->text().trimmed());
    p.mqttVersion = m_version->currentData().toInt();
    p.clientId = m_clientId->text().trimmed();
    p.keepAliveSeconds = m_keepAlive->value();
    p.cleanSession = m_clean->isChecked();
    if (!m_user->text().isEmpty() || p.username.isEmpty())
        p.username = m_user->text();
    if (!m_password->text().isEmpty() || p.password.isEmpty())
        p.password = m_password->text();
    p.caFile = m_ca->text().trimmed();
    p.certFile = m_cert->text().trimmed();
    p.keyFile = m_key->text().trimmed();
    p.keyPassword = m_keyPassword->text();
    p.verifyServer = m_verify->isChecked();
    p.filters.clear();
    for (const QString& f : m_filters->text().split(u',', Qt::SkipEmptyParts))
        p.filters << f.trimmed();
    p.brokerStatistics = m_sys->isChecked();
    p.historyDepth = m_history->value();
    return p;
}

bool MqttProfileDialog::rememberPassword() const
{
    return m_remember->isChecked();
}

void MqttProfileDialog::accept()
{
    if (const Status valid = profile().validate(); !valid) {
        m_error->setText(valid.error().toString());
        m_error->show();
        return;
    }
    QDialog::accept();
}
