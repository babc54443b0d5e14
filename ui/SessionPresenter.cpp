#include "ui/SessionPresenter.h"

#include "service/SessionController.h"
#include "session/TrialSeries.h"
#include "ui/ApplyPanel.h"
#include "ui/ApplyPreview.h"
#include "ui/ConvergenceChart.h"
#include "ui/ConvergenceTableModel.h"
#include "ui/MessageBar.h"
#include "ui/ParameterTableModel.h"
#include "ui/PreTrialCheckView.h"
#include "ui/RobotPanel.h"
#include "ui/RunPanel.h"
#include "ui/ScenarioForm.h"
#include "ui/TrackingErrorPlot.h"

namespace learnid {

SessionPresenter::SessionPresenter(SessionController *controller, Views views, QObject *parent)
    : QObject(parent)
    , m_controller(controller)
    , m_views(views)
{
    SessionController *c = m_controller;
    connect(c, &SessionController::opened, this, [this] {
        const SessionInfo &info = *m_controller->info();
        QStringList names;
        for (const ParameterInfo &p : info.parameters)
            names << p.name;
        m_views.form->setParameterNames(names);
        m_views.table->setParameters(info.parameters, info.truth);
        m_views.parameters->setParameters(info.parameters, info.truth);
        m_views.plot->clear();
        m_views.plot->setJointNames(info.jointNames);
        m_views.robot->setConnected(true, tr("connected: %1").arg(info.robotDescription));
    });
    connect(c, &SessionController::openFailed, this, [this](const QString &message) {
        m_views.robot->setConnected(false, tr("not connected"));
        m_views.message->showMessage(tr("Cannot start the session: %1").arg(message),
                                     MessageBar::Severity::Error);
    });
    connect(c, &SessionController::closed, this, [this] {
        m_views.robot->setConnected(false, tr("not connected"));
        m_views.check->clear(tr("Connect a robot to plan the first trial."));
    });
    connect(c, &SessionController::checkChanged, this, [this] {
        m_views.check->setCheck(*m_controller->lastCheck(), int(m_controller->history().size()));
    });
    connect(c, &SessionController::trialStarted, this, [this](int index, int) {
        m_views.run->setStatus(tr("Trial %1 running\u2026").arg(index));
    });
    connect(c, &SessionController::progress, this, [this](int index, int done, int total) {
        m_views.run->setTrialProgress(index, done, total);
    });
    connect(c, &SessionController::trialFinished, this,
            [this](const TrialResult &t, const QList<TrackingErrorCurve> &curves) {
                if (t.status() != TrialStatus::Refused)
                    m_views.plot->setTrialCurves(t.index, curves);
                if (t.learnedFromPartial()) {
                    m_views.run->trialDone(int(m_controller->estimates().size()) - 1);
                    m_views.message->showMessage(
                        tr("Trial %1 stopped: %2. Learned from its first %3 s (a partial "
                           "trial); the next trial runs with the new estimate.")
                            .arg(t.index)
                            .arg(t.record.message)
                            .arg(t.partialSamples * t.record.samplePeriod, 0, 'f', 3),
                        MessageBar::Severity::Info);
                } else if (t.learned()) {
                    m_views.run->trialDone(int(m_controller->estimates().size()) - 1);
                    if (t.record.lateSetpoints > 0) // the CAN robot: the PC missed deadlines
                        m_views.message->showMessage(
                            tr("Trial %1: %2.").arg(t.index).arg(t.message),
                            MessageBar::Severity::Info);
                } else if (t.status() == TrialStatus::Refused) { // nothing moved, nothing recorded
                    QString text = t.message;
                    if (!text.isEmpty())
                        text[0] = text[0].toUpper();
                    m_views.message->showMessage(text, MessageBar::Severity::Error);
                } else
                    m_views.message->showMessage(tr("Trial %1 %2: %3. Its data are kept.")
                                                     .arg(t.index)
                                                     .arg(trialStatusName(t.status()), t.message),
                                                 MessageBar::Severity::Error);
                // Tracked worse than the trial before; Run all stops after a partial trial.
                for (const QString &note : {t.worseTracking, t.seriesStop}) {
                    if (note.isEmpty())
                        continue;
                    QString text = note;
                    text[0] = text[0].toUpper();
                    m_views.message->showMessage(text + QLatin1Char('.'),
                                                 note == t.seriesStop ? MessageBar::Severity::Error
                                                                      : MessageBar::Severity::Info);
                }
            });
    connect(c, &SessionController::historyChanged, this, &SessionPresenter::refreshTables);
    connect(c, &SessionController::runFinished, this, [this](bool all) {
        m_views.run->setStatus(
            all ? tr("Finished; %1 estimate(s) learned.").arg(m_controller->estimates().size() - 1)
                : tr("Stopped; see the message above."));
    });
    connect(c, &SessionController::acceptedChanged, this, [this](int k) {
        m_views.apply->setAccepted(k);
        m_views.message->showMessage(tr("Estimate %1 accepted.").arg(k),
                                     MessageBar::Severity::Info);
    });
    connect(c, &SessionController::applied, this, [this](const Eigen::VectorXd &) {
        m_views.message->showMessage(tr("Parameters written to the robot and read back."),
                                     MessageBar::Severity::Success);
    });
    connect(c, &SessionController::operationFailed, this,
            [this](SessionOperation, const QString &text) {
                m_views.message->showMessage(text, MessageBar::Severity::Error);
            });
}

void SessionPresenter::refreshTables()
{
    const SessionController *c = m_controller;
    m_views.table->setFigures(c->estimateFigures());
    m_views.table->setHistory(c->history(), c->estimates());
    m_views.table->setAccepted(c->acceptedIndex());
    m_views.table->setApplied(c->appliedEstimateIndex());
    m_views.parameters->setEstimates(c->estimates(), c->history(), c->estimateFigures());
    m_views.parameters->setAccepted(c->acceptedIndex());
    if (c->info())
        m_views.chart->setData(c->info()->parameters, c->estimates(), c->info()->truth,
                               c->estimateFigures());
    m_views.apply->setEstimateCount(int(c->estimates().size()),
                                    proposedEstimate(c->history(), int(c->estimates().size())));
    const Eigen::VectorXd &stored = c->storedParameters();
    m_views.apply->setStored(
        stored.size() == 0
            ? tr("nothing applied yet")
            : tr("%1 (estimate %2)").arg(parameterSetText(stored)).arg(c->appliedEstimateIndex()));
}

} // namespace learnid
