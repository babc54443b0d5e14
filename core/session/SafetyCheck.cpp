#include "session/SafetyCheck.h"

#include "control/PidController.h"
#include "model/VectorState.h"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <QCoreApplication>
#include <cmath>
#include <unsupported/Eigen/MatrixFunctions>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(SafetyCheck)
};

// Sizes of the check for N joints (N = Eigen::Dynamic: any count, known at run time).
template <int N> struct CheckSizes
{
    static constexpr int fixed(int k) { return N == Eigen::Dynamic ? Eigen::Dynamic : k * N; }
    using JointVector = Eigen::Matrix<double, N, 1>;
    using PlantMatrix = Eigen::Matrix<double, fixed(2), fixed(2)>; // x = (q, qd)
    using InputMatrix = Eigen::Matrix<double, fixed(2), N>;
    using HoldMatrix = Eigen::Matrix<double, fixed(3), fixed(3)>;       // [A B; 0 0]
    using ControllerMatrix = Eigen::Matrix<double, fixed(3), fixed(3)>; // 3 PID states per joint
    using ControllerInput = Eigen::Matrix<double, fixed(3), N>;
    using ControllerOutput = Eigen::Matrix<double, N, fixed(3)>;
    using JointMatrix = Eigen::Matrix<double, N, N>;
    using LoopMatrix = Eigen::Matrix<double, fixed(5), fixed(5)>;
};

// The joints' discrete PIDs as one block-diagonal controller: xc+ = Ac xc + Bc e, u = Cc xc + Dc e.
template <int N> struct Controller
{
    typename CheckSizes<N>::ControllerMatrix a;
    typename CheckSizes<N>::ControllerInput b;
    typename CheckSizes<N>::ControllerOutput c;
    typename CheckSizes<N>::JointMatrix d;

    Controller(const PidController &pid, int n)
    {
        a.setZero(3 * n, 3 * n);
        b.setZero(3 * n, n);
        c.setZero(n, 3 * n);
        d.setZero(n, n);
        for (int j = 0; j < n; ++j) {
            const StateSpace &s = pid.joint(j);
            a.block(3 * j, 3 * j, 3, 3) = s.a;
            b.block(3 * j, j, 3, 1) = s.b;
            c.block(j, 3 * j, 1, 3) = s.c;
            d(j, j) = s.d(0, 0);
        }
    }
};

// Spectral radius of the discrete closed loop at one point of the path: the plant
// x = (q, qd), x' = (qd, M^-1 (tau - h)) linearised at (q, qd, qdd) with tau = inverse dynamics
// there (central differences), discretised with zero-order hold, under the controller.
template <int N>
double closedLoopRadius(const RobotModel &model, const Eigen::VectorXd &phi,
                        const Eigen::Ref<const Eigen::VectorXd> &q,
                        const Eigen::Ref<const Eigen::VectorXd> &qd,
                        const Eigen::Ref<const Eigen::VectorXd> &qdd, double ts,
                        const Controller<N> &ctrl)
{
    using S = CheckSizes<N>;
    const int n = model.dof();
    typename S::JointVector tau(n), fp(n), fm(n), qp(n), qm(n), vp(n), vm(n);
    model.inverseDynamics(q, qd, qdd, phi, tau);
    typename S::HoldMatrix aug = S::HoldMatrix::Zero(3 * n, 3 * n);
    aug.block(0, n, n, n).setIdentity();
    for (int i = 0; i < 2 * n; ++i) {
        qp = q;
        qm = q;
        vp = qd;
        vm = qd;
        const double base = i < n ? q[i] : qd[i - n];
        const double h = 1e-6 * std::max(1.0, std::abs(base));
        if (i < n) {
            qp[i] += h;
            qm[i] -= h;
        } else {
            vp[i - n] += h;
            vm[i - n] -= h;
        }
        model.forwardDynamics(qp, vp, tau, phi, fp);
        model.forwardDynamics(qm, vm, tau, phi, fm);
        aug.block(n, i, n, 1) = (fp - fm) / (2.0 * h);
    }
    Eigen::MatrixXd m(n, n);
    model.massMatrix(q, phi, m);
    aug.block(n, 2 * n, n, n) = typename S::JointMatrix(m).inverse();
    // Zero-order hold: exp([A B; 0 0] ts) = [Phi Gamma; 0 I].
    aug *= ts;
    const typename S::HoldMatrix e = aug.exp();
    const typename S::PlantMatrix phiPlant = e.topLeftCorner(2 * n, 2 * n);
    const typename S::InputMatrix gamma = e.topRightCorner(2 * n, n);

    // Closed loop with y = C x = q, e = -y: x+ = Phi x + Gamma u, u = Cc xc - Dc C x;
    // xc+ = Ac xc - Bc C x.
    const int np = 2 * n, nc = 3 * n;
    typename S::LoopMatrix cl(np + nc, np + nc);
    cl.topLeftCorner(np, np) = phiPlant;
    cl.topLeftCorner(np, n) -= gamma * ctrl.d;
    cl.topRightCorner(np, nc) = gamma * ctrl.c;
    cl.bottomLeftCorner(nc, np).setZero();
    cl.bottomLeftCorner(nc, n) = -ctrl.b;
    cl.bottomRightCorner(nc, nc) = ctrl.a;
    const Eigen::EigenSolver<typename S::LoopMatrix> es(cl, false);
    return es.eigenvalues().cwiseAbs().maxCoeff();
}

template <int N>
void checkPath(const RobotModel &model, const Eigen::VectorXd &phiHat, const TrialPlan &plan,
               int points, SafetyVerdict &v)
{
    const double ts = plan.desired.samplePeriod;
    const Controller<N> ctrl(PidController(plan.controller), model.dof());
    const int samples = plan.samples();
    const int count = std::max(2, points);
    for (int p = 0; p < count; ++p) {
        const int k = int(std::lround(double(p) * (samples - 1) / (count - 1)));
        const auto q = plan.desired.q.col(k);
        if (!model.massMatrixPositiveDefinite(q, phiHat)) {
            v.physical = false;
            v.worstTime = k * ts;
            break;
        }
        const double radius = closedLoopRadius<N>(model, phiHat, q, plan.desired.qd.col(k),
                                                  plan.desired.qdd.col(k), ts, ctrl);
        if (radius > v.worstSpectralRadius) {
            v.worstSpectralRadius = radius;
            v.worstTime = k * ts;
        }
    }
}

// The first sample where a joint leaves its position or speed limits, as a reason; empty when
// none does (or the plan has no limits).
QString jointLimitViolation(const TrialPlan &plan)
{
    const JointTrajectory &d = plan.desired;
    if (plan.positionLower.size() != d.dof())
        return {};
    for (int k = 0; k < d.samples(); ++k) {
        for (int j = 0; j < d.dof(); ++j) {
            const double q = d.q(j, k), v = d.qd(j, k);
            const double t = k * d.samplePeriod;
            if (q < plan.positionLower[j] || q > plan.positionUpper[j]) {
                return Text::tr("joint %1 would reach %2 at t = %3 s, outside its limits %4 to %5")
                    .arg(j + 1)
                    .arg(q, 0, 'f', 4)
                    .arg(t, 0, 'f', 3)
                    .arg(plan.positionLower[j], 0, 'f', 4)
                    .arg(plan.positionUpper[j], 0, 'f', 4);
            }
            if (std::abs(v) > plan.velocityLimit[j]) {
                return Text::tr("joint %1 would move at %2 at t = %3 s, above its speed limit %4")
                    .arg(j + 1)
                    .arg(v, 0, 'f', 4)
                    .arg(t, 0, 'f', 3)
                    .arg(plan.velocityLimit[j], 0, 'f', 4);
            }
        }
    }
    return {};
}

} // namespace

SafetyVerdict checkTrial(const RobotModel &model, const Eigen::VectorXd &phiHat,
                         const TrialPlan &plan, double margin, int points)
{
    clearUpperVectorState();
    const int n = model.dof();
    const double ts = plan.desired.samplePeriod;
    SafetyVerdict v;
    v.torqueLimit = plan.torqueLimit;
    v.motionDuration = plan.motionDuration;
    v.peakTorque = plan.feedforward.cwiseAbs().rowwise().maxCoeff();
    v.peakGravityTorque = Eigen::VectorXd::Zero(n);
    Eigen::VectorXd gravity(n);
    const Eigen::VectorXd rest = Eigen::VectorXd::Zero(n);
    for (int k = 0; k < plan.samples(); ++k) {
        model.biasTorque(plan.desired.q.col(k), rest, phiHat, gravity);
        v.peakGravityTorque = v.peakGravityTorque.cwiseMax(gravity.cwiseAbs());
    }

    // Fixed-size matrices for the 2-link arm (10 x 10 closed loop): no heap work per point.
    if (n == 2)
        checkPath<2>(model, phiHat, plan, points, v);
    else
        checkPath<Eigen::Dynamic>(model, phiHat, plan, points, v);
    v.worstDecayRate = std::log(std::max(v.worstSpectralRadius, 1e-300)) / ts;
    v.stable = v.physical && v.worstDecayRate < -margin;
    int overJoint = -1;
    for (int j = 0; j < n; ++j)
        if (v.peakTorque[j] > v.torqueLimit[j] && overJoint < 0)
            overJoint = j;
    v.torqueWithinLimits = overJoint < 0;
    const QString limitViolation = jointLimitViolation(plan);
    v.withinJointLimits = limitViolation.isEmpty();

    if (!v.physical) {
        v.reason = Text::tr("the estimate is not a physical robot: its mass matrix is not positive "
                            "definite at t = %1 s")
                       .arg(v.worstTime, 0, 'f', 3);
    } else if (!v.stable) {
        v.reason =
            Text::tr("the closed loop would be unstable: linearised along the path with the "
                     "current estimate, a pole has |z| = %1 (growth rate %2 1/s) at t = %3 s. "
                     "Raise the derivative filter bandwidth lambda or lower the gains")
                .arg(v.worstSpectralRadius, 0, 'f', 5)
                .arg(v.worstDecayRate, 0, 'g', 3)
                .arg(v.worstTime, 0, 'f', 3);
    } else if (!v.torqueWithinLimits) {
        v.reason = Text::tr("planned torque of joint %1 is %2 N m, above its limit of %3 N m")
                       .arg(overJoint + 1)
                       .arg(v.peakTorque[overJoint], 0, 'f', 3)
                       .arg(v.torqueLimit[overJoint], 0, 'f', 3);
    } else if (!v.withinJointLimits) {
        v.reason = limitViolation;
    }
    return v;
}

} // namespace learnid
