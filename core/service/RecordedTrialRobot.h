#pragma once

#include "robot/Robot.h"

#include <QList>
#include <QString>

namespace learnid {

/// A robot that answers with trials its own controller ran and logged (`learnid-cli learn`):
/// the k-th runTrial returns the k-th record, provided the plan the session asks it to run is
/// the plan the record was made with (the same plan-id, io/PlanCsv.h). Like the candump replay,
/// a session over it learns exactly what it learned when the trials came in one by one.
class RecordedTrialRobot final : public Robot
{
public:
    struct Run
    {
        QString planId;     ///< the plan the controller ran
        TrialRecord record; ///< what it logged
        QString source;     ///< the log file, for messages
    };

    explicit RecordedTrialRobot(QList<Run> runs = {});

    QString description() const override;
    /// The next run's record; a record Faulted with mismatch() set when the plan is not the one
    /// the run was made with or no run is left.
    TrialRecord runTrial(const TrialPlan &plan, const TrialMonitor &monitor) override;
    QString applyParameters(const Eigen::VectorXd &phi) override;
    Eigen::VectorXd storedParameters() const override { return {}; }

    /// Why a trial could not be answered (another plan than recorded); empty when all could.
    const QString &mismatch() const { return m_mismatch; }
    /// The plan-id of the plan the session asked for when it did not match (empty otherwise).
    const QString &askedPlanId() const { return m_askedPlanId; }

private:
    QList<Run> m_runs;
    int m_next = 0;
    QString m_mismatch;
    QString m_askedPlanId;
};

} // namespace learnid
