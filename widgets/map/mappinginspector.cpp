// SPDX-License-Identifier: MIT
#include "mappinginspector.h"

#include "config/configdocument.h"
#include "config/mappingmodel.h"
#include "widgets/map/optionform.h"
#include "widgets/map/undocommands.h"

#include <QComboBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QScrollArea>
#include <QStackedWidget>
#include <QUndoStack>
#include <QVBoxLayout>

using namespace Qt::StringLiterals;

MappingInspector::MappingInspector(ConfigDocument* document, QUndoStack* undoStack, QWidget* parent)
    : QWidget(parent)
    , m_doc(document)
    , m_undo(undoStack)
{
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    m_pages = new QStackedWidget(this);
    layout->addWidget(m_pages);

    auto* empty = new QLabel(tr("Select a mapping to edit it, or add one with Insert."), m_pages);
    empty->setAlignment(Qt::AlignCenter);
    empty->setWordWrap(true);
    m_pages->addWidget(empty);
    auto* scroll = new QScrollArea(m_pages);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setWidget(createEditPage(scroll));
    m_pages->addWidget(scroll);

    connect(m_direction, &QComboBox::activated, this, &MappingInspector::setDirection);
    connect(m_rosTopic, &QLineEdit::editingFinished, this,
            [this] { commitTopic(u"ros_topic"_s, m_rosTopic); });
    connect(m_mqttTopic, &QLineEdit::editingFinished, this,
            [this] { commitTopic(u"mqtt_topic"_s, m_mqttTopic); });
    for (OptionForm* form : {m_outForm, m_inForm}) {
        connect(form, &OptionForm::optionEdited, this,
                [this, form](const QString& path, const QString& text, bool unset) {
                    applyOption(form->scope(), path, text, unset);
                });
    }
    followDocument();
    refresh();
}

/// The summary, direction and topics, the problems and the options of one direction.
QWidget* MappingInspector::createEditPage(QWidget* parent)
{
    auto* page = new QWidget(parent);
    auto* v = new QVBoxLayout(page);
    m_summary = new QLabel(page);
    m_summary->setWordWrap(true);
    v->addWidget(m_summary);
    auto* head = new QFormLayout;
    m_direction = new QComboBox(page);
    m_direction->setObjectName(u"direction"_s);
    m_direction->addItem(MappingModel::directionText(Direction::Ros2Mqtt));
    m_direction->addItem(MappingModel::directionText(Direction::Mqtt2Ros));
    m_rosTopic = new QLineEdit(page);
    m_rosTopic->setObjectName(u"ros_topic"_s);
    m_mqttTopic = new QLineEdit(page);
    m_mqttTopic->setObjectName(u"mqtt_topic"_s);
    head->addRow(tr("&Direction"), m_direction);
    head->addRow(tr("&ROS topic"), m_rosTopic);
    head->addRow(tr("M&QTT topic"), m_mqttTopic);
    v->addLayout(head);
    m_problems = new QLabel(page);
    m_problems->setWordWrap(true);
    m_problems->setTextFormat(Qt::PlainText);
    m_problems->setObjectName(u"problems"_s);
    v->addWidget(m_problems);
    m_forms = new QStackedWidget(page);
    const QStringList topics = {u"ros_topic"_s, u"mqtt_topic"_s};
    m_outForm = new OptionForm(OptionScope::Ros2Mqtt, topics, m_forms);
    m_inForm = new OptionForm(OptionScope::Mqtt2Ros, topics, m_forms);
    m_forms->addWidget(m_outForm);
    m_forms->addWidget(m_inForm);
    v->addWidget(m_forms, 1);
    return page;
}

/// An option edited in a form, applied to every selected mapping as one undoable step.
void MappingInspector::applyOption(OptionScope scope, const QString& path, const QString& text, bool unset)
{
    const OptionSpec* spec = OptionSchema::find(scope, path);
    applyToSelection(tr("Set %1").arg(path), [&](Mapping& m) {
        if (unset)
            m.unset(path);
        else if (spec && spec->kind == OptionKind::StringList) {
            QStringList items;
            for (const QString& item : text.split(u',', Qt::SkipEmptyParts))
                items << item.trimmed();
            m.block.values.setList(path, items);
        } else
            m.set(path, text);
    });
}

/// The inspector shows what the document holds now: edits, removals and a new file.
void MappingInspector::followDocument()
{
    connect(m_doc, &ConfigDocument::mappingChanged, this, [this](int row) {
        if (m_ids.contains(m_doc->mapping(row).id))
            refresh();
    });
    connect(m_doc, &ConfigDocument::problemsChanged, this, &MappingInspector::refresh);
    connect(m_doc, &ConfigDocument::mappingsRemoved, this, [this] {
        QList<quint64> still;
        for (quint64 id : std::as_const(m_ids)) {
            if (m_doc->rowOf(id) >= 0)
                still << id;
        }
        if (still != m_ids)
            setMappings(still);
    });
    connect(m_doc, &ConfigDocument::resetDone, this, [this] { setMappings({}); });
}

void MappingInspector::setMappings(const QList<quint64>& ids)
{
    m_ids = ids;
    refresh();
}

QList<Mapping> MappingInspector::selected() const
{
    QList<Mapping> out;
    for (quint64 id : m_ids) {
        const int row = m_doc->rowOf(id);
        if (row >= 0)
            out << m_doc->mapping(row);
    }
    return out;
}

void MappingInspector::refresh()
{
    if (m_refreshing)
        return;
    m_refreshing = true;
    const QList<Mapping> list = selected();
    m_pages->setCurrentIndex(list.isEmpty() ? 0 : 1);
    if (!list.isEmpty()) {
        const bool one = list.size() == 1;
        bool sameDirection = true;
        for (const Mapping& m : list)
            sameDirection = sameDirection && m.direction == list.first().direction;
        m_summary->setText(
            one ? QString() : tr("%1 mappings selected: a change applies to all of them.").arg(list.size()));
        m_summary->setVisible(!one);
        m_direction->setEnabled(sameDirection);
        m_direction->setCurrentIndex(sameDirection ? int(list.first().direction) : -1);
        m_rosTopic->setEnabled(one);
        m_mqttTopic->setEnabled(one);
        // Only touch text that changed, so that a cursor in the other field stays where it is.
        const QString ros = one ? list.first().rosTopic() : QString();
        const QString mqtt = one ? list.first().mqttTopic() : QString();
        if (m_rosTopic->text() != ros) {
            m_rosTopic->setText(ros);
            m_rosTopic->setCursorPosition(0);
        }
        if (m_mqttTopic->text() != mqtt) {
            m_mqttTopic->setText(mqtt);
            m_mqttTopic->setCursorPosition(0);
        }
        m_rosTopic->setPlaceholderText(one ? tr("e.g. /vehicle/points") : tr("(several)"));
        m_mqttTopic->setPlaceholderText(one ? tr("e.g. vehicle/points") : tr("(several)"));
        QList<OptionBlock> blocks;
        QList<Problem> problems;
        QStringList lines;
        for (const Mapping& m : list) {
            blocks << m.block;
            const QList<Problem> own = m_doc->problemsOf(m.id);
            problems += own;
            if (one) {
                for (const Problem& p : own)
                    lines << (p.severity == Severity::Error ? tr("Error: %1") : tr("Warning: %1"))
                                 .arg(p.message)
                            + (p.fix.isEmpty() ? QString() : u"\n  → "_s + p.fix);
            }
        }
        if (!one && !problems.isEmpty())
            lines << tr("Problems in the selection: %1").arg(problems.size());
        m_problems->setText(lines.join(u'\n'));
        m_problems->setVisible(!lines.isEmpty());
        m_forms->setVisible(sameDirection);
        if (sameDirection) {
            OptionForm* form = this->form(list.first().direction);
            m_forms->setCurrentWidget(form);
            form->setBlocks(blocks);
            form->setProblems(problems);
        }
    }
    m_refreshing = false;
}

void MappingInspector::applyToSelection(const QString& description,
                                        const std::function<void(Mapping&)>& change)
{
    const QList<Mapping> before = selected();
    QList<Mapping> after = before;
    bool any = false;
    for (int i = 0; i < after.size(); ++i) {
        change(after[i]);
        any = any || !after[i].sameContent(before[i]);
    }
    if (!any)
        return;
    const QString text
        = before.size() == 1 ? description : tr("%1 on %2 mappings").arg(description).arg(before.size());
    m_undo->push(new ConfigCommands::EditMappings(m_doc, before, after, text));
}

void MappingInspector::commitTopic(const QString& field, QLineEdit* edit)
{
    if (m_refreshing || m_ids.size() != 1)
        return;
    const QString text = edit->text().trimmed();
    applyToSelection(field == u"ros_topic"_s ? tr("Set ROS topic") : tr("Set MQTT topic"),
                     [&](Mapping& m) { m.set(field, text); });
}

void MappingInspector::setDirection(int index)
{
    if (m_refreshing || index < 0)
        return;
    const auto d = Direction(index);
    applyToSelection(tr("Change direction"), [d](Mapping& m) {
        if (m.direction == d)
            return;
        // Keep what the other direction understands too (qos, primitive, ...).
        Mapping turned = Mapping::create(d, m.rosTopic(), m.mqttTopic());
        turned.id = m.id;
        for (const QString& path : m.block.values.paths()) {
            if (OptionSchema::find(scopeOf(d), path))
                turned.block.values.copyFrom(m.block.values, path);
        }
        turned.block.extras = m.block.extras;
        m = turned;
    });
}

void MappingInspector::focusField(const QString& path)
{
    const QList<Mapping> list = selected();
    if (list.isEmpty())
        return;
    if (path == u"ros_topic"_s) {
        m_rosTopic->setFocus(Qt::OtherFocusReason);
        m_rosTopic->selectAll();
    } else if (path == u"mqtt_topic"_s) {
        m_mqttTopic->setFocus(Qt::OtherFocusReason);
        m_mqttTopic->selectAll();
    } else {
        form(list.first().direction)->focusOption(path);
    }
}
