// SPDX-License-Identifier: MIT
#include "recorddialog.h"

#include "record/runfile.h"

#include <QDateTime>
#include <QDialogButtonBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QVBoxLayout>

using namespace Qt::StringLiterals;

RecordDialog::RecordDialog(QWidget* parent)
    : QDialog(parent)
    , m_name(new QLineEdit(this))
    , m_notes(new QPlainTextEdit(this))
    , m_path(new QLineEdit(this))
{
    setWindowTitle(tr("Record a Run"));
    m_name->setText(tr("run %1").arg(QDateTime::currentDateTime().toString(u"yyyy-MM-dd HH-mm-ss"_s)));
    m_notes->setPlaceholderText(tr("What is special about this run: link, QoS, load, software versions…"));
    m_notes->setTabChangesFocus(true);
    m_path->setText(suggestedPath(m_name->text()));
    auto* browse = new QPushButton(tr("&Browse…"), this);
    auto* pathRow = new QHBoxLayout;
    pathRow->addWidget(m_path, 1);
    pathRow->addWidget(browse);
    auto* form = new QFormLayout;
    form->addRow(tr("&Name:"), m_name);
    form->addRow(tr("N&otes:"), m_notes);
    auto* pathLabel = new QLabel(tr("Run &file:"), this); // its buddy is the field, not the row
    pathLabel->setBuddy(m_path);
    form->addRow(pathLabel, pathRow);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    buttons->button(QDialogButtonBox::Ok)->setText(tr("&Record"));
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(buttons);
    connect(browse, &QPushButton::clicked, this, &RecordDialog::browse);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    // The file follows the name until the user picks one.
    connect(m_name, &QLineEdit::textEdited, this, [this](const QString& name) {
        if (m_path->isModified())
            return;
        m_path->setText(suggestedPath(name));
    });
    resize(560, 300);
}

QString RecordDialog::name() const
{
    return m_name->text().trimmed();
}

QString RecordDialog::notes() const
{
    return m_notes->toPlainText().trimmed();
}

QString RecordDialog::path() const
{
    return m_path->text().trimmed();
}

void RecordDialog::setPath(const QString& path)
{
    m_path->setText(path);
}

QString RecordDialog::suggestedPath(const QString& name)
{
    const QString dir
        = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation) + u"/Bridgescope runs"_s;
    QString base = name;
    base.replace(QRegularExpression(u"[^A-Za-z0-9._ -]+"_s), u"_"_s);
    if (base.isEmpty())
        base = u"run"_s;
    QString path = dir + u'/' + base + u'.' + RunFile::suffix();
    for (int i = 2; QFileInfo::exists(path); ++i)
        path = dir + u'/' + base + u'-' + QString::number(i) + u'.' + RunFile::suffix();
    return path;
}

void RecordDialog::browse()
{
    const QString path = QFileDialog::getSaveFileName(this, tr("Run File"), m_path->text(),
                                                      tr("Bridgescope runs (*.%1)").arg(RunFile::suffix()));
    if (!path.isEmpty()) {
        m_path->setText(path);
        m_path->setModified(true);
    }
}
