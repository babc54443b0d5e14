#include "session/PayloadPathChange.h"

#include "model/Error.h"
#include "session/TrialPlanner.h"

#include <Eigen/Eigenvalues>
#include <QCoreApplication>
#include <QStringList>
#include <algorithm>
#include <cmath>
#include <limits>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(PayloadPathChange)
};

// What a changed path measures of what `before` misses: identified, and predicted to within
// the parameter's own scale (a standard error larger than the value it measures measures
// nothing). measured[p] for the parameters `before` misses; the others stay false.
std::array<bool, 10> measuredOfMissing(const PayloadObservability &after,
                                       const PayloadObservability &before,
                                       const Eigen::Matrix<double, 10, 1> &errors,
                                       const Eigen::Matrix<double, 10, 1> &scale)
{
    std::array<bool, 10> measured{};
    for (int p = 0; p < 10; ++p)
        measured[size_t(p)] = !before.identified(p) && after.identified(p) && errors[p] <= scale[p];
    return measured;
}

// Every parameter of `wanted` that `before` misses is measured.
bool covers(const std::array<bool, 10> &measured, const PayloadObservability &before, int first,
            int last)
{
    for (int p = first; p <= last; ++p)
        if (!before.identified(p) && !measured[size_t(p)])
            return false;
    return true;
}

} // namespace

QString PayloadPathChange::describe(const ChainModel &model) const
{
    QStringList seen;
    const QStringList names = PayloadObservability::parameterNames();
    for (int p = 0; p < 10; ++p)
        if (measured[size_t(p)])
            seen << names.at(p);
    return Text::tr("moving %1 at waypoint %2 by %3 rad (to %4 rad, inside its limits) would let "
                    "the trials measure %5")
        .arg(model.chain().joints[size_t(joint)].name)
        .arg(waypoint + 1)
        .arg(change, 0, 'f', 2)
        .arg(value, 0, 'f', 3)
        .arg(seen.join(QStringLiteral(", ")));
}

Eigen::Matrix<double, 10, 1> payloadPredictedStdErrors(const PayloadModel &payload,
                                                       const JointTrajectory &path,
                                                       const Eigen::VectorXd &noise)
{
    Eigen::Matrix<double, 10, 10> gram = Eigen::Matrix<double, 10, 10>::Zero();
    const Eigen::VectorXd weight = noise.cwiseInverse();
    for (Eigen::Index k = 0; k < path.q.cols(); ++k) {
        const Eigen::MatrixXd y =
            weight.asDiagonal() *
            payload.regressorAt(path.q.col(k), path.qd.col(k), path.qdd.col(k));
        gram.noalias() += y.transpose() * y;
    }
    // Scaled to unit diagonal so that the inverse's accuracy does not depend on the units.
    const Eigen::Matrix<double, 10, 1> d = gram.diagonal().cwiseMax(1e-300).cwiseSqrt();
    const Eigen::Matrix<double, 10, 10> scaled =
        d.cwiseInverse().asDiagonal() * gram * d.cwiseInverse().asDiagonal();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 10, 10>> eig(scaled);
    Eigen::Matrix<double, 10, 1> out;
    const Eigen::Matrix<double, 10, 1> inverse = eig.eigenvalues().unaryExpr(
        [](double l) { return l > 1e-12 ? 1.0 / l : std::numeric_limits<double>::infinity(); });
    for (int p = 0; p < 10; ++p) {
        double v = 0.0;
        for (int i = 0; i < 10; ++i) {
            const double c = eig.eigenvectors()(p, i);
            if (c * c > 1e-24)
                v += c * c * inverse[i];
        }
        out[p] = std::sqrt(v) / d[p];
    }
    return out;
}

Eigen::Matrix<double, 10, 1> payloadParameterScale(const PayloadPrior &prior)
{
    const InertialParameters pi = prior.parameters();
    const double size = prior.bound.box ? 0.5 * (prior.bound.upper - prior.bound.lower).maxCoeff()
                                        : prior.bound.radius;
    const double moment = (pi[4] + pi[6] + pi[9]) / 3.0; // Ixx, Iyy, Izz about the link frame
    Eigen::Matrix<double, 10, 1> s;
    s << pi[0], Eigen::Vector3d::Constant(pi[0] * 0.01 * size),
        Eigen::Matrix<double, 6, 1>::Constant(moment);
    return s;
}

PayloadPathChange smallestPayloadPathChange(const Scenario &scenario,
                                            const std::shared_ptr<const ChainModel> &model,
                                            const PayloadModel &payload, const PayloadPrior &prior,
                                            const Eigen::VectorXd &phi, bool gentle,
                                            const PayloadObservability &before)
{
    PayloadPathChange none;
    if (scenario.path.kind != PathKind::Waypoints)
        return none;
    bool missing = false;
    for (int p = 0; p < 10; ++p)
        missing = missing || !before.identified(p);
    if (!missing)
        return none;
    constexpr double steps[] = {0.05, 0.1, 0.2, 0.3, 0.5, 0.75, 1.0};
    const Eigen::VectorXd noise = 0.01 * scenario.torqueLimits;
    const Eigen::Matrix<double, 10, 1> scale = payloadParameterScale(prior);
    constexpr double margin = 0.05;
    const int last = payload.joint();
    // The smallest change that measures all that is missing; else the smallest that measures
    // the missing mass and centre of mass (the inertia may need more than one joint's turn).
    PayloadPathChange massAndCom;
    for (double step : steps) {
        for (int joint = last; joint >= std::max(0, last - 2); --joint) {
            const ChainJoint &j = model->chain().joints[size_t(joint)];
            for (size_t w = 0; w < scenario.path.waypoints.size(); ++w) {
                for (double sign : {1.0, -1.0}) {
                    const double value = scenario.path.waypoints[w][joint] + sign * step;
                    if (value < j.lower + margin || value > j.upper - margin)
                        continue;
                    Scenario changed = scenario;
                    changed.path.waypoints[w][joint] = value;
                    PayloadPathChange c;
                    try {
                        const JointTrajectory d =
                            TrialPlanner(changed, model).plan(phi, nullptr, gentle).desired;
                        c.observability = payloadPathObservability(payload, d.q, d.qd, d.qdd);
                        c.measured =
                            measuredOfMissing(c.observability, before,
                                              payloadPredictedStdErrors(payload, d, noise), scale);
                    } catch (const Error &) {
                        continue; // this change cannot be planned: not offered
                    }
                    c.waypoint = int(w);
                    c.joint = joint;
                    c.change = sign * step;
                    c.value = value;
                    if (covers(c.measured, before, 0, 9))
                        return c;
                    if (!massAndCom.valid() && covers(c.measured, before, 0, 3) &&
                        std::find(c.measured.begin(), c.measured.end(), true) != c.measured.end())
                        massAndCom = c;
                }
            }
        }
    }
    return massAndCom;
}

} // namespace learnid
