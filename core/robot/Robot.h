#pragma once

#include "types/DriveIdentity.h"
#include "types/Trial.h"

#include <QCoreApplication>
#include <QList>
#include <QString>
#include <optional>

namespace learnid {

/// A robot the commissioning session can drive: simulated or on a CAN bus, the session cannot
/// tell the difference. Calls are blocking and are made from one worker thread.
class Robot
{
public:
    virtual ~Robot() = default;

    /// One line for the status bar, e.g. "simulated paper-2link" or "CAN socketcan/can0".
    virtual QString description() const = 0;

    /// Runs one trial of the plan under PID plus the plan's feedforward and returns what was
    /// measured. Faults and safety aborts end the trial early with the partial record.
    virtual TrialRecord runTrial(const TrialPlan &plan, const TrialMonitor &monitor) = 0;

    /// Writes a parameter set to the robot controller, reads it back and stores it; all or
    /// nothing. Returns an empty string on success, else what failed and where.
    virtual QString applyParameters(const Eigen::VectorXd &phi) = 0;

    /// Writes a payload to the robot controller, reads it back and stores it, all or nothing:
    /// joint (1-based) is the joint whose moving body carries it, body its 10 standard
    /// parameters in that body's frame (InertialParameters' order). Returns an empty string on
    /// success, else what failed and where; a robot that takes no payload says so.
    virtual QString applyPayload(int joint, const Eigen::VectorXd &body)
    {
        Q_UNUSED(joint);
        Q_UNUSED(body);
        return QCoreApplication::translate("Robot",
                                           "this robot's controller takes no payload: give it "
                                           "the payload's parameter file");
    }

    /// The parameter set the robot controller currently holds (empty before any apply).
    virtual Eigen::VectorXd storedParameters() const = 0;

    /// The true parameters, known only for a simulated robot (for error-against-truth figures).
    virtual std::optional<Eigen::VectorXd> trueParameters() const { return std::nullopt; }

    /// The identity (CiA 301 0x1018) of each joint's drive, for the parameter file; empty when
    /// the robot has no such drives or has not read them yet.
    virtual QList<DriveIdentity> driveIdentities() const { return {}; }
};

} // namespace learnid
