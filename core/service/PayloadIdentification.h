#pragma once

#include "identify/PayloadBaseline.h"
#include "identify/PayloadFit.h"
#include "model/Payload.h"
#include "model/PayloadPrior.h"
#include "service/LogIdentification.h"
#include "service/PayloadArm.h"

#include <QString>
#include <memory>
#include <vector>

namespace learnid {

/// A payload to identify from recorded logs with the arm's model held fixed (`learnid-cli
/// identify --payload`, docs/payload.md). The arm is logs.robot (loadPayloadArm(): a URDF, e.g.
/// the one an earlier identification exported, a built-in robot, or a parameter file an earlier
/// identification exported); the logs, their columns, filter and resampling as for the arm's
/// own identification.
/// How recorded baselines are laid over the logs: shifted by up to 2 s to match the joint angles,
/// refused when those differ by more than 2 deg RMS (another path), covering at least 80 % of
/// each log.
BaselineSettings recordedBaselineSettings();

struct PayloadIdentificationRequest
{
    LogIdentificationRequest logs; ///< fit settings other than the filter are not used
    QString armUrdf; ///< the URDF of a parameter file of robot.model "urdf"; else empty
    QString armUrdfName = QStringLiteral("the arm's URDF"); ///< armUrdf in messages
    QString link; ///< the link the payload is fixed to; empty: the tip
    PayloadPrior prior;
    /// Logs of the same motion without the payload (docs/payload.md, "A wrong arm model and the
    /// baseline trial"): each training log is laid over them by its joint angles and their
    /// residual taken out (withBaselineSubtracted).
    QStringList baselineLogs;
    BaselineSettings baseline = recordedBaselineSettings();
    PayloadFitSettings fit;
};

/// What a payload identification produced; nothing is written.
struct PayloadIdentificationResult
{
    PayloadArm arm; ///< the arm's model held fixed, and where it came from
    std::shared_ptr<const PayloadModel> model;
    QStringList trainingLogs;
    std::vector<BaselineAlignment> baselines; ///< per training log, each baseline's alignment
    PayloadFit fit;
    /// Per validation log: "given" the arm alone (the URDF as given, no payload), "identified"
    /// the arm with the identified payload.
    std::vector<LogValidation> validation;
    std::vector<LogReading> readings; ///< the training logs, the baselines, the validation logs
};

/// Reads the arm (loadPayloadArm), checks the prior (validatePayloadPrior with `names`) and
/// the link (payloadJointOf), reads, resamples and filters every log as identifyFromLogs()
/// does, fits the payload (fitPayload) and predicts the validation logs. Throws Error naming
/// the file, option or field at fault.
PayloadIdentificationResult identifyPayloadFromLogs(const PayloadIdentificationRequest &request,
                                                    const PayloadFieldNames &names = {});

} // namespace learnid
