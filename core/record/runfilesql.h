// SPDX-License-Identifier: MIT
#pragma once

// The SQLite connection the run file's writer and reader share (not part of the API).

#include "base/result.h"

#include <QSqlDatabase>
#include <QSqlError>
#include <QSqlQuery>
#include <QString>
#include <QUuid>

namespace RunSql {
using namespace Qt::StringLiterals;

/// A database connection of this thread that is removed again on destruction.
class Connection
{
public:
    explicit Connection(const QString& path, bool readOnly = false)
        : m_name(u"bridgescope-run-"_s + QUuid::createUuid().toString(QUuid::WithoutBraces))
    {
        QSqlDatabase db = QSqlDatabase::addDatabase(u"QSQLITE"_s, m_name);
        db.setDatabaseName(path);
        if (readOnly)
            db.setConnectOptions(u"QSQLITE_OPEN_READONLY"_s);
        m_open = db.open();
        if (!m_open)
            m_error = db.lastError().text();
    }
    ~Connection()
    {
        {
            QSqlDatabase db = QSqlDatabase::database(m_name, false);
            if (db.isOpen())
                db.close();
        }
        QSqlDatabase::removeDatabase(m_name);
    }
    QSqlDatabase db() const { return QSqlDatabase::database(m_name, false); }
    bool isOpen() const { return m_open; }
    QString error() const { return m_error; }

private:
    QString m_name;
    bool m_open = false;
    QString m_error;
};

inline Result<void> exec(QSqlQuery& q, const QString& sql)
{
    if (q.exec(sql))
        return {};
    return LocatedError {q.lastError().text()};
}

} // namespace RunSql
