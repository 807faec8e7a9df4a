// SPDX-License-Identifier: MIT
#include "passwordstore.h"

#include <qt6keychain/keychain.h>

namespace {
const QString kService = QStringLiteral("bridgescope");
} // namespace

PasswordStore::PasswordStore(QObject* parent)
    : QObject(parent)
{ }

void PasswordStore::store(const QString& key, const QString& password)
{
    auto* job = new QKeychain::WritePasswordJob(kService, this);
    job->setAutoDelete(true);
    job->setInsecureFallback(false);
    job->setKey(key);
    job->setTextData(password);
    connect(job, &QKeychain::Job::finished, this, [this, key](QKeychain::Job* j) {
        emit stored(key, j->error() == QKeychain::NoError, j->errorString());
    });
    job->start();
}

void PasswordStore::fetch(const QString& key)
{
    auto* job = new QKeychain::ReadPasswordJob(kService, this);
    job->setAutoDelete(true);
    job->setInsecureFallback(false);
    job->setKey(key);
    connect(job, &QKeychain::Job::finished, this, [this, key](QKeychain::Job* j) {
        auto* read = static_cast<QKeychain::ReadPasswordJob*>(j);
        const bool ok = j->error() == QKeychain::NoError;
        emit fetched(key, ok ? read->textData() : QString(), ok, j->errorString());
    });
    job->start();
}

void PasswordStore::remove(const QString& key)
{
    auto* job = new QKeychain::DeletePasswordJob(kService, this);
    job->setAutoDelete(true);
    job->setKey(key);
    job->start();
}
