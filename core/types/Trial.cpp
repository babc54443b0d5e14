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

} // namespace learnid
