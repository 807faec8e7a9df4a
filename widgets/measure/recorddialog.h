// SPDX-License-Identifier: MIT
#pragma once

#include <QDialog>

class QLineEdit;
class QPlainTextEdit;

/// Asks for what a new recording needs: a name, notes, and the run file to write.
class RecordDialog : public QDialog
{
    Q_OBJECT
public:
    explicit RecordDialog(QWidget* parent = nullptr);

    QString name() const;
    QString notes() const;
    QString path() const;
    void setPath(const QString& path);
    /// A file name that does not exist yet in the user's runs folder.
    static QString suggestedPath(const QString& name);

private:
    void browse();

    QLineEdit* m_name;
    QPlainTextEdit* m_notes;
    QLineEdit* m_path;
};
