#pragma once

#include "session/PayloadSession.h"

#include <QByteArray>
#include <QString>

namespace learnid {

/// The report of a payload session, `learnid-payload-report/1` (docs/file-formats.md, "Payload
/// session report"): the robot, the payload's link, prior and bound, one entry per trial run
/// (baseline or payload, its status, samples, tracking error per joint, and for a trial learned
/// from the payload fitted after it with what it identified), and the result: the payload of the
/// last learned trial as the parameter file's payload section, or null when none was learned.
/// endedEarly: why the session ended before its last trial (omitted when empty).
QByteArray payloadReportJson(const PayloadSession &session, const QString &endedEarly = {});

} // namespace learnid
