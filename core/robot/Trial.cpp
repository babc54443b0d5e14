#include "robot/Trial.h"

#include <QCoreApplication>

namespace learnid {

Eigen::MatrixXd feedforwardTorque(const RobotModel &model, const JointTrajectory &desired,
                                  const Eigen::VectorXd &phi)
{
    Eigen::MatrixXd tau(model.dof(), desired.samples());
    for (int k = 0; k < desired.samples(); ++k)
        model.inverseDynamics(desired.q.col(k), desired.qd.col(k), desired.qdd.col(k), phi,
                              tau.col(k));
    return tau;
}

QString trialStatusName(TrialStatus status)
{
    switch (status) {
    case TrialStatus::Completed:
        return QCoreApplication::translate("TrialStatus", "completed");
    case TrialStatus::Aborted:
        return QCoreApplication::translate("TrialStatus", "aborted");
    case TrialStatus::Faulted:
        return QCoreApplication::translate("TrialStatus", "robot fault");
    case TrialStatus::Cancelled:
        return QCoreApplication::translate("TrialStatus", "cancelled");
    case TrialStatus::Refused:
        return QCoreApplication::translate("TrialStatus", "refused");
    }
    return {};
}

} // namespace learnid
