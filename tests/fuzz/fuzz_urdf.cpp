// Fuzz target: the URDF reader beyond urdfdom's own parsing (core/model UrdfChain, UrdfGeometry,
// UrdfExtension, MeshBounds, ModelCheck): the chain, each body's geometry box from <collision>
// and <visual> shapes, learnid's <learnid:dynamics> element, and the check of the URDF's own
// values as a real robot's. The input is the URDF text; there is no folder to look for meshes in
// (relative names are skipped). Bad input must end in a learnid::Error. An accepted chain has
// finite armature and offset for every joint, a geometry box that is empty or finite and
// ordered, and, when the model can be made, the check runs without throwing.

#include "FuzzSupport.h"

#include "model/ChainModel.h"
#include "model/Error.h"
#include "model/ModelCheck.h"
#include "model/UrdfChain.h"

#include <cmath>

using namespace learnid;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz::quietMessages();
    qunsetenv("ROS_PACKAGE_PATH");
    SerialChain chain;
    try {
        chain = parseUrdfChain(fuzz::bytes(data, size), QStringLiteral("fuzz.urdf"));
    } catch (const Error &) {
        return 0;
    }
    for (const ChainJoint &j : chain.joints) {
        if (!std::isfinite(j.armature) || !std::isfinite(j.offset))
            fuzz::fuzzFailure("an accepted joint has an armature or offset that is not finite");
        const Eigen::AlignedBox3d &box = j.geometryBox;
        if (!box.isEmpty() && (!box.min().allFinite() || !box.max().allFinite() ||
                               (box.max() - box.min()).minCoeff() < 0.0))
            fuzz::fuzzFailure("a geometry box is not finite or not ordered", j.link);
    }
    if (chain.dof() > 8)
        return 0; // the model's base parameters take long for many joints; not the target here
    try {
        const ChainModel model(chain, JointTerms{true, true, true, true}, QStringLiteral("urdf"));
        (void)modelWarnings(model);
    } catch (const Error &) {
        // a chain the dynamics refuse (a joint count beyond their limit, a non-finite origin)
    }
    return 0;
}
