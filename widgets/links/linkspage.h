// SPDX-License-Identifier: MIT
#pragma once

#include "config/bridgeconfig.h"

#include <QWidget>

class EventLogModel;
class LinkModel;
class LiveText;
class QLabel;
class QLayout;
class QLineEdit;
class QSortFilterProxyModel;
class QSystemTrayIcon;
class QTableView;
class RateChart;
class WatchSession;
struct WatchEvent;

/// The Links page: every mapping of the watched configs as a link, with its health, rates, loss,
/// latency and a sparkline, grouped by bridge; the selected link's history; the event log.
///
/// The configs are the one open on the Map page and any added here. Figures come from a
/// WatchSession on the window's live session, refreshed once a second: the table changes with one
/// dataChanged, so thousands of links stay fluid. An alert raised while the window is not active
/// is also a desktop notification.
class LinksPage : public QWidget
{
    Q_OBJECT
public:
    explicit LinksPage(WatchSession* watch, QWidget* parent = nullptr);
    ~LinksPage() override;

    /// The config open on the Map page (replaces the previous one; empty name: none).
    void setMapConfig(const QString& name, const BridgeConfig& config);
    /// Every config open on the Map page, by name; they replace those given before.
    void setMapConfigs(const QList<std::pair<QString, BridgeConfig>>& configs);
    /// Adds the config files; false with `error` for one that cannot be read.
    bool addConfigFiles(const QStringList& paths, QString* error = nullptr);

    QTableView* linkView() const { return m_links; }
    QTableView* eventView() const { return m_events; }
    LinkModel* linkModel() const { return m_model; }
    EventLogModel* eventModel() const { return m_eventModel; }
    QLabel* summaryLabel() const { return m_summary; }
    /// The selected link's figures (its name is above them, in a label of its own).
    LiveText* detailLabel() const { return m_detail; }
    int notificationsShown() const { return m_notified; }

protected:
    void showEvent(QShowEvent* event) override;

private:
    QLayout* createBar();
    QWidget* createLinkTable();
    QWidget* createDetailPane();
    QWidget* createEventLog();
    void applyConfigs();
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
    LiveText* m_detail = nullptr;
    RateChart* m_rateChart = nullptr;
    RateChart* m_latencyChart = nullptr;
    QSystemTrayIcon* m_tray = nullptr;
    QList<std::pair<QString, BridgeConfig>> m_mapConfigs; ///< those open on the Map page
    QList<std::pair<QString, BridgeConfig>> m_added;
    int m_notified = 0;
};
