#pragma once

#include <QObject>

class QAction;
class QActionGroup;
class QMenuBar;
class QToolBar;

namespace learnid {

/// The window's actions with icons and shortcuts, and the menus and tool bar that show them.
/// Buttons in the panels show the same actions, so one setEnabled() covers all.
class MainActions : public QObject
{
    Q_OBJECT

public:
    explicit MainActions(QObject *parent);

    void populate(QMenuBar *menuBar, QToolBar *toolBar);
    /// Checks the language entry; "" = system.
    void setLanguage(const QString &language);

    QAction *connectRobot;
    QAction *newSession;
    QAction *identifyFromLogs;
    QAction *learnPayload;
    QAction *openScenario;
    QAction *saveScenario;
    QAction *exportParameters;
    QAction *exportTrialCsv;
    QAction *exportPlot;
    QAction *exportReport;
    QAction *exportUrdf;
    QAction *quit;
    QAction *runTrial;
    QAction *runAll;
    QAction *stop;
    QAction *accept;
    QAction *apply;
    QAction *revert;
    QAction *about;
    QAction *aboutQt;
    QActionGroup *languages;

signals:
    /// The technician chose a language ("" = system); it takes effect at the next start.
    void languageChosen(const QString &language);
};

} // namespace learnid
