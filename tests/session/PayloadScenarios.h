#pragma once

// Test support: scenarios of a simulated robot carrying a payload, for tst_payloadsession,
// tst_cli_payload_run and learnid-bench-payload --loop. The arm's model is the true arm (no
// perturbation), 2^20-count encoders, 1 % torque noise; the gains are stiff enough to hold the
// payload within the 5 deg tracking limit while its estimate is still the prior.

#include "session/RobotScenario.h"
#include "types/Scenario.h"

#include <cmath>
#include <initializer_list>

namespace learnid::test {

inline Eigen::VectorXd jointValues(std::initializer_list<double> v)
{
    Eigen::VectorXd q(Eigen::Index(v.size()));
    Eigen::Index i = 0;
    for (double x : v)
        q[i++] = x;
    return q;
}

/// The KUKA LWR4+ (urdf: ../shared/data/kuka-lwr4/kuka_lwr4.urdf) carrying 3 kg 5 cm off the
/// flange axis (cz 8 cm); the prior 2.5 kg on the axis at 5 cm.
inline Scenario kukaWithPayload(const QString &urdf)
{
    Scenario s;
    s.model = QStringLiteral("urdf");
    s.urdf.file = urdf;
    s.torqueLimits.resize(0);
    s.initialParameters.resize(0);
    s.simulation.trueParameters.resize(0);
    s.path.kind = PathKind::Waypoints;
    s.path.waypoints = {jointValues({0, 0.3, 0, -1.2, 0, 0.5, 0}),
                        jointValues({0.8, 0.8, 0.5, -0.6, 0.6, -0.4, 0.9}),
                        jointValues({-0.4, 0.5, -0.5, -1.4, -0.5, 0.6, -0.7})};
    s.planningFraction = 0.45;
    s.controller.kp = jointValues({340, 600, 100, 140, 60, 60, 30});
    s.controller.ki = s.controller.kp / 10.0;
    s.controller.kd = jointValues({45, 80, 14, 19, 3, 3, 1.5});
    s.controller.lambda = 1000;
    s.maxTrackingErrorDeg = 5;
    s.simulation.encoderCounts = 1 << 20;
    s.simulation.torqueNoise = 0.01;
    s.simulation.substeps = 5;
    s.iterations = 3;
    s.payload.enabled = true;
    s.payload.mass = 2.5;
    s.payload.com = Eigen::Vector3d(0.0, 0.0, 0.05);
    s.simulation.payload.present = true;
    s.simulation.payload.mass = 3.0;
    s.simulation.payload.com = Eigen::Vector3d(0.05, 0.0, 0.08);
    s.simulation.payload.inertia << 0.012, 0.001, 0.011, 0.0, 0.0, 0.006;
    return s;
}

/// The Panda's starting scenario (scenarioForRobot) carrying 1.5 kg 5 cm off the flange axis
/// (cz 8 cm), the prior 1.2 kg on the axis at 5 cm; its gains doubled and the wrist's six-fold
/// (the bare arm's would let the payload sag past the limit), damping along.
inline Scenario pandaWithPayload()
{
    Scenario s = scenarioForRobot(QStringLiteral("panda"));
    s.simulation.inertiaPerturbation = 0.0; // the arm's model is the true arm
    for (int j = 0; j < 7; ++j) {
        const double wrist = j >= 4 ? 3.0 : 1.0;
        s.controller.kp[j] *= 2.0 * wrist;
        s.controller.kd[j] *= 1.4 * std::sqrt(wrist);
        s.controller.ki[j] = s.controller.kp[j] / 10.0;
    }
    s.iterations = 3;
    s.payload.enabled = true;
    s.payload.link = QStringLiteral("panda_link7");
    s.payload.mass = 1.2;
    s.payload.com = Eigen::Vector3d(0.0, 0.0, 0.05);
    s.simulation.payload.present = true;
    s.simulation.payload.mass = 1.5;
    s.simulation.payload.com = Eigen::Vector3d(0.05, 0.0, 0.08);
    s.simulation.payload.inertia << 0.006, 0.0005, 0.0055, 0.0, 0.0, 0.003;
    return s;
}

/// The Panda at its rated payload, the 3 kg case: 3 kg 5 cm off the flange axis (cz 8
/// cm), the prior 2.5 kg on the axis at 5 cm, from the payload starter (scenarioForRobot with the
/// prior: gains and path for the arm carrying it; the bare arm's stretched path needs more than
/// the planner allows at joint 2 once the estimate nears 3 kg).
inline Scenario pandaWithRatedPayload()
{
    PayloadSettings prior;
    prior.enabled = true;
    prior.link = QStringLiteral("panda_link7");
    prior.mass = 2.5;
    prior.com = Eigen::Vector3d(0.0, 0.0, 0.05);
    Scenario s = scenarioForRobot(QStringLiteral("panda"), {}, prior);
    s.simulation.inertiaPerturbation = 0.0; // the arm's model is the true arm
    s.iterations = 3;
    s.simulation.payload.present = true;
    s.simulation.payload.mass = 3.0;
    s.simulation.payload.com = Eigen::Vector3d(0.05, 0.0, 0.08);
    s.simulation.payload.inertia << 0.012, 0.001, 0.011, 0.0, 0.0, 0.006;
    return s;
}

} // namespace learnid::test
