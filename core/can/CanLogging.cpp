#include "can/CanLogging.h"

namespace learnid {

Q_LOGGING_CATEGORY(lcCan, "learnid.can", QtInfoMsg)

} // namespace learnid
