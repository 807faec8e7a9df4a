// SPDX-License-Identifier: MIT
#include "settingsinspector.h"

#include "config/configdocument.h"
#include "widgets/map/optionform.h"
#include "widgets/map/undocommands.h"

#include <QLabel>
#include <QScrollArea>
#include <QUndoStack>
#include <QVBoxLayout>

SettingsInspector::SettingsInspector(ConfigDocument* document, QUndoStack* undoStack, QWidget* parent)
    : QWidget(parent)
    , m_doc(document)
    , m_undo(undoStack)
{
    auto* outer = new QVBoxLayout(this);
    outer->setContentsMargins(0, 0, 0, 0);
    auto* scroll = new QScrollArea(this);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    outer->addWidget(scroll);
    auto* page = new QWidget(scroll);
    auto* v = new QVBoxLayout(page);
    auto* brokerTitle = new QLabel(tr("<b>Broker</b>"), page);
    v->addWidget(brokerTitle);
    m_broker = new OptionForm(OptionScope::Broker, {}, page);
    v->addWidget(m_broker);
    auto* clientTitle = new QLabel(tr("<b>Client</b>"), page);
    v->addWidget(clientTitle);
    m_client = new OptionForm(OptionScope::Client, {}, page);
    v->addWidget(m_client);
    v->addStretch(1);
    scroll->setWidget(page);

    for (OptionForm* form : {m_broker, m_client}) {
        connect(form, &OptionForm::optionEdited, this,
                [this, form](const QString& path, const QString& text, bool unset) {
                    const OptionScope scope = form->scope();
                    const OptionBlock before = m_doc->config().block(scope);
                    OptionBlock after = before;
                    const OptionSpec* spec = OptionSchema::find(scope, path);
                    if (unset) {
                        after.values.remove(path);
                    } else if (spec && spec->kind == OptionKind::StringList) {
                        QStringList items;
                        for (const QString& item : text.split(u',', Qt::SkipEmptyParts))
                            items << item.trimmed();
                        after.values.setList(path, items);
                    } else {
                        after.values.setText(path, text);
                    }
                    if (!after.sameContent(before))
                        m_undo->push(new ConfigCommands::EditBlock(
                            m_doc, scope, before, after,
                            tr("Set %1.%2").arg(OptionSchema::scopeKey(scope), path)));
                });
    }
    connect(m_doc, &ConfigDocument::settingsChanged, this, &SettingsInspector::refresh);
    connect(m_doc, &ConfigDocument::resetDone, this, &SettingsInspector::refresh);
    connect(m_doc, &ConfigDocument::problemsChanged, this, &SettingsInspector::refresh);
    refresh();
}

OptionForm* SettingsInspector::form(OptionScope scope) const
{
    return scope == OptionScope::Broker ? m_broker : m_client;
}

void SettingsInspector::refresh()
{
    for (OptionForm* form : {m_broker, m_client}) {
        form->setBlocks({m_doc->config().block(form->scope())});
        QList<Problem> mine;
        for (const Problem& p : m_doc->problems()) {
            if (p.mappingId == 0 && p.scope == form->scope() && !p.field.isEmpty())
                mine << p;
        }
        form->setProblems(mine);
    }
}

void SettingsInspector::focusField(OptionScope scope, const QString& path)
{
    form(scope)->focusOption(path);
}
