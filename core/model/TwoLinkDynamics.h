#pragma once

#include <QtGlobal>
#include <cmath>

namespace learnid::twolink {

// The paper's 2-link arm (TwoLinkArm) as inline kernels on plain doubles, for the simulator's
// inner loop (131,000 RK4 steps per 6-trial session): no virtual call, no Eigen::Ref, and one
// sin/cos of d = theta2 - theta1 per sample period instead of one per RK4 step.

/// sin and cos of d + delta from s = sin d, c = cos d. The series below are exact to double
/// precision (the first omitted term below half an ulp of the result) for |delta| < 1e-4
/// (delta^5/5!: relative 1e-18; delta^4/4!: 4e-18), |delta| < 1e-3 (delta^7/7!, delta^6/6!:
/// below 2e-21) and |delta| < 0.01 (delta^9/9!, delta^8/8!: below 1e-20); larger steps evaluate
/// sin and cos of d + delta directly. The RK4 stages of the paper scenario rotate by 1e-6 to
/// 1e-4 rad.
Q_ALWAYS_INLINE void rotate(double d, double s, double c, double delta, double &sOut, double &cOut)
{
    const double d2 = delta * delta;
    const double size = std::abs(delta);
    double sd, cd;
    if (size < 1e-4) {
        sd = delta * (1.0 - d2 * (1.0 / 6.0));
        cd = 1.0 - d2 * 0.5;
    } else if (size < 1e-3) {
        sd = delta * (1.0 - d2 * (1.0 / 6.0) * (1.0 - d2 * (1.0 / 20.0)));
        cd = 1.0 - d2 * 0.5 * (1.0 - d2 * (1.0 / 12.0));
    } else if (size < 0.01) {
        sd = delta * (1.0 - d2 / 6.0 * (1.0 - d2 / 20.0 * (1.0 - d2 / 42.0)));
        cd = 1.0 - d2 / 2.0 * (1.0 - d2 / 12.0 * (1.0 - d2 / 30.0));
    } else {
        sOut = std::sin(d + delta);
        cOut = std::cos(d + delta);
        return;
    }
    sOut = s * cd + c * sd;
    cOut = c * cd - s * sd;
}

/// qdd [rad/s^2] (2) of eq. (21) at velocities qd [rad/s] (2) under tau [N m] (2), given
/// sd = sin d and cd = cos d, d = theta2 - theta1; phi = (a, b, c) [kg m^2].
Q_ALWAYS_INLINE void accelerations(double sd, double cd, const double *qd, const double *tau,
                                   const double *phi, double *qdd)
{
    const double bc = phi[1] * cd;
    const double bs = phi[1] * sd;
    const double r0 = tau[0] + bs * qd[1] * qd[1];
    const double r1 = tau[1] - bs * qd[0] * qd[0];
    const double inverseDet = 1.0 / (phi[0] * phi[2] - bc * bc); // a c > b^2 for a physical phi
    qdd[0] = (phi[2] * r0 - bc * r1) * inverseDet;
    qdd[1] = (phi[0] * r1 - bc * r0) * inverseDet;
}

/// One classical RK4 step of length h [s] of eq. (21) with tau held, updating q [rad] (2) and
/// qd [rad/s] (2) in place. s and c hold sin and cos of q[1] - q[0] on entry and are carried to
/// the new angle on return by the same exact rotation the stages use.
Q_ALWAYS_INLINE void rk4Step(double *q, double *qd, double &s, double &c, const double *tau,
                             const double *phi, double h)
{
    const double d = q[1] - q[0];
    const double v1[2] = {qd[0], qd[1]};
    double a1[2], a2[2], a3[2], a4[2], v2[2], v3[2], v4[2], ss, cs;
    accelerations(s, c, v1, tau, phi, a1);
    // Stage angles: d + h/2 (v1_2 - v1_1), d + h/2 (v2_2 - v2_1), d + h (v3_2 - v3_1).
    v2[0] = v1[0] + 0.5 * h * a1[0];
    v2[1] = v1[1] + 0.5 * h * a1[1];
    rotate(d, s, c, 0.5 * h * (v1[1] - v1[0]), ss, cs);
    accelerations(ss, cs, v2, tau, phi, a2);
    v3[0] = v1[0] + 0.5 * h * a2[0];
    v3[1] = v1[1] + 0.5 * h * a2[1];
    rotate(d, s, c, 0.5 * h * (v2[1] - v2[0]), ss, cs);
    accelerations(ss, cs, v3, tau, phi, a3);
    v4[0] = v1[0] + h * a3[0];
    v4[1] = v1[1] + h * a3[1];
    rotate(d, s, c, h * (v3[1] - v3[0]), ss, cs);
    accelerations(ss, cs, v4, tau, phi, a4);
    for (int i = 0; i < 2; ++i) {
        q[i] += (h / 6.0) * (v1[i] + 2.0 * v2[i] + 2.0 * v3[i] + v4[i]);
        qd[i] += (h / 6.0) * (a1[i] + 2.0 * a2[i] + 2.0 * a3[i] + a4[i]);
    }
    const double dNew = q[1] - q[0];
    rotate(d, s, c, dNew - d, s, c);
}

/// `steps` RK4 steps of length h with tau held (one sample period of the simulator). The
/// sin/cos of d is evaluated once, at the start; the steps carry it by exact rotations, whose
/// rounding (a few 1e-16 over a sample period) is of the order of the angle's own.
inline void rk4Steps(double *q, double *qd, const double *tau, const double *phi, double h,
                     int steps)
{
    // Local copies keep the state in registers through the steps.
    double x[2] = {q[0], q[1]}, v[2] = {qd[0], qd[1]};
    const double t[2] = {tau[0], tau[1]}, p[3] = {phi[0], phi[1], phi[2]};
    const double d = x[1] - x[0];
    double s = std::sin(d);
    double c = std::cos(d);
    for (int i = 0; i < steps; ++i)
        rk4Step(x, v, s, c, t, p, h);
    q[0] = x[0];
    q[1] = x[1];
    qd[0] = v[0];
    qd[1] = v[1];
}

} // namespace learnid::twolink
