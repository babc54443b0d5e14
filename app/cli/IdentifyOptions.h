#pragma once

#include "cli/PayloadOptions.h"
#include "identify/LogFit.h"
#include "identify/LogSignals.h"
#include "identify/UniformLog.h"
#include "io/RobotLogCsv.h"
#include "types/ChainSettings.h"

#include <QString>
#include <QStringList>
#include <optional>

namespace learnid::cli {

struct CommandLine;

/// What `learnid-cli identify` was asked to do (docs/cli.md). Output paths are already absolute
/// (resolveOutputPath against --workspace).
struct IdentifyOptions
{
    QString robot;              ///< a built-in robot id (ModelFactory.h) or a URDF file
    QString baseLink;           ///< empty: the URDF's root link
    QString tipLink;            ///< empty: the one leaf below the base
    QStringList logs;           ///< --log: the logs fitted together
    QStringList validationLogs; ///< --validate: the logs the result is checked on
    LogColumns columns;
    JointTerms terms{false, true, true, true}; ///< viscous, Coulomb friction and an offset
    LogFilterSettings filter;
    LogFitSettings fit;
    ResampleOptions resample;
    QString scenarioPath; ///< --scenario: the controller gains the parameter file records
    QString exportPath;   ///< the parameter file (JSON, and its DCF beside it); empty: none
    QString urdfPath;     ///< the identified URDF; empty: none
    QString reportPath;   ///< the report (PDF: tables and plots); empty: none
    QString plotsDir;     ///< one PNG per validation log; empty: none
    bool quiet = false;
    std::optional<PayloadOptions> payload; ///< --payload: identify only the payload
};

/// Parses `learnid-cli identify ...` (args[1] is "identify") into cl: cl->identify and the
/// command Identify, or Help with this command's usage, or an error with its exit code
/// (ExitUsage for a syntax error, an unknown option or no --log; ExitBadInput for a bad value,
/// including a --columns entry with an unknown key).
void parseIdentifyCommandLine(const QStringList &args, CommandLine *cl);

} // namespace learnid::cli
