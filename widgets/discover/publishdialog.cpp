// SPDX-License-Identifier: MIT
#include "publishdialog.h"

#include "text/topicnames.h"
#include "base/wallclock.h"
#include "mqtt/mqttconnection.h"
#include "models/mqtttopictree.h"
#include "wire/payloadtext.h"
#include "wire/publishpayload.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QFontDatabase>
#include <QFormLayout>
#include <QJsonDocument>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QStandardItemModel>
#include <QTime>
#include <QVBoxLayout>

using namespace Qt::StringLiterals;

PublishDialog::PublishDialog(MqttConnection* connection, MqttTopicTree* topics, const QString& topic,
                             QWidget* parent)
    : QDialog(parent)
    , m_connection(connection)
    , m_topics(topics)
    , m_topic(new QLineEdit(topic, this))
    , m_qos(new QComboBox(this))
    , m_retained(new QCheckBox(tr("&Retained"), this))
    , m_format(new QComboBox(this))
    , m_payload(new QPlainTextEdit(this))
    , m_note(new QLabel(this))
    , m_status(new QLabel(this))
{
    setWindowTitle(tr("Publish to MQTT"));
    m_topic->setObjectName(u"publishTopic"_s);
    m_qos->setObjectName(u"publishQos"_s);
    m_retained->setObjectName(u"publishRetained"_s);
    m_format->setObjectName(u"publishFormat"_s);
    m_qos->addItems({u"0"_s, u"1"_s, u"2"_s});
    m_format->addItem(tr("Text"), int(Text));
    m_format->addItem(tr("JSON"), int(Json));
    m_format->addItem(tr("ROS message"), int(RosMessage));
    m_payload->setObjectName(u"publishPayload"_s);
    m_payload->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    m_payload->setTabChangesFocus(true);
    m_note->setWordWrap(true);
    m_status->setWordWrap(true);
    m_status->setObjectName(u"publishStatus"_s);
    m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);

    auto* form = new QFormLayout;
    form->addRow(tr("&Topic:"), m_topic);
    auto* options = new QHBoxLayout;
    options->addWidget(m_qos);
    options->addWidget(m_retained);
    options->addStretch(1);
    auto* qosLabel = new QLabel(tr("&QoS:"), this); // a row of a layout gets no buddy by itself
    qosLabel->setBuddy(m_qos);
    form->addRow(qosLabel, options);
    form->addRow(tr("&Format:"), m_format);
    auto* payloadLabel = new QLabel(tr("P&ayload:"), this);
    payloadLabel->setBuddy(m_payload);

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    m_publish = buttons->addButton(tr("&Publish"), QDialogButtonBox::ActionRole);
    m_publish->setObjectName(u"publishButton"_s);
    m_publish->setDefault(true);
    m_publish->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_Return));
    m_publish->setToolTip(tr("Publish (Ctrl+Enter)"));
    connect(m_publish, &QPushButton::clicked, this, &PublishDialog::publish);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

    auto* v = new QVBoxLayout(this);
    v->addLayout(form);
    v->addWidget(payloadLabel);
    v->addWidget(m_payload, 1);
    v->addWidget(m_note);
    v->addWidget(m_status);
    v->addWidget(buttons);
    resize(560, 460);

    connect(m_topic, &QLineEdit::textChanged, this, &PublishDialog::topicChanged);
    connect(m_format, &QComboBox::currentIndexChanged, this, &PublishDialog::formatChanged);
    topicChanged();
}

/// The formats the topic offers, and the payload to start from: its last one.
void PublishDialog::topicChanged()
{
    const QString topic = m_topic->text();
    const auto info = m_topics->topicData().info(topic);
    const bool typed = info && info->rosType && m_topics->topicData().registryFor(topic);
    auto* model = qobject_cast<QStandardItemModel*>(m_format->model());
    if (QStandardItem* item = model ? model->item(RosMessage) : nullptr)
        item->setEnabled(typed);
    m_format->setItemText(RosMessage,
                          typed ? tr("ROS message (%1)").arg(info->rosType->name) : tr("ROS message"));
    const auto* history = m_topics->topicData().history(topic);
    const QByteArray last = history && !history->empty() ? history->back().payload : QByteArray();
    Format want = Text;
    if (typed)
        want = RosMessage;
    else if (!last.isEmpty() && !QJsonDocument::fromJson(last).isNull())
        want = Json;
    if (m_format->currentIndex() == int(want))
        formatChanged();
    else
        m_format->setCurrentIndex(int(want));
}

void PublishDialog::formatChanged()
{
    const QString topic = m_topic->text();
    const auto info = m_topics->topicData().info(topic);
    const auto* history = m_topics->topicData().history(topic);
    const QByteArray last = history && !history->empty() ? history->back().payload : QByteArray();
    const auto format = Format(m_format->currentData().toInt());
    m_note->clear();
    if (format == RosMessage) {
        const auto registry = m_topics->topicData().registryFor(topic);
        if (info && info->rosType && registry) {
            const PublishPayload::Prefill pre = PublishPayload::rosMessage(*registry, *info->rosType, last);
            m_payload->setPlainText(pre.text);
            m_note->setText(tr("%1 as YAML or JSON, sent in ROS serialization as mqtt_client does%2. %3")
                                .arg(info->rosType->name,
                                     info->rosType->stamped ? tr(", after the send stamp") : QString(),
                                     pre.note));
        }
    } else if (m_shownFormat == RosMessage || m_payload->toPlainText().isEmpty()) {
        // The last payload, when it reads as text; binary payloads are not retyped by hand.
        if (PayloadText::isText(last) && last.size() <= 64 * 1024)
            m_payload->setPlainText(QString::fromUtf8(last));
        else
            m_payload->clear();
    }
    m_shownFormat = format;
}

void PublishDialog::setStatus(const QString& text, bool error)
{
    m_status->setText(error ? u"<font color=\"#b00020\">%1</font>"_s.arg(text.toHtmlEscaped())
                            : text.toHtmlEscaped());
}

bool PublishDialog::publish()
{
    const QString topic = m_topic->text();
    QString why;
    if (!TopicNames::isValidMqttTopic(topic, true, &why)) {
        setStatus(tr("Not sent: %1").arg(why), true);
        return false;
    }
    const auto format = Format(m_format->currentData().toInt());
    const auto info = m_topics->topicData().info(topic);
    const auto registry = m_topics->topicData().registryFor(topic);
    const Result<QByteArray> payload = PublishPayload::build(
        format == Text ? PublishPayload::Format::Text
                       : (format == Json ? PublishPayload::Format::Json : PublishPayload::Format::RosMessage),
        m_payload->toPlainText(), registry.get(), info && info->rosType ? &*info->rosType : nullptr,
        wallClockNs());
    if (!payload) {
        setStatus(tr("Not sent: %1").arg(payload.error().toString()), true);
        return false;
    }
    const bool retained = m_retained->isChecked();
    if (retained && m_topics->topicData().store().mayHoldRetained(topic)) {
        QMessageBox ask(QMessageBox::Question, tr("Replace the retained message"),
                        tr("The broker keeps a retained message for %1. Replace it?").arg(topic),
                        QMessageBox::Yes | QMessageBox::Cancel, this);
        ask.setDefaultButton(QMessageBox::Cancel);
        if (ask.exec() != QMessageBox::Yes) {
            setStatus(tr("Not sent: the retained message stays."), false);
            return false;
        }
    }
    if (!m_connection->publish(topic, *payload, m_qos->currentIndex(), retained, &why)) {
        setStatus(tr("Not sent: %1").arg(why), true);
        return false;
    }
    setStatus(tr("%1: published %n bytes to %2.", nullptr, int(payload->size()))
                  .arg(QTime::currentTime().toString(u"HH:mm:ss"_s), topic),
              false);
    return true;
}
