// SPDX-License-Identifier: MIT
#include "optionform.h"

#include <QComboBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QStyle>
#include <QToolButton>
#include <QVBoxLayout>

using namespace Qt::StringLiterals;

namespace {
QString sectionOf(const QString& path)
{
    const int dot = path.lastIndexOf(u'.');
    return dot < 0 ? QString() : path.left(dot);
}

QString keyOf(const QString& path)
{
    return path.mid(path.lastIndexOf(u'.') + 1);
}
} // namespace

OptionForm::OptionForm(OptionScope scope, const QStringList& excludedPaths, QWidget* parent)
    : QWidget(parent)
    , m_scope(scope)
{
    // One form, so that labels line up; each section ("tls", "advanced.mqtt", ...) starts with
    // its name as a heading row.
    auto* outer = new QVBoxLayout(this);
    outer->setContentsMargins(0, 0, 0, 0);
    auto* form = new QFormLayout;
    form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    outer->addLayout(form);
    QString current = u"\x01"_s;
    for (const OptionSpec& spec : OptionSchema::options(scope)) {
        if (excludedPaths.contains(spec.path))
            continue;
        const QString section = spec.extension ? tr("benchmarking suite") : sectionOf(spec.path);
        if (section != current) {
            auto* heading = new QLabel(u"<b>%1</b>"_s.arg(section.isEmpty() ? tr("general") : section), this);
            heading->setContentsMargins(0, form->rowCount() ? 8 : 0, 0, 0);
            form->addRow(heading);
            current = section;
        }
        buildRow(spec, this, form);
    }
    outer->addStretch(1);
}

void OptionForm::buildRow(const OptionSpec& spec, QWidget* parent, QFormLayout* layout)
{
    Row row;
    row.spec = &spec;
    auto* field = new QWidget(parent);
    auto* h = new QHBoxLayout(field);
    h->setContentsMargins(0, 0, 0, 0);
    const QString tip = OptionSchema::summary(spec)
        + (spec.defaultText.isEmpty() ? QString() : u"\n"_s + tr("Default: %1").arg(spec.defaultText))
        + (spec.ros2Only ? u"\n"_s + tr("Only understood by the ROS 2 mqtt_client.") : QString())
        + (spec.extension ? u"\n"_s + tr("Benchmarking suite extension; mqtt_client ignores it.")
                          : QString());
    if (spec.kind == OptionKind::Bool || spec.kind == OptionKind::Enum) {
        auto* combo = new QComboBox(field);
        combo->setObjectName(spec.path);
        connect(combo, &QComboBox::activated, this, [this, path = spec.path] { commitCombo(path); });
        row.editor = combo;
    } else {
        auto* edit = new QLineEdit(field);
        edit->setObjectName(spec.path);
        edit->setClearButtonEnabled(true);
        if (spec.secret)
            edit->setEchoMode(QLineEdit::PasswordEchoOnEdit);
        connect(edit, &QLineEdit::editingFinished, this, [this, path = spec.path] { commitLineEdit(path); });
        row.editor = edit;
        if (spec.kind == OptionKind::Path) {
            auto* browse = new QToolButton(field);
            browse->setText(u"…"_s);
            browse->setToolTip(tr("Choose a file"));
            connect(browse, &QToolButton::clicked, this, [this, edit, path = spec.path] {
                const QString file
                    = QFileDialog::getOpenFileName(this, tr("Choose %1").arg(path), edit->text());
                if (!file.isEmpty()) {
                    edit->setText(file);
                    commitLineEdit(path);
                }
            });
            h->addWidget(edit, 1);
            h->addWidget(browse);
        }
    }
    row.editor->setToolTip(tip);
    if (h->count() == 0)
        h->addWidget(row.editor, 1);
    row.marker = new QLabel(field);
    row.marker->setVisible(false);
    h->addWidget(row.marker);
    auto* label = new QLabel(keyOf(spec.path), parent);
    label->setToolTip(tip);
    label->setBuddy(row.editor);
    layout->addRow(label, field);
    m_rows.insert(spec.path, row);
    fill(m_rows[spec.path], QString(), false, false);
}

void OptionForm::fill(Row& row, const QString& value, bool mixed, bool isSet)
{
    row.shown = isSet ? value : QString();
    row.mixed = mixed;
    const OptionSpec& spec = *row.spec;
    if (auto* combo = qobject_cast<QComboBox*>(row.editor)) {
        combo->clear();
        const QString def = spec.defaultText.isEmpty() ? tr("not set") : spec.defaultText;
        combo->addItem(mixed ? tr("(mixed)") : tr("default (%1)").arg(def), QString());
        const QStringList values
            = spec.kind == OptionKind::Bool ? QStringList {u"true"_s, u"false"_s} : spec.enumValues;
        for (const QString& v : values)
            combo->addItem(v, v);
        if (isSet && !mixed) {
            int index = combo->findData(value);
            if (index < 0) { // e.g. "$(arg latched)" or "yes": keep what the file says
                combo->addItem(value, value);
                index = combo->count() - 1;
            }
            combo->setCurrentIndex(index);
        } else {
            combo->setCurrentIndex(0);
        }
    } else if (auto* edit = qobject_cast<QLineEdit*>(row.editor)) {
        const QString text = mixed ? QString() : row.shown;
        if (edit->text() != text) {
            edit->setText(text);
            edit->setCursorPosition(0); // show where a long value starts
        }
        edit->setPlaceholderText(
            mixed ? tr("(mixed)")
                  : (spec.defaultText.isEmpty() ? tr("not set") : tr("default: %1").arg(spec.defaultText)));
    }
}

void OptionForm::setBlocks(const QList<OptionBlock>& blocks)
{
    m_filling = true;
    for (auto it = m_rows.begin(); it != m_rows.end(); ++it) {
        const QString& path = it.key();
        QString value;
        bool isSet = false;
        bool mixed = false;
        for (int i = 0; i < blocks.size(); ++i) {
            const OptionValues& v = blocks[i].values;
            const QString text = v.has(path) ? v.text(path) : QString();
            if (i == 0) {
                value = text;
                isSet = v.has(path);
            } else if (text != value || v.has(path) != isSet) {
                mixed = true;
            }
        }
        fill(*it, value, mixed, isSet);
    }
    setEnabled(!blocks.isEmpty());
    m_filling = false;
}

void OptionForm::setProblems(const QList<Problem>& problems)
{
    for (Row& row : m_rows)
        row.marker->setVisible(false);
    for (const Problem& p : problems) {
        auto it = m_rows.find(p.field);
        if (it == m_rows.end())
            continue;
        const QStyle::StandardPixmap icon
            = p.severity == Severity::Error ? QStyle::SP_MessageBoxCritical : QStyle::SP_MessageBoxWarning;
        const int size = style()->pixelMetric(QStyle::PM_SmallIconSize);
        it->marker->setPixmap(style()->standardIcon(icon).pixmap(size, size));
        it->marker->setToolTip(p.message + (p.fix.isEmpty() ? QString() : u"\n→ "_s + p.fix));
        it->marker->setVisible(true);
    }
}

QWidget* OptionForm::editor(const QString& path) const
{
    const auto it = m_rows.constFind(path);
    return it == m_rows.cend() ? nullptr : it->editor;
}

void OptionForm::focusOption(const QString& path)
{
    if (QWidget* w = editor(path)) {
        w->setFocus(Qt::OtherFocusReason);
        if (auto* edit = qobject_cast<QLineEdit*>(w))
            edit->selectAll();
    }
}

void OptionForm::commitLineEdit(const QString& path)
{
    if (m_filling)
        return;
    Row& row = m_rows[path];
    auto* edit = qobject_cast<QLineEdit*>(row.editor);
    const QString text = edit->text().trimmed();
    if (row.mixed ? text.isEmpty() : text == row.shown)
        return;
    row.shown = text;
    row.mixed = false;
    emit optionEdited(path, text, text.isEmpty());
}

void OptionForm::commitCombo(const QString& path)
{
    if (m_filling)
        return;
    Row& row = m_rows[path];
    auto* combo = qobject_cast<QComboBox*>(row.editor);
    const QString value = combo->currentData().toString();
    if (row.mixed ? combo->currentIndex() == 0 : value == row.shown)
        return;
    row.shown = value;
    row.mixed = false;
    emit optionEdited(path, value, value.isEmpty());
}
