// SPDX-License-Identifier: MIT
#pragma once

#include <QUrl>
#include <QWidget>

class FleetModel;
class FleetSource;
class PasswordStore;
class QLabel;
class QLineEdit;
class QSortFilterProxyModel;
class QTableView;
class QTimer;
class RateChart;

/// The Links page's fleet view: every host's links from a Prometheus server (FleetSource),
/// refreshed every 5 s without blocking, the selected link's last 15 minutes from query_range.
/// It subscribes to nothing on any broker or master. The server's URL and user are remembered in
/// the settings, its password only in the system keyring (PasswordStore), like broker profiles'.
/// When the server cannot be reached, the status line says so and the links stay as they were:
/// the window's own outage is not drawn as links going down.
class FleetView : public QWidget
{
    Q_OBJECT
public:
    static constexpr int kRefreshMs = 5000;
    static constexpr double kHistoryMinutes = 15;
    /// Rows measured to fit a column (QHeaderView::resizeContentsPrecision; Qt's default is 1,000).
    static constexpr int kFitRows = 200;

    explicit FleetView(QWidget* parent = nullptr);
    ~FleetView() override;

    /// Reads the server from `url` (refused with the reason in the status line when it is not an
    /// http or https URL), remembers it, keeps a given password in the keyring, and starts refreshing.
    bool connectTo(const QString& url, const QString& user = {}, const QString& password = {});
    /// The server remembered in the settings, its password fetched from the keyring first.
    void connectToRemembered();
    /// Stops refreshing (the page shows the window's own watch).
    void stop();
    bool isRefreshing() const;

    FleetSource* source() const { return m_source; }

private:
    QWidget* createBar();
    QWidget* createDetail();
    void refreshed();
    void showHistory();
    static QString keyringKey(const QString& url, const QString& user);

    FleetSource* m_source;
    FleetModel* m_model;
    QSortFilterProxyModel* m_proxy;
    PasswordStore* m_passwords;
    QTimer* m_timer;
    QLineEdit* m_url = nullptr;
    QLineEdit* m_user = nullptr;
    QLineEdit* m_password = nullptr;
    QLabel* m_status = nullptr;
    QTableView* m_table = nullptr;
    QLabel* m_detailTitle = nullptr;
    RateChart* m_rateChart = nullptr;
    RateChart* m_latencyChart = nullptr;
    quint64 m_historyAsked = 0;
};
