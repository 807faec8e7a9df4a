// SPDX-License-Identifier: MIT
#include "configtabs.h"

#include "widgets/common/severityiconproxy.h"
#include "widgets/map/configfilecontroller.h"

#include <QMap>

using namespace Qt::StringLiterals;

ConfigTabs::ConfigTabs(ConfigFileController* files, QWidget* parent)
    : QTabBar(parent)
    , m_files(files)
{
    setObjectName(u"configTabs"_s);
    setDocumentMode(true);
    setTabsClosable(true);
    setExpanding(false);
    setElideMode(Qt::ElideMiddle);
    setUsesScrollButtons(true);
    connect(m_files, &ConfigFileController::openConfigsChanged, this, &ConfigTabs::refresh);
    connect(this, &QTabBar::currentChanged, this, [this](int i) {
        if (!m_rebuilding && i >= 0)
            m_files->activate(i);
    });
    connect(this, &QTabBar::tabCloseRequested, this, [this](int i) { m_files->closeConfig(i); });
    refresh();
}

void ConfigTabs::refresh()
{
    m_rebuilding = true;
    while (count() > m_files->openCount())
        removeTab(count() - 1);
    m_iconState.fill(-2); // the tabs may stand for other configs now
    while (count() < m_files->openCount())
        addTab(QString());
    m_health.resize(m_files->openCount());
    for (int i = 0; i < count(); ++i)
        describe(i);
    setCurrentIndex(m_files->currentIndex());
    m_rebuilding = false;
}

void ConfigTabs::setHealth(int i, const QHash<quint64, MappingHealth>& health)
{
    if (i < 0 || i >= count())
        return;
    m_health.resize(count());
    m_health[i] = health;
    describe(i);
}

void ConfigTabs::describe(int i)
{
    // "•" while edits are unsaved, as editors mark a modified tab.
    const QString text = m_files->nameOf(i) + (m_files->isModified(i) ? u" •"_s : QString())
        + (m_files->isReadOnly(i) ? u' ' + tr("(read-only)") : QString());
    if (tabText(i) != text)
        setTabText(i, text);
    const QHash<quint64, MappingHealth>& health = m_health.value(i);
    const QString path = m_files->pathOf(i);
    QString tip = path.isEmpty() ? tr("A config not saved yet") : path;
    if (m_files->isModified(i))
        tip += u'\n' + tr("Unsaved edits");
    if (!health.isEmpty())
        tip += u'\n' + summary(health);
    if (tabToolTip(i) != tip)
        setTabToolTip(i, tip);
    // Set only when it changes: a new icon relays the bar out and repaints it with the page.
    const int state = health.isEmpty() ? -1 : int(worst(health));
    m_iconState.resize(count(), -2);
    if (m_iconState[i] != state) {
        m_iconState[i] = state;
        setTabIcon(i, state < 0 ? QIcon() : SeverityIconProxy::healthIcon(state));
    }
}

QString ConfigTabs::summary(const QHash<quint64, MappingHealth>& health)
{
    QMap<int, int> counts;
    for (const MappingHealth& h : health)
        ++counts[h.state];
    QStringList parts;
    const auto add = [&](MappingHealth::State s, const QString& words) {
        if (const int n = counts.value(s))
            parts << words.arg(n);
    };
    add(MappingHealth::Healthy, tr("%1 carry data"));
    add(MappingHealth::NoBridge, tr("%1 without a bridge"));
    add(MappingHealth::TypeMismatch, tr("%1 of another type"));
    add(MappingHealth::QosMismatch, tr("%1 whose QoS cannot match"));
    add(MappingHealth::Missing, tr("%1 missing"));
    add(MappingHealth::Idle, tr("%1 idle"));
    add(MappingHealth::Unknown, tr("%1 not seen yet"));
    return tr("%n mapping(s): %1", nullptr, int(health.size())).arg(parts.join(u", "_s));
}

MappingHealth::State ConfigTabs::worst(const QHash<quint64, MappingHealth>& health)
{
    // Worst first: what the user must act on, then what is only quiet.
    static const MappingHealth::State order[]
        = {MappingHealth::TypeMismatch, MappingHealth::QosMismatch, MappingHealth::NoBridge,
           MappingHealth::Missing,      MappingHealth::Idle,        MappingHealth::Healthy};
    for (MappingHealth::State s : order)
        for (const MappingHealth& h : health)
            if (h.state == s)
                return s;
    return MappingHealth::Unknown;
}
