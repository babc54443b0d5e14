#pragma once

#include "io/ParameterFile.h"
#include "service/LogIdentification.h"
#include "service/PayloadIdentification.h"

#include <QByteArray>
#include <QList>
#include <QPair>
#include <QString>
#include <optional>

namespace learnid {

/// The payload section of an estimate on the link `link`: the plausible body, per value whether
/// the data identified it, and the standard error of each identified one (NaN otherwise).
ParameterFilePayload payloadSection(const PayloadEstimate &estimate, const QString &link);

/// What a payload fit adds to the arm's parameter file: its payload section on `link`, and as
/// quality the fit's residual per joint, condition and rank (of the payload's 10 directions).
void setPayloadFit(ParameterFileContent &content, const PayloadFit &fit, const QString &link);

/// Puts the payload's apply into content.canWrites, before the stores: objects::payloadWrites()
/// of the payload (10 parameters in `link`'s frame) moved into the frame of the body that carries
/// it (docs/can-protocol.md §2.5), so the file's writes put the arm and the payload on the
/// drives.
void addPayloadWrites(ParameterFileContent &content, const PayloadLink &link,
                      const InertialParameters &payload);

/// The body values an estimate keeps at the prior, by name (PayloadEstimate::bodyNames()).
QStringList payloadValuesKept(const PayloadEstimate &estimate);

/// The parameter file of a payload identification (docs/file-formats.md, "Payload section"):
/// the arm's model as it was held fixed (its base parameters, its standard parameters with the
/// shares its parameter file recorded, the CAN writes of those base parameters: the arm's, as
/// without the payload), the payload section, and as quality the payload fit's residual per
/// joint, condition and rank (of the payload's 10 directions). The rest as logParameterFile().
ParameterFileContent payloadParameterFile(const PayloadIdentificationResult &result,
                                          const std::optional<ControllerSettings> &controller);

/// The arm's URDF as it was held fixed (the URDF as given, or with a parameter file's standard
/// parameters written in, urdfWithStandard()) plus the payload as a link fixed to its link
/// (urdfWithPayload()). comment: who made it and when; a note on which of the payload's values
/// were kept at the prior follows it.
QByteArray payloadIdentifiedUrdf(const PayloadIdentificationResult &result, const QString &comment);

/// The files of request (the parameter file and its DCF fragment, the URDF), built in memory
/// so that the caller writes all or none (writeFilesAtomically). Throws Error naming what
/// cannot be exported, as logExportFiles().
QList<QPair<QString, QByteArray>> payloadExportFiles(const PayloadIdentificationResult &result,
                                                     const LogExportRequest &request);

} // namespace learnid
