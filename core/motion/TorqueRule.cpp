#include "motion/TorqueRule.h"

#include "model/Error.h"

#include <QCoreApplication>
#include <cmath>

namespace learnid {

namespace {

// Peak of |A/T^2 + g| / limit over the grid, per joint.
Eigen::VectorXd peakRatio(const Eigen::MatrixXd &a, const Eigen::MatrixXd &g,
                          const Eigen::VectorXd &limit, double T)
{
    const Eigen::MatrixXd tau = a / (T * T) + g;
    return tau.cwiseAbs().rowwise().maxCoeff().cwiseQuotient(limit);
}

} // namespace

TorqueRuleGrid torqueRuleGrid(const RobotModel &model, const Kinematics &kinematics,
                              const CartesianLine &line, int gridPoints)
{
    const int n = model.dof();
    const int m = model.parameterCount();
    if (gridPoints < 2)
        throw Error(QCoreApplication::translate("TorqueRule", "torque rule needs 2 grid points"));
    TorqueRuleGrid grid;
    grid.dof = n;
    grid.inertial.resize(Eigen::Index(n) * gridPoints, m);
    grid.gravity.resize(Eigen::Index(n) * gridPoints, m);
    const Eigen::VectorXd zero = Eigen::VectorXd::Zero(n);
    Eigen::VectorXd near = kinematics.inverse(line.start, Eigen::VectorXd());
    Eigen::VectorXd q(n), qd(n), qdd(n);
    for (int i = 0; i < gridPoints; ++i) {
        lineStateInto(kinematics, line, 1.0, double(i) / (gridPoints - 1), near, q, qd, qdd);
        near = q;
        const Eigen::Index row = Eigen::Index(i) * n;
        model.regressor(q, zero, zero, grid.gravity.middleRows(row, n));
        model.regressor(q, qd, qdd, grid.inertial.middleRows(row, n));
        grid.inertial.middleRows(row, n) -= grid.gravity.middleRows(row, n);
    }
    return grid;
}

TorqueRuleResult shortestDuration(const TorqueRuleGrid &grid, const Eigen::VectorXd &phi,
                                  const Eigen::VectorXd &torqueLimit, double fraction)
{
    const int n = grid.dof;
    if (torqueLimit.size() != n || (torqueLimit.array() <= 0.0).any() || !(fraction > 0.0) ||
        phi.size() != grid.inertial.cols()) {
        throw Error(QCoreApplication::translate(
            "TorqueRule",
            "torque rule needs one positive limit per joint and a positive fraction"));
    }
    // A(u): inertial and velocity torque at T = 1, columns per grid point; g(u): gravity.
    const Eigen::Index points = grid.inertial.rows() / n;
    const Eigen::VectorXd av = grid.inertial * phi;
    const Eigen::VectorXd gv = grid.gravity * phi;
    const Eigen::Map<const Eigen::MatrixXd> a(av.data(), n, points);
    const Eigen::Map<const Eigen::MatrixXd> g(gv.data(), n, points);
    const Eigen::VectorXd limit = fraction * torqueLimit;
    const Eigen::VectorXd staticRatio = g.cwiseAbs().rowwise().maxCoeff().cwiseQuotient(limit);
    if ((staticRatio.array() >= 1.0).any()) {
        throw Error(
            QCoreApplication::translate(
                "TorqueRule", "gravity alone needs more than %1 % of a joint's torque limit")
                .arg(fraction * 100.0));
    }
    const Eigen::VectorXd inertialRatio = a.cwiseAbs().rowwise().maxCoeff().cwiseQuotient(limit);
    if (!inertialRatio.allFinite() || inertialRatio.maxCoeff() <= 0.0) {
        throw Error(QCoreApplication::translate(
            "TorqueRule", "the path needs no torque: check its length and the parameters"));
    }

    TorqueRuleResult result;
    if (staticRatio.maxCoeff() == 0.0) {
        result.duration = std::sqrt(inertialRatio.maxCoeff()); // max |A|/T^2 = limit
    } else {
        // ratio(T) -> staticRatio < 1 as T grows; bisect on the first T meeting the rule.
        double lo = 1e-3;
        double hi = std::sqrt(inertialRatio.maxCoeff() / (1.0 - staticRatio.maxCoeff())) + 1.0;
        for (int it = 0; it < 200 && hi - lo > 1e-12 * hi; ++it) {
            const double mid = 0.5 * (lo + hi);
            (peakRatio(a, g, limit, mid).maxCoeff() > 1.0 ? lo : hi) = mid;
        }
        result.duration = hi;
    }
    const Eigen::VectorXd ratio = peakRatio(a, g, limit, result.duration);
    ratio.maxCoeff(&result.limitingJoint);
    result.peakTorque = ratio.cwiseProduct(limit);
    return result;
}

TorqueRuleResult shortestDuration(const RobotModel &model, const Eigen::VectorXd &phi,
                                  const Kinematics &kinematics, const CartesianLine &line,
                                  const Eigen::VectorXd &torqueLimit, double fraction,
                                  int gridPoints)
{
    return shortestDuration(torqueRuleGrid(model, kinematics, line, gridPoints), phi, torqueLimit,
                            fraction);
}

} // namespace learnid
