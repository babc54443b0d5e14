#include "service/RecordedTrialRobot.h"

#include "io/PlanCsv.h"

#include <QCoreApplication>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(RecordedTrialRobot)
};

} // namespace

RecordedTrialRobot::RecordedTrialRobot(QList<Run> runs)
    : m_runs(std::move(runs))
{}

QString RecordedTrialRobot::description() const
{
    return Text::tr("the robot's own controller (plan and log files)");
}

TrialRecord RecordedTrialRobot::runTrial(const TrialPlan &plan, const TrialMonitor &monitor)
{
    TrialRecord record;
    record.samplePeriod = plan.desired.samplePeriod;
    record.status = TrialStatus::Faulted;
    record.stopCause = TrialStopCause::Other;
    if (m_next >= m_runs.size()) {
        record.message = m_mismatch =
            Text::tr("no logged trial is left for trial run %1").arg(m_next + 1);
        return record;
    }
    const Run &run = m_runs.at(m_next++);
    const QString asked = planIdOf(plan);
    if (asked != run.planId) {
        m_askedPlanId = asked;
        record.message = m_mismatch =
            Text::tr("%1 ran plan %2, but with this scenario the trial is planned as %3: the "
                     "scenario is not the one the plan was made with")
                .arg(run.source, run.planId, asked);
        return record;
    }
    if (monitor.progress)
        monitor.progress(run.record.samples(), plan.samples());
    return run.record;
}

QString RecordedTrialRobot::applyParameters(const Eigen::VectorXd &)
{
    return Text::tr("the robot's own controller takes its parameters its own way: give it the "
                    "estimate's parameter file");
}

} // namespace learnid
