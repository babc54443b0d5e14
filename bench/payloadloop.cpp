// learnid-bench-payload --loop (issue 25): the payload learned in the learning loop
// (PayloadSession) on the simulated KUKA LWR4+ (3 kg) and Panda (1.5 kg, and its rated 3 kg), 5
// cm off the flange axis, the arm's model the true arm, 2^20-count encoders, 1 % torque noise, 8
// noise seeds, 3 trials each (tests/session/PayloadScenarios.h): the errors of mass, centre of
// mass and inertia after trial 2, trial 2's max tracking error against the same timed path run
// with the true payload in the feedforward and without the payload (arm alone), and the CPU of
// the payload update after trial 2 (filter, regressor and fit over 3 trials).
#include "../tests/session/PayloadScenarios.h"
#include "../tests/support/SharedData.h"
#include "BenchSupport.h"
#include "model/ModelFactory.h"
#include "model/PayloadPrior.h"
#include "session/PayloadPathChange.h"
#include "session/PayloadSession.h"
#include "session/ScenarioRobot.h"

#include <cstdio>

using namespace learnid;

namespace {

// Max tracking error over the joints [deg] of `plan` run on `robot`.
double trackingOf(Robot &robot, const TrialPlan &plan)
{
    const TrialRecord record = robot.runTrial(plan, {});
    Eigen::VectorXd maxDeg, rmsDeg;
    trackingErrorFigures(plan, record, maxDeg, rmsDeg);
    return record.completed() ? maxDeg.maxCoeff() : qQNaN();
}

void runRobot(const char *name, const Scenario &given)
{
    std::printf("\n%s, %.1f kg payload:\n\n| seed | mass error %% | CoM error [mm] | inertia error "
                "%% | max tracking error trial 0 / 2 [deg] | same path, true payload's "
                "feedforward [deg] | same path, no payload [deg] | update CPU [ms] |\n"
                "|---|---|---|---|---|---|---|---|\n",
                name, given.simulation.payload.mass);
    std::vector<double> mass, com, inertia, ratio, cpu;
    long long samples = 0;
    Eigen::Matrix<double, 10, 1> predicted = Eigen::Matrix<double, 10, 1>::Zero();
    for (quint64 seed = 1; seed <= 8; ++seed) {
        Scenario s = given;
        s.simulation.seed = seed;
        const auto model = makeRobotModel(s.model, s.urdf);
        s = withRobotDefaults(s, *model);
        PayloadSession session(s, model, makeSimulatedRobot(s, model));
        if (!session.runTrials(3)) {
            std::printf("| %llu | %s |\n", static_cast<unsigned long long>(seed),
                        qPrintable(session.history().back().message));
            continue;
        }
        const PayloadTrial &last = session.history().back();
        // The standard errors the three planned paths predict at the simulated noise (1 % of
        // each joint's limit per sample): each path's inverse variances add up.
        Eigen::Matrix<double, 10, 1> information = Eigen::Matrix<double, 10, 1>::Zero();
        for (const PayloadTrial &t : session.history())
            information += payloadPredictedStdErrors(session.payloadModel(), t.plan().desired,
                                                     s.simulation.torqueNoise * s.torqueLimits)
                               .cwiseAbs2()
                               .cwiseInverse();
        predicted = predicted.cwiseMax(information.cwiseInverse().cwiseSqrt());
        const PayloadBody &b = last.fit->estimate.body;
        const PayloadBody truth =
            payloadBody(simulatedPayloadParameters(s.simulation.payload, s.payload));
        mass.push_back(100.0 * std::abs(b.mass - truth.mass) / truth.mass);
        com.push_back(1000.0 * (b.com - truth.com).norm());
        inertia.push_back(100.0 * (b.inertiaAtCom - truth.inertiaAtCom).norm() /
                          truth.inertiaAtCom.norm());
        // The same timed path (planned with trial 2's estimate), its feedforward from the arm
        // with the true payload, and from the arm alone on the robot without the payload.
        TrialPlanner planner(s, model);
        const Eigen::VectorXd planned = session.feedforwardParameters(last.payloadUsed);
        const Eigen::VectorXd withTruth = session.feedforwardParameters(truth.parameters());
        const double oracle = trackingOf(*makeSimulatedRobot(s, model),
                                         planner.plan(planned, nullptr, false, &withTruth));
        const double alone =
            trackingOf(*makeSimulatedBareRobot(s, model),
                       planner.plan(planned, nullptr, false, &s.initialParameters));
        const double trial2 = last.maxTrackingErrorDeg.maxCoeff();
        ratio.push_back(trial2 / alone);
        cpu.push_back(1000.0 * last.updateCpuSeconds);
        samples = last.fit->samples;
        std::printf("| %llu | %.3f | %.2f | %.0f | %.3g / %.3g | %.3g | %.3g | %.1f |\n",
                    static_cast<unsigned long long>(seed), mass.back(), com.back(), inertia.back(),
                    session.history().front().maxTrackingErrorDeg.maxCoeff(), trial2, oracle, alone,
                    cpu.back());
    }
    if (mass.empty())
        return;
    std::printf(
        "\nworst of %zu seeds: mass %.3f %%, centre of mass %.2f mm, inertia %.0f %%; "
        "trial 2's max tracking error / the arm's without the payload: median %.2f, "
        "worst %.2f; update CPU median %.1f ms (%lld samples of 3 trials, after the filter's "
        "settling)\n",
        mass.size(), *std::max_element(mass.begin(), mass.end()),
        *std::max_element(com.begin(), com.end()),
        *std::max_element(inertia.begin(), inertia.end()), bench::median(ratio),
        *std::max_element(ratio.begin(), ratio.end()), bench::median(cpu), samples);
    // An inertia entry (about the link frame) smaller than three of its predicted standard errors
    // is not told from zero: the smallest inertia these paths identify.
    std::printf("smallest identifiable inertia (3 predicted standard errors after 3 trials, about "
                "the link frame, Ixx Ixy Iyy Ixz Iyz Izz): %.2g %.2g %.2g %.2g %.2g %.2g kg m^2\n",
                3.0 * predicted[4], 3.0 * predicted[5], 3.0 * predicted[6], 3.0 * predicted[7],
                3.0 * predicted[8], 3.0 * predicted[9]);
}

} // namespace

int payloadLoopBench()
{
    const QString kuka = test::sharedDataFile(QStringLiteral("kuka-lwr4/kuka_lwr4.urdf"));
    if (kuka.isEmpty())
        std::printf("KUKA LWR4+ skipped: %s\n", qPrintable(test::sharedDataMissing()));
    else
        runRobot("KUKA LWR4+", test::kukaWithPayload(kuka));
    runRobot("Panda", test::pandaWithPayload());
    runRobot("Panda", test::pandaWithRatedPayload());
    return 0;
}
