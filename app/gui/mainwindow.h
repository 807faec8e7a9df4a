// SPDX-License-Identifier: MIT
#pragma once

#include <QMainWindow>

class ConfigDocument;
class DiscoverPage;
class ExperimentPage;
class LinksPage;
class WatchSession;
class MapPage;
class MeasurePage;
class MeasureSession;
class ReportsPage;
class LiveSession;
class LiveWatch;
class ConfigEditor;
class ConfigFileController;
class QLabel;
class QMenu;
class QTabWidget;
class QUndoStack;
class RecentFiles;

/// The main window: wires the pages, menus and status bar together and does nothing else.
class MainWindow : public QMainWindow
{
    Q_OBJECT
public:
    /// How often the figures of topics are said to their views (LiveSession::setFiguresInterval).
    static constexpr int kFiguresMs = 250;
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    ConfigDocument* document() const { return m_document; }
    ConfigEditor* configEditor() const { return m_configEditor; }
    ConfigFileController* files() const { return m_files; }
    LiveSession* session() const { return m_session; }
    DiscoverPage* discoverPage() const { return m_discover; }
    MeasurePage* measurePage() const { return m_measurePage; }
    MeasureSession* measure() const { return m_measure; }
    LinksPage* linksPage() const { return m_links; }
    WatchSession* watch() const { return m_watch; }
    QTabWidget* pages() const { return m_pages; }

    /// Brings back how the window was left (geometry, page, splitters, columns, filters) and keeps
    /// it when it closes. Not by default: tests and screenshots start from the same window.
    void rememberSession();
    /// Every shortcut of the window: (where, keys), as Help › Keyboard Shortcuts lists them.
    QList<std::pair<QString, QString>> shortcuts() const;
    void showUserGuide();
    void showShortcuts();
    /// About's text: the versions of Bridgescope, Qt, Paho, yaml-cpp and roscpp.
    static QString aboutText();
    /// Writes the window's state now (also done on close once rememberSession() was called).
    void saveSession() const;

    /// Where measurements (runs, suite CSV, bags) open: one on Measure and several on Reports
    /// (Show), or all on Reports (Compare: dropped on that page).
    enum class Measurements { Show, Compare };
    /// Opens each file where it belongs and shows the page of the first that opened: a bridge
    /// config on Map (more configs are watched on Links), a pipeline and a single run, suite CSV
    /// or bag on Measure, several of those on Reports, an experiment's folder on Experiments.
    /// Each goes among the recent files. Returns what could not be opened, a line each. Every file
    /// the window is given comes through here: drops, File › Open, Open Recent, the command line.
    QStringList openPaths(const QStringList& paths, Measurements measurements = Measurements::Show);
    /// openPaths(), saying what did not open in a (non-blocking) message box; returns it too.
    QStringList openAndReport(const QStringList& paths, Measurements measurements = Measurements::Show);

protected:
    void closeEvent(class QCloseEvent* event) override;
    void dragEnterEvent(class QDragEnterEvent* event) override;
    void dropEvent(class QDropEvent* event) override;

private:
    void createMenus();
    void watchTheMapConfig();
    void updateTitle();
    void updateProblemStatus();
    void updateRecentMenu(const QStringList& files);
    void chooseFiles();

    LiveWatch* m_live; ///< the live session, its watch and measurement
    LiveSession* m_session;
    MeasureSession* m_measure;
    ConfigDocument* m_document;
    QUndoStack* m_undo;
    RecentFiles* m_recent; ///< File › Open Recent
    ConfigFileController* m_files;
    QTabWidget* m_pages;
    DiscoverPage* m_discover;
    MapPage* m_map;
    MeasurePage* m_measurePage;
    ReportsPage* m_reports;
    WatchSession* m_watch;
    LinksPage* m_links;
    ExperimentPage* m_experiments;
    ConfigEditor* m_configEditor;
    QMenu* m_recentMenu = nullptr;
    QMenu* m_themeMenu = nullptr;
    QLabel* m_problemStatus;
    bool m_remember = false;
};
