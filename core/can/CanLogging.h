#pragma once

#include <QLoggingCategory>

namespace learnid {

/// Log category of the CAN link and the CANopen protocol layer ("learnid.can").
Q_DECLARE_LOGGING_CATEGORY(lcCan)

} // namespace learnid
