// SPDX-License-Identifier: MIT
#pragma once

#include "config/bridgeconfig.h"
#include "watch/watchsession.h"

#include <QSet>
#include <QWidget>

class EventLogModel;
class FleetView;
class QComboBox;
class QStackedWidget;
class LinkModel;
class LiveText;
class QLabel;
class QLayout;
class QLineEdit;
class QSortFilterProxyModel;
class QSystemTrayIcon;
class QTableView;
class QTreeWidget;
class QTreeWidgetItem;
class RateChart;
struct WatchEvent;

/// The Links page: every mapping of the watched configs as a link, with its health, rates, loss,
/// latency and a sparkline, grouped by bridge; the selected link's history; the event log.
///
/// The configs are those open on the Map page and any added here, listed with what watching each
/// would subscribe to; only those the user checks are watched (opening or editing one subscribes
/// to nothing), within WatchSession::kWindowLinkLimit links. Figures come from a
/// WatchSession on the window's live session, refreshed once a second: the table changes with one
/// dataChanged, so thousands of links stay fluid. An alert raised while the window is not active
/// is also a desktop notification.
class LinksPage : public QWidget
{
    Q_OBJECT
public:
    explicit LinksPage(WatchSession* watch, QWidget* parent = nullptr);
    ~LinksPage() override;

    /// Every config open on the Map page; they replace those given before. A watched config that
    /// is no longer among them is no longer watched.
    void setMapConfigs(const QList<WatchSession::Config>& configs);
    /// Adds the config files, watched when `watch` (within the limit); an error for one that
    /// cannot be read, or when watching them would pass the limit.
    Status addConfigFiles(const QStringList& paths, bool watch = false);
    /// Turns watching of the listed config `name` (its name, or its file) on or off; an error when
    /// there is no such config or watching it would pass the limit.
    Status setWatched(const QString& name, bool watched);
    /// The config in `file` is watched as soon as it is listed (the demo lab's own configs).
    void watchWhenListed(const QString& file);

    /// Shows every host's links from the Prometheus server at `url` (the fleet view) instead of
    /// this window's own watch.
    void showFleet(const QString& url);

    QTableView* eventView() const { return m_events; }
    LinkModel* linkModel() const { return m_model; }
    int notificationsShown() const { return m_notified; }

protected:
    void showEvent(QShowEvent* event) override;

private:
    /// "Links from: this window's watch | Prometheus server…" over the two views.
    QLayout* createSourceChoice(QWidget* local);
    QLayout* createBar();
    QWidget* createLinkTable();
    QWidget* createDetailPane();
    QWidget* createEventLog();
    QWidget* createConfigList();
    Status applyConfigs();
    void listConfigs();
    void showPlan();
    void configChecked(QTreeWidgetItem* item);
    void chooseConfigs();
    void editRules();
    void showDetail();
    void updateSummary();
    void notify(const WatchEvent& event);

    WatchSession* m_watch;
    LinkModel* m_model;
    EventLogModel* m_eventModel;
    QSortFilterProxyModel* m_proxy;
    QTableView* m_links = nullptr;
    QTableView* m_events = nullptr;
    QLineEdit* m_filter = nullptr;
    QLabel* m_summary = nullptr;
    QLabel* m_detailTitle = nullptr;
    /// The selected link's figures (its name is above them, in a label of its own).
    LiveText* m_detail = nullptr;
    RateChart* m_rateChart = nullptr;
    RateChart* m_latencyChart = nullptr;
    QSystemTrayIcon* m_tray = nullptr;
    QComboBox* m_sourceChoice = nullptr;
    QStackedWidget* m_sources = nullptr;
    FleetView* m_fleet = nullptr;
    /// A config listed: open on the Map page or added here, watched or not.
    struct Listed
    {
        WatchSession::Config config;
        bool added = false; ///< added on this page (else open on the Map page)
        bool watched = false;
    };
    QList<Listed> m_configs;
    QSet<QString> m_watchWhenListed; ///< files
    /// The configs listed, one row each with its check (watched) and counts.
    QTreeWidget* m_configList = nullptr;
    /// What watching the current config subscribes to, or why watching was refused.
    QLabel* m_plan = nullptr;
    int m_notified = 0;
};
