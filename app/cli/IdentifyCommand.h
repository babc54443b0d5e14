#pragma once

#include "cli/CliOptions.h"
#include "service/LogIdentification.h"

#include <QTextStream>

namespace learnid::cli {

/// `learnid-cli identify`: the robot's inertia and joint friction fitted to its recorded logs
/// (identifyFromLogs(), service/LogIdentification.h), checked on the --validate
/// logs against the URDF as given. Writes the tables to out, progress and errors to err, and
/// the requested files (all or none) only when everything succeeded.
ExitCode identifyCommand(const IdentifyOptions &options, QTextStream &out, QTextStream &err);

/// Writes identify's files (the --plots folder made first), all or none, and names each on err
/// unless --quiet: ExitOk, or ExitWriteFailed with the reason on err. Shared by the arm's and the
/// payload's identification.
ExitCode writeIdentifyFiles(const IdentifyOptions &options,
                            const QList<QPair<QString, QByteArray>> &files, QTextStream &err);

/// What --export and --urdf-out ask identify to write (no files when neither is given): the
/// paths, the --scenario's controller gains for `joints` joints (read and checked; none without
/// --scenario: logs do not say which gains recorded them) and the URDF's comment (tool version,
/// date). Shared by the arm's and the payload's identification; throws Error naming the file.
LogExportRequest identifyExportRequest(const IdentifyOptions &options, int joints);

} // namespace learnid::cli
