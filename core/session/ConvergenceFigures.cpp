#include "session/ConvergenceFigures.h"

#include <cmath>

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

} // namespace learnid
