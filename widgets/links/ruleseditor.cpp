// SPDX-License-Identifier: MIT
#include "ruleseditor.h"

#include "files/atomicfile.h"
#include "yaml/yamlreader.h"

#include <QDialogButtonBox>
#include <QFileDialog>
#include <QFontDatabase>
#include <QLabel>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QVBoxLayout>

using namespace Qt::StringLiterals;

RulesEditor::RulesEditor(const WatchRules& rules, QWidget* parent)
    : QDialog(parent)
    , m_text(new QPlainTextEdit(this))
    , m_status(new QLabel(this))
    , m_rules(rules)
{
    setWindowTitle(tr("Watch Rules"));
    setObjectName(u"rulesEditor"_s);
    m_text->setObjectName(u"rulesText"_s);
    m_text->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    m_text->setPlainText(QString::fromUtf8(rules.toYaml()));
    m_status->setObjectName(u"rulesStatus"_s);
    m_status->setWordWrap(true);
    auto* help
        = new QLabel(tr("Settings: latency_p99_ms, min_rate_hz, min_rate_percent, max_loss_percent, "
                        "stall_seconds, stall_periods, source_stopped_seconds. A number is the alert "
                        "level; {warning: N, alert: N} sets both. Entries under links match a glob on the "
                        "ROS or MQTT topic, client:ID or config:NAME."),
                     this);
    help->setWordWrap(true);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Cancel, this);
    m_apply = buttons->addButton(tr("&Apply"), QDialogButtonBox::AcceptRole);
    m_apply->setObjectName(u"rulesApply"_s);
    QPushButton* load = buttons->addButton(tr("&Open…"), QDialogButtonBox::ActionRole);
    QPushButton* save = buttons->addButton(tr("&Save As…"), QDialogButtonBox::ActionRole);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(load, &QPushButton::clicked, this, &RulesEditor::load);
    connect(save, &QPushButton::clicked, this, &RulesEditor::save);
    connect(m_text, &QPlainTextEdit::textChanged, this, &RulesEditor::check);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(help);
    layout->addWidget(m_text, 1);
    layout->addWidget(m_status);
    layout->addWidget(buttons);
    check();
    resize(640, 480);
}

void RulesEditor::check()
{
    Result<WatchRules> rules = WatchRules::read(m_text->toPlainText().toUtf8());
    const QString error = rules.error().toString();
    m_rules = rules ? std::optional<WatchRules>(std::move(rules).value()) : std::nullopt;
    m_apply->setEnabled(bool(m_rules));
    m_status->setText(
        m_rules ? tr("Valid: %n override(s) after the defaults.", nullptr, int(m_rules->overrides.size()))
                : error);
    m_status->setStyleSheet(m_rules ? QString() : u"color: #b00020"_s);
}

void RulesEditor::load()
{
    const QString path = QFileDialog::getOpenFileName(this, tr("Open Watch Rules"), QString(),
                                                      tr("Rules (*.yaml *.yml);;All files (*)"));
    if (path.isEmpty())
        return;
    if (const Result<QByteArray> bytes = YamlReader::readFile(path); bytes)
        m_text->setPlainText(QString::fromUtf8(*bytes)); // checked as if typed
    else
        m_status->setText(bytes.error().toString());
}

void RulesEditor::save()
{
    const QString path = QFileDialog::getSaveFileName(this, tr("Save Watch Rules"), u"watch-rules.yaml"_s,
                                                      tr("Rules (*.yaml *.yml);;All files (*)"));
    if (path.isEmpty())
        return;
    if (const Status written = AtomicFile::write(path, m_text->toPlainText().toUtf8()); !written)
        m_status->setText(written.error().toString());
}
