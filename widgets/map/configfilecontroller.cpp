// SPDX-License-Identifier: MIT
#include "configfilecontroller.h"

#include "files/atomicfile.h"
#include "config/configdocument.h"
#include "config/configwriter.h"
#include "config/peerconfig.h"
#include "widgets/map/recentfiles.h"

#include <algorithm>
#include <QFileDialog>
#include <QFileInfo>
#include <QMessageBox>
#include <QUndoStack>

using namespace Qt::StringLiterals;

ConfigFileController::ConfigFileController(ConfigDocument* document, QUndoStack* undoStack,
                                           RecentFiles* recent, QWidget* dialogParent)
    : QObject(dialogParent)
    , m_doc(document)
    , m_undo(undoStack)
    , m_recent(recent)
    , m_parent(dialogParent)
    , m_open {m_doc->snapshot()}
{
    m_ask = [this](const QString& title, const QString& question) {
        return QMessageBox::question(m_parent, title, question, QMessageBox::Yes | QMessageBox::No,
                                     QMessageBox::No)
            == QMessageBox::Yes;
    };
}

void ConfigFileController::showError(const QString& title, const QString& message)
{
    emit statusMessage(message);
    if (m_parent && m_parent->isVisible())
        QMessageBox::warning(m_parent, title, message);
}

QString ConfigFileController::layoutFilter(ConfigLayout layout)
{
    switch (layout) {
    case ConfigLayout::Ros1:
        return tr("mqtt_client config, ROS 1 (*.yaml *.yml)");
    case ConfigLayout::Ros2:
        return tr("mqtt_client config, ROS 2 (*.yaml *.yml)");
    case ConfigLayout::MqttBridge:
        return tr("mqtt_bridge config (*.yaml *.yml)");
    }
    return QString();
}

bool ConfigFileController::openFile(const QString& path, QString* error)
{
    const QString absolute = QFileInfo(path).absoluteFilePath();
    for (int i = 0; i < openCount(); ++i) {
        if (pathOf(i) == absolute) {
            activate(i); // open already: shown, with its edits
            return true;
        }
    }
    const bool replace = currentIsBlank();
    const ConfigDocument::Snapshot before = m_doc->snapshot();
    const ConfigDocument::LoadResult r = m_doc->load(path); // leaves the document as it was on failure
    if (r.unreadable) {
        if (error)
            *error = r.error;
        else
            showError(tr("Cannot open the config"), r.error);
        return false;
    }
    if (!replace) {
        m_open[m_current] = before;
        m_open.append(ConfigDocument::Snapshot {});
        m_current = openCount() - 1;
    }
    // A file that reads but is no config (broken, too large) is shown read-only with its error,
    // in a tab of its own: the user sees where it is wrong instead of a refusal.
    if (!r.ok)
        m_doc->openReadOnly(path, r);
    m_undo->clear();
    m_recent->add(m_doc->filePath());
    if (!r.ok)
        emit statusMessage(tr("Opened %1 read-only: %2").arg(m_doc->filePath(), r.error));
    else
        emit statusMessage(tr("Opened %1 (mappings: %2)").arg(m_doc->filePath()).arg(m_doc->mappingCount()));
    emit openConfigsChanged();
    return true;
}

bool ConfigFileController::currentIsBlank() const
{
    return m_doc->filePath().isEmpty() && !m_doc->isModified() && m_doc->mappingCount() == 0;
}

void ConfigFileController::stashCurrentForAnother()
{
    m_open[m_current] = m_doc->snapshot();
    m_open.append(ConfigDocument::Snapshot {});
    m_current = openCount() - 1;
}

QString ConfigFileController::pathOf(int i) const
{
    return i == m_current ? m_doc->filePath() : m_open.value(i).path;
}

QString ConfigFileController::nameOf(int i) const
{
    const QString path = pathOf(i);
    return path.isEmpty() ? tr("untitled") : QFileInfo(path).fileName();
}

bool ConfigFileController::isReadOnly(int i) const
{
    return i == m_current ? m_doc->isReadOnly() : !m_open.value(i).readOnly.reason.isEmpty();
}

bool ConfigFileController::isModified(int i) const
{
    return i == m_current ? m_doc->isModified() : m_open.value(i).modified;
}

BridgeConfig ConfigFileController::configOf(int i) const
{
    return i == m_current ? m_doc->config() : m_open.value(i).current;
}

void ConfigFileController::activate(int i)
{
    if (i == m_current || i < 0 || i >= openCount())
        return;
    m_open[m_current] = m_doc->snapshot();
    m_current = i;
    m_doc->restore(m_open[i]);
    m_undo->clear();
    emit openConfigsChanged();
}

bool ConfigFileController::closeConfig(int i)
{
    if (i < 0 || i >= openCount())
        return false;
    activate(i);
    if (!maybeSave())
        return false;
    m_open.removeAt(i);
    if (m_open.isEmpty()) {
        m_doc->clear();
        m_open.append(m_doc->snapshot());
        m_current = 0;
    } else {
        m_current = std::min(i, openCount() - 1);
        m_doc->restore(m_open[m_current]);
    }
    m_undo->clear();
    emit openConfigsChanged();
    return true;
}

bool ConfigFileController::maybeSaveAll()
{
    for (int i = 0; i < openCount(); ++i) {
        if (!isModified(i))
            continue;
        activate(i);
        if (!maybeSave())
            return false;
    }
    return true;
}

bool ConfigFileController::saveTo(const QString& path, ConfigLayout layout)
{
    ConfigDocument::SaveResult r = m_doc->save(path, layout, false);
    if (r.status == ConfigDocument::SaveResult::NeedsRewrite) {
        const QString question = tr("The file cannot keep its comments and formatting: %1.\n\nSaving writes "
                                    "it anew (the previous file "
                                    "stays as %2.bak). Save anyway?")
                                     .arg(r.rewriteReason, QFileInfo(path).fileName());
        if (!m_ask(tr("Rewrite the file?"), question))
            return false;
        r = m_doc->save(path, layout, true);
    }
    if (r.status == ConfigDocument::SaveResult::Failed) {
        showError(tr("Cannot save the config"), tr("Nothing was changed on disk: %1").arg(r.error));
        return false;
    }
    m_undo->setClean();
    m_recent->add(m_doc->filePath());
    QString message = tr("Saved %1").arg(m_doc->filePath());
    if (!r.notes.isEmpty())
        message += u" ("_s + r.notes.join(u"; "_s) + u')';
    emit statusMessage(message);
    return true;
}

bool ConfigFileController::exportTo(const QString& path, ConfigLayout layout)
{
    QStringList notes;
    const QString text = ConfigWriter::write(m_doc->config(), layout, &notes);
    if (const Status written = AtomicFile::write(path, text.toUtf8()); !written) {
        showError(tr("Cannot export the config"), written.error().toString());
        return false;
    }
    emit statusMessage(tr("Exported %1 as %2%3")
                           .arg(path, layoutName(layout),
                                notes.isEmpty() ? QString() : u" ("_s + notes.join(u"; "_s) + u')'));
    return true;
}

bool ConfigFileController::writePeer(const QString& path, const QString& clientId)
{
    const PeerConfig::Result peer = PeerConfig::make(m_doc->config(), clientId);
    QStringList notes = peer.notes;
    const QString text = ConfigWriter::write(peer.config, m_doc->layout(), &notes);
    if (const Status written = AtomicFile::write(path, text.toUtf8()); !written) {
        showError(tr("Cannot write the peer config"), written.error().toString());
        return false;
    }
    emit statusMessage(tr("Wrote the peer config %1%2")
                           .arg(path, notes.isEmpty() ? QString() : u" ("_s + notes.join(u"; "_s) + u')'));
    return true;
}

bool ConfigFileController::maybeSave()
{
    if (!m_doc->isModified())
        return true;
    const auto answer = QMessageBox::warning(
        m_parent, tr("Unsaved changes"), tr("%1 has unsaved changes. Save them?").arg(nameOf(m_current)),
        QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
    if (answer == QMessageBox::Cancel)
        return false;
    return answer == QMessageBox::Discard || save();
}

bool ConfigFileController::newFile()
{
    if (currentIsBlank())
        return true;
    stashCurrentForAnother(); // the config shown so far stays open, with its edits
    m_doc->clear();
    m_undo->clear();
    emit openConfigsChanged();
    return true;
}

bool ConfigFileController::open()
{
    const QString dir = m_doc->filePath().isEmpty() ? QString() : QFileInfo(m_doc->filePath()).absolutePath();
    const QString path = QFileDialog::getOpenFileName(m_parent, tr("Open Bridge Config"), dir,
                                                      tr("YAML files (*.yaml *.yml);;All files (*)"));
    return !path.isEmpty() && openFile(path);
}

bool ConfigFileController::save()
{
    if (m_doc->filePath().isEmpty())
        return saveAs();
    return saveTo(m_doc->filePath(), m_doc->layout());
}

bool ConfigFileController::saveAs()
{
    const QList<ConfigLayout> layouts = {ConfigLayout::Ros1, ConfigLayout::Ros2};
    QStringList filters;
    for (ConfigLayout l : layouts)
        filters << layoutFilter(l);
    QString selected
        = layoutFilter(m_doc->layout() == ConfigLayout::MqttBridge ? ConfigLayout::Ros1 : m_doc->layout());
    QString start = m_doc->filePath().isEmpty() ? m_doc->suggestedPath() : m_doc->filePath();
    if (start.isEmpty())
        start = u"mqtt_client.yaml"_s;
    const QString path = QFileDialog::getSaveFileName(m_parent, tr("Save Bridge Config"), start,
                                                      filters.join(u";;"_s), &selected);
    if (path.isEmpty())
        return false;
    const ConfigLayout layout = layouts.value(int(filters.indexOf(selected)), ConfigLayout::Ros1);
    return saveTo(path, layout);
}

bool ConfigFileController::exportAs(ConfigLayout layout)
{
    const QFileInfo current(m_doc->filePath());
    const QString start = current.fileName().isEmpty()
        ? u"bridge_%1.yaml"_s.arg(layoutName(layout))
        : current.absoluteDir().filePath(current.completeBaseName() + u'_' + layoutName(layout) + u".yaml"_s);
    const QString path
        = QFileDialog::getSaveFileName(m_parent, tr("Export Bridge Config"), start, layoutFilter(layout));
    return !path.isEmpty() && exportTo(path, layout);
}

bool ConfigFileController::generatePeer()
{
    const QFileInfo current(m_doc->filePath());
    const QString start = current.fileName().isEmpty()
        ? u"peer.yaml"_s
        : current.absoluteDir().filePath(current.completeBaseName() + u"_peer.yaml"_s);
    const QString path = QFileDialog::getSaveFileName(m_parent, tr("Save Peer Config"), start,
                                                      layoutFilter(m_doc->layout()));
    if (path.isEmpty() || !writePeer(path, QString()))
        return false;
    if (m_ask(tr("Peer config written"), tr("Open the peer config %1 now?").arg(QFileInfo(path).fileName())))
        openFile(path); // beside this one
    return true;
}
