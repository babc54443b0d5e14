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

void requireGridPoints(int gridPoints)
{
    if (gridPoints < 2)
        throw Error(QCoreApplication::translate("TorqueRule", "torque rule needs 2 grid points"));
}

// The grid of regressor rows at gridPoints values of u in [0, 1]; stateAt(u, q, q', q'') gives
// the path's state at T = 1 into its three Ref<VectorXd> arguments, u increasing call by call.
template <typename StateAt>
TorqueRuleGrid gridOver(const RobotModel &model, int gridPoints, StateAt &&stateAt)
{
    const int n = model.dof();
    const int m = model.parameterCount();
    requireGridPoints(gridPoints);
    TorqueRuleGrid grid;
    grid.dof = n;
    grid.inertial.resize(Eigen::Index(n) * gridPoints, m);
    grid.gravity.resize(Eigen::Index(n) * gridPoints, m);
    const Eigen::VectorXd zero = Eigen::VectorXd::Zero(n);
    Eigen::VectorXd q(n), qd(n), qdd(n);
    for (int i = 0; i < gridPoints; ++i) {
        stateAt(double(i) / (gridPoints - 1), Eigen::Ref<Eigen::VectorXd>(q),
                Eigen::Ref<Eigen::VectorXd>(qd), Eigen::Ref<Eigen::VectorXd>(qdd));
        const Eigen::Index row = Eigen::Index(i) * n;
        model.regressor(q, zero, zero, grid.gravity.middleRows(row, n));
        model.regressor(q, qd, qdd, grid.inertial.middleRows(row, n));
        grid.inertial.middleRows(row, n) -= grid.gravity.middleRows(row, n);
    }
    return grid;
}

} // namespace

TorqueRuleGrid torqueRuleGrid(const RobotModel &model, const Kinematics &kinematics,
                              const CartesianLine &line, int gridPoints)
{
    requireGridPoints(gridPoints); // before the inverse kinematics, which may throw too
    Eigen::VectorXd near = kinematics.inverse(line.start, Eigen::VectorXd());
    return gridOver(model, gridPoints, [&](double u, auto q, auto qd, auto qdd) {
        lineStateInto(kinematics, line, 1.0, u, near, q, qd, qdd);
        near = q;
    });
}

TorqueRuleGrid torqueRuleGrid(const RobotModel &model, const JointPath &path, int gridPoints)
{
    if (path.dof() != model.dof()) {
        throw Error(QCoreApplication::translate(
                        "TorqueRule", "torque rule: the path has %1 joints, the robot model %2")
                        .arg(path.dof())
                        .arg(model.dof()));
    }
    return gridOver(model, gridPoints,
                    [&](double u, auto q, auto qd, auto qdd) { path.stateInto(u, q, qd, qdd); });
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
        Eigen::Index joint = 0;
        staticRatio.maxCoeff(&joint);
        throw Error(QCoreApplication::translate("TorqueRule",
                                                "gravity alone needs %1 N m at joint %2 on this "
                                                "path, more than %3 % of its %4 N m limit: no "
                                                "duration can meet the torque rule")
                        .arg(staticRatio[joint] * limit[joint], 0, 'f', 2)
                        .arg(joint + 1)
                        .arg(fraction * 100.0)
                        .arg(torqueLimit[joint], 0, 'g', 4));
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
