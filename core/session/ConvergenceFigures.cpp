#include "session/ConvergenceFigures.h"

#include <cmath>
#include <limits>

namespace learnid {

double largestRelativeDifferencePercent(const Eigen::VectorXd &x, const Eigen::VectorXd &ref)
{
    double worst = 0.0;
    for (Eigen::Index i = 0; i < std::min(x.size(), ref.size()); ++i) {
        if (ref[i] == 0.0)
            continue;
        const double r = (x[i] - ref[i]) / std::abs(ref[i]) * 100.0;
        if (std::abs(r) > std::abs(worst))
            worst = r;
    }
    return worst;
}

double pathTorqueErrorPercent(const RobotModel &model, const JointTrajectory &path,
                              const Eigen::VectorXd &phiHat, const Eigen::VectorXd &phi)
{
    const Eigen::MatrixXd truth = feedforwardTorque(model, path, phi);
    const double scale = truth.norm();
    if (!(scale > 0.0))
        return std::numeric_limits<double>::quiet_NaN();
    return 100.0 * (feedforwardTorque(model, path, phiHat) - truth).norm() / scale;
}

} // namespace learnid
