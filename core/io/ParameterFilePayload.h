#pragma once

#include "model/SerialChain.h"

#include <Eigen/Core>
#include <QString>
#include <array>
#include <limits>

namespace learnid {

class JsonTree;
class JsonObjectReader;

/// A parameter file's optional "payload" section (docs/file-formats.md, "Payload section"): the
/// body fixed to one link of the arm whose model the file holds, as `learnid-cli identify
/// --payload --export` writes it. All in the link's frame.
struct ParameterFilePayload
{
    QString link;                                  ///< the moving link it is fixed to
    double mass = 0.0;                             ///< [kg] > 0
    Eigen::Vector3d com = Eigen::Vector3d::Zero(); ///< centre of mass [m]
    /// Inertia about the centre of mass in the link's axes [kg m^2], the standard parameters'
    /// order: Ixx, Ixy, Iyy, Ixz, Iyz, Izz.
    std::array<double, 6> inertiaAtCom{};
    /// Per value (m, cx, cy, cz, then the six of inertiaAtCom): identified by the data, or kept
    /// at the prior (PayloadEstimate::bodyIdentified).
    std::array<bool, 10> identified{};
    /// The standard uncertainty of each value in its unit; NaN where not available (always for
    /// a value kept at the prior).
    std::array<double, 10> standardUncertainty = filledWithNan();

    /// The 10 standard parameters about the link frame's origin (PayloadBody::parameters()).
    InertialParameters parameters() const;

    static std::array<double, 10> filledWithNan()
    {
        std::array<double, 10> a;
        a.fill(std::numeric_limits<double>::quiet_NaN());
        return a;
    }
};

/// The section as the file writes it (ParameterFile.cpp).
JsonTree payloadSectionTree(const ParameterFilePayload &payload);

/// Reads the section: every key present with its type, no unknown keys. Throws Error naming the
/// key path ("payload.com[2]: ...").
ParameterFilePayload readPayloadSection(JsonObjectReader reader);

/// Checks the section's content for a file of robot.model `robotModel`: a link named (for a
/// built-in robot one of its moving links; a "urdf" file's link is checked against its URDF by
/// checkPayloadLink()), mass > 0, finite values, a real body (positive semidefinite
/// pseudo-inertia up to rounding), uncertainties not negative and none for a value kept at the
/// prior. Throws Error "payload.<key>: <problem>".
void validatePayloadSection(const ParameterFilePayload &payload, const QString &robotModel);

/// Throws Error "payload.link: ..." listing the chain's moving links when the payload's link is
/// not one of them (payloadJointOf()); returns its joint index.
int checkPayloadLink(const ParameterFilePayload &payload, const SerialChain &chain);

} // namespace learnid
