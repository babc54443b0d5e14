#pragma once

#include <QWidget>

class QAction;
class QLabel;
class QProgressBar;
class QToolButton;

namespace learnid {

/// Run trial / Run all / Stop and the progress over the trial and the series. The buttons show
/// the window's actions, so menus, shortcuts and buttons are enabled together.
class RunPanel : public QWidget
{
    Q_OBJECT

public:
    RunPanel(QAction *runTrial, QAction *runAll, QAction *stop, QWidget *parent = nullptr);

    /// A series of `count` trials starts (1 for a single trial).
    void startSeries(int count);
    void setTrialProgress(int trialIndex, int samplesDone, int samplesTotal);
    /// A trial of the series finished; completed trials so far.
    void trialDone(int doneInSeries);
    void setStatus(const QString &text);
    QString status() const;
    int trialProgressPercent() const;

private:
    QProgressBar *m_trial;
    QProgressBar *m_series;
    QLabel *m_status;
    int m_seriesCount = 1;
};

} // namespace learnid
