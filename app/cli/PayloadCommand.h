#pragma once

#include "cli/CliOptions.h"

#include <QTextStream>

namespace learnid {
struct PayloadEstimate;
}

namespace learnid::cli {

/// `learnid-cli identify --payload`: the payload fitted to the logs on top of the --robot URDF
/// held fixed (identifyPayloadFromLogs(), service/PayloadIdentification.h): each value with its
/// standard error and whether the logs identified it, what the path did not show, and per
/// --validate log the torque of the arm alone and with the payload. Writes the tables to out,
/// progress and errors to err, the --plots and --report files (all or none) only on success.
ExitCode payloadIdentifyCommand(const IdentifyOptions &options, QTextStream &out, QTextStream &err);

/// One row per value of the payload's body (mass, centre of mass, inertia about it): estimate,
/// standard error, prior, and where it came from (dataName, or the prior when not identified).
QString payloadTable(const PayloadEstimate &estimate, const QString &dataName);

} // namespace learnid::cli
