#include "ui/SessionInfo.h"

#include "robot/SimulatedRobot.h"
#include "session/TrialResult.h"
#include "ui/TrackingErrorData.h"

namespace learnid {

void registerSessionMetaTypes()
{
    qRegisterMetaType<learnid::SessionInfo>();
    qRegisterMetaType<learnid::TrialResult>();
    qRegisterMetaType<learnid::PreTrialCheck>();
    qRegisterMetaType<QList<learnid::TrackingErrorCurve>>();
    qRegisterMetaType<Eigen::VectorXd>();
    qRegisterMetaType<QVector<Eigen::VectorXd>>();
}

} // namespace learnid
