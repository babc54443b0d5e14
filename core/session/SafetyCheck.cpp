#include "session/SafetyCheck.h"

#include "control/PidController.h"

#include <Eigen/Eigenvalues>
#include <QCoreApplication>
#include <cmath>

namespace learnid {

namespace {

QString tr(const char *text)
{
    return QCoreApplication::translate("SafetyCheck", text);
}

// Continuous plant linearised at (q, qd, qdd) with tau = inverse dynamics there.
StateSpace linearisedPlant(const RobotModel &model, const Eigen::VectorXd &phi,
                           const Eigen::VectorXd &q, const Eigen::VectorXd &qd,
                           const Eigen::VectorXd &qdd)
{
    const int n = model.dof();
    Eigen::VectorXd tau(n);
    model.inverseDynamics(q, qd, qdd, phi, tau);
    StateSpace s;
    s.a = Eigen::MatrixXd::Zero(2 * n, 2 * n);
    s.a.topRightCorner(n, n).setIdentity();
    Eigen::VectorXd fp(n), fm(n);
    for (int i = 0; i < 2 * n; ++i) {
        Eigen::VectorXd qp = q, qm = q, vp = qd, vm = qd;
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
        s.a.block(n, i, n, 1) = (fp - fm) / (2.0 * h);
    }
    Eigen::MatrixXd m(n, n);
    model.massMatrix(q, phi, m);
    s.b = Eigen::MatrixXd::Zero(2 * n, n);
    s.b.bottomRows(n) = m.inverse();
    s.c = Eigen::MatrixXd::Zero(n, 2 * n);
    s.c.leftCols(n).setIdentity();
    s.d = Eigen::MatrixXd::Zero(n, n);
    return s;
}

} // namespace

SafetyVerdict checkTrial(const RobotModel &model, const Eigen::VectorXd &phiHat,
                         const TrialPlan &plan, double margin, int points)
{
    const int n = model.dof();
    const double ts = plan.desired.samplePeriod;
    SafetyVerdict v;
    v.torqueLimit = plan.torqueLimit;
    v.motionDuration = plan.motionDuration;
    v.peakTorque = plan.feedforward.cwiseAbs().rowwise().maxCoeff();

    // Controller: block diagonal of the joints' discrete PIDs (3 states each).
    const PidController pid(plan.controller);
    const int nc = 3 * n;
    Eigen::MatrixXd ac = Eigen::MatrixXd::Zero(nc, nc), bc = Eigen::MatrixXd::Zero(nc, n);
    Eigen::MatrixXd cc = Eigen::MatrixXd::Zero(n, nc), dc = Eigen::MatrixXd::Zero(n, n);
    for (int j = 0; j < n; ++j) {
        const StateSpace &d = pid.joint(j);
        ac.block(3 * j, 3 * j, 3, 3) = d.a;
        bc.block(3 * j, j, 3, 1) = d.b;
        cc.block(j, 3 * j, 1, 3) = d.c;
        dc(j, j) = d.d(0, 0);
    }

    const int samples = plan.samples();
    const int count = std::max(2, points);
    for (int p = 0; p < count; ++p) {
        const int k = int(std::lround(double(p) * (samples - 1) / (count - 1)));
        const Eigen::VectorXd q = plan.desired.q.col(k);
        if (!model.massMatrixPositiveDefinite(q, phiHat)) {
            v.physical = false;
            v.worstTime = k * ts;
            break;
        }
        const StateSpace plant = zeroOrderHold(
            linearisedPlant(model, phiHat, q, plan.desired.qd.col(k), plan.desired.qdd.col(k)), ts);
        // Closed loop: x+ = Phi x + Gamma u, u = Cc xc - Dc C x; xc+ = Ac xc - Bc C x.
        const int np = plant.states();
        Eigen::MatrixXd cl(np + nc, np + nc);
        cl.topLeftCorner(np, np) = plant.a - plant.b * dc * plant.c;
        cl.topRightCorner(np, nc) = plant.b * cc;
        cl.bottomLeftCorner(nc, np) = -bc * plant.c;
        cl.bottomRightCorner(nc, nc) = ac;
        const Eigen::EigenSolver<Eigen::MatrixXd> es(cl, false);
        const double radius = es.eigenvalues().cwiseAbs().maxCoeff();
        if (radius > v.worstSpectralRadius) {
            v.worstSpectralRadius = radius;
            v.worstTime = k * ts;
        }
    }
    v.worstDecayRate = std::log(std::max(v.worstSpectralRadius, 1e-300)) / ts;
    v.stable = v.physical && v.worstDecayRate < -margin;
    int overJoint = -1;
    for (int j = 0; j < n; ++j)
        if (v.peakTorque[j] > v.torqueLimit[j] && overJoint < 0)
            overJoint = j;
    v.torqueWithinLimits = overJoint < 0;

    if (!v.physical) {
        v.reason = tr("the estimate is not a physical robot: its mass matrix is not positive "
                      "definite at t = %1 s")
                       .arg(v.worstTime, 0, 'f', 3);
    } else if (!v.stable) {
        v.reason = tr("the closed loop would be unstable: linearised along the path with the "
                      "current estimate, a pole has |z| = %1 (growth rate %2 1/s) at t = %3 s. "
                      "Raise the derivative filter bandwidth lambda or lower the gains")
                       .arg(v.worstSpectralRadius, 0, 'f', 5)
                       .arg(v.worstDecayRate, 0, 'g', 3)
                       .arg(v.worstTime, 0, 'f', 3);
    } else if (!v.torqueWithinLimits) {
        v.reason = tr("planned torque of joint %1 is %2 N m, above its limit of %3 N m")
                       .arg(overJoint + 1)
                       .arg(v.peakTorque[overJoint], 0, 'f', 3)
                       .arg(v.torqueLimit[overJoint], 0, 'f', 3);
    }
    return v;
}

} // namespace learnid
