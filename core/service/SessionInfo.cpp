#include "service/SessionInfo.h"

#include "robot/SimulatedRobot.h"
#include "service/SessionExport.h"
#include "service/SessionState.h"
#include "service/TrackingErrorData.h"
#include "session/ConvergenceFigures.h"
#include "session/TrialResult.h"

namespace learnid {

void registerSessionMetaTypes()
{
    qRegisterMetaType<learnid::SessionInfo>();
    qRegisterMetaType<learnid::TrialResult>();
    qRegisterMetaType<learnid::PreTrialCheck>();
    qRegisterMetaType<QList<learnid::TrackingErrorCurve>>();
    qRegisterMetaType<Eigen::VectorXd>();
    qRegisterMetaType<QVector<Eigen::VectorXd>>();
    qRegisterMetaType<learnid::EstimateFigures>();
    qRegisterMetaType<learnid::SessionState>();
    qRegisterMetaType<learnid::SessionOperation>();
    qRegisterMetaType<learnid::ExportRequest>();
}

} // namespace learnid
