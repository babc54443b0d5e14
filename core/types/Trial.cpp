#include "types/Trial.h"

#include <QCoreApplication>

namespace learnid {

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

TrialStopCause defaultStopCause(TrialStatus status)
{
    switch (status) {
    case TrialStatus::Completed:
    case TrialStatus::Refused:
        return TrialStopCause::None;
    case TrialStatus::Faulted:
        return TrialStopCause::RobotFault;
    case TrialStatus::Cancelled:
        return TrialStopCause::Operator;
    case TrialStatus::Aborted:
        return TrialStopCause::Other;
    }
    return TrialStopCause::Other;
}

} // namespace learnid
