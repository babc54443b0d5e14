#pragma once

#include "model/PayloadPrior.h"

#include <QCommandLineOption>
#include <QCommandLineParser>
#include <QList>
#include <QString>
#include <optional>

namespace learnid::cli {

/// `learnid-cli identify --payload ...` (docs/cli.md): the payload fixed to a link of the arm
/// the --robot URDF models, and what the technician knows of it.
struct PayloadOptions
{
    QString link; ///< --payload-link; empty: the tip link
    /// --arm-urdf: the URDF a --robot parameter file of robot.model "urdf" was identified on
    QString armUrdf;
    PayloadPrior prior;
    /// --baseline-log: logs of the same program run without the payload (docs/payload.md)
    QStringList baselineLogs;
};

/// --payload and its --payload-* options, for identify's parser (with --arm-urdf and
/// --baseline-log), or for `scenario --print` (the prior and its bound only).
QList<QCommandLineOption> payloadCliOptions(bool identify = true);

/// The field names of the options, for messages.
PayloadFieldNames payloadOptionNames();

/// Reads the options into *payload (set when --payload is given); returns an error naming the
/// option, or an empty string. A --payload-* option without --payload, a missing
/// --payload-mass, a value that is not a number list of the right length, and every refusal of
/// validatePayloadPrior() are errors.
QString readPayloadOptions(const QCommandLineParser &parser, std::optional<PayloadOptions> *payload,
                           bool identify = true);

} // namespace learnid::cli
