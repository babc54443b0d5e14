#include "control/PidController.h"

namespace learnid {

StateSpace pidStateSpace(double kp, double ki, double kd, double lambda)
{
    // x0' = e (integral); x1' = x2, x2' = -lambda^2 x1 - 2 lambda x2 + e, so that
    // x2 = s/(s + lambda)^2 e and lambda^2 x2 is the filtered derivative of e.
    StateSpace s;
    s.a = Eigen::MatrixXd::Zero(3, 3);
    s.a(1, 2) = 1.0;
    s.a(2, 1) = -lambda * lambda;
    s.a(2, 2) = -2.0 * lambda;
    s.b = Eigen::MatrixXd::Zero(3, 1);
    s.b(0, 0) = 1.0;
    s.b(2, 0) = 1.0;
    s.c = Eigen::MatrixXd::Zero(1, 3);
    s.c(0, 0) = ki;
    s.c(0, 2) = kd * lambda * lambda;
    s.d = Eigen::MatrixXd::Constant(1, 1, kp);
    return s;
}

PidController::PidController(const ControllerSettings &settings)
{
    for (int j = 0; j < settings.dof(); ++j) {
        const StateSpace d =
            tustin(pidStateSpace(settings.kp[j], settings.ki[j], settings.kd[j], settings.lambda),
                   settings.samplePeriod);
        Joint joint;
        joint.a = d.a;
        joint.b = d.b;
        joint.c = d.c;
        joint.d = d.d(0, 0);
        m_joints.push_back(joint);
        m_discrete.push_back(d);
    }
}

void PidController::reset()
{
    for (Joint &j : m_joints)
        j.x.setZero();
}

void PidController::step(const Eigen::Ref<const Eigen::VectorXd> &e, Eigen::Ref<Eigen::VectorXd> u)
{
    for (int i = 0; i < dof(); ++i) {
        Joint &j = m_joints[size_t(i)];
        u[i] = j.c.dot(j.x) + j.d * e[i];
        j.x = j.a * j.x + j.b * e[i];
    }
}

} // namespace learnid
