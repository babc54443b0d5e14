// learnid-bench-payload --starter (issue 25): the starting scenario for an arm carrying a payload
// (`scenario --print --robot R --payload ...`, scenarioForRobot with a payload section) on the
// simulated Panda, KUKA LWR4+ and PUMA 560, the payload heavier than the technician's prior and
// 5 cm off the flange axis (cz 8 cm), 2^20 counts, 1 % torque noise, 8 seeds, 3 payload trials:
// with the arm's model exact, and with the real arm 30 % off it (the starter's own simulation)
// and one baseline trial. Against the bare arm's starter given the same payload section. With a
// clock other than 2 ms (--starter MS), both designed for it (scenarioForRobot's samplePeriod),
// and the payload starter designed for 2 ms run at that clock.
#include "../tests/support/SharedData.h"
#include "BenchSupport.h"
#include "model/Error.h"
#include "model/ModelFactory.h"
#include "session/PayloadSession.h"
#include "session/RobotScenario.h"
#include "session/ScenarioRobot.h"

#include <cmath>
#include <cstdio>
#include <utility>

using namespace learnid;

namespace {

struct Case
{
    const char *name;
    QString robot; ///< scenarioForRobotName's
    double prior, truth;
};

struct Outcome
{
    int completed = 0;
    double trial0 = 0.0, mass = 0.0, com = 0.0; ///< worst over the seeds that completed
};

enum class Starter { Payload, PayloadFor2ms, Bare };

Outcome run(const Case &c, Starter starter, bool wrongArm, double samplePeriod)
{
    PayloadSettings prior;
    prior.enabled = true;
    prior.mass = c.prior;
    prior.com = Eigen::Vector3d(0.0, 0.0, 0.05);
    Outcome o;
    for (quint64 seed = 1; seed <= 8; ++seed) {
        Scenario s;
        try {
            s = starter == Starter::Bare
                    ? scenarioForRobotName(c.robot, {}, samplePeriod)
                    : scenarioForRobotName(c.robot, prior,
                                           starter == Starter::Payload ? samplePeriod : 0.002);
        } catch (const Error &e) { // no design for this clock: no session completes
            std::fprintf(stderr, "%s: %s\n", c.name, qPrintable(e.message()));
            return o;
        }
        s.controller.samplePeriod = samplePeriod;
        if (starter == Starter::Bare)
            s.payload = prior;
        s.payload.baselineTrials = wrongArm ? 1 : 0;
        s.simulation.payload.present = true;
        s.simulation.payload.mass = c.truth;
        s.simulation.payload.com = Eigen::Vector3d(0.05, 0.0, 0.08);
        s.simulation.payload.inertia << 0.006, 0.0005, 0.0055, 0.0, 0.0, 0.003;
        s.simulation.inertiaPerturbation = wrongArm ? 0.3 : 0.0;
        s.simulation.seed = seed;
        const auto model = makeRobotModel(s.model, s.urdf);
        s = withRobotDefaults(s, *model);
        PayloadSession session(s, model, makeSimulatedRobot(s, model),
                               makeSimulatedBareRobot(s, model));
        if (!session.runTrials(3)) { // why, on stderr
            std::fprintf(stderr, "%s %.1f -> %.1f kg, seed %llu: %s\n", c.name, c.prior, c.truth,
                         seed, qPrintable(session.history().back().message));
            continue;
        }
        ++o.completed;
        const PayloadBody &b = session.history().back().fit->estimate.body;
        o.mass = std::max(o.mass, 100.0 * std::abs(b.mass - c.truth) / c.truth);
        o.com = std::max(o.com, 1000.0 * (b.com - Eigen::Vector3d(0.05, 0.0, 0.08)).norm());
        for (const PayloadTrial &t : session.history())
            if (!t.baseline)
                o.trial0 = std::max(o.trial0, t.maxTrackingErrorDeg.maxCoeff());
    }
    return o;
}

QString cells(const Outcome &o)
{
    if (o.completed == 0)
        return QStringLiteral("0 / 8 | | | ");
    return QStringLiteral("%1 / 8 | %2 | %3 | %4")
        .arg(o.completed)
        .arg(o.trial0, 0, 'f', 2)
        .arg(o.mass, 0, 'f', 2)
        .arg(o.com, 0, 'f', 2);
}

} // namespace

int payloadStarterBench(double samplePeriod)
{
    std::vector<Case> cases = {{"Panda", QStringLiteral("panda"), 1.2, 1.5},
                               {"Panda", QStringLiteral("panda"), 0.5, 1.0},
                               {"Panda", QStringLiteral("panda"), 2.5, 3.0},
                               {"PUMA 560", QStringLiteral("puma560"), 2.0, 2.5}};
    const QString kuka = test::sharedDataFile(QStringLiteral("kuka-lwr4/kuka_lwr4.urdf"));
    if (!kuka.isEmpty()) {
        cases.push_back({"KUKA LWR4+", kuka, 2.5, 3.0});
        cases.push_back({"KUKA LWR4+", kuka, 5.0, 7.0});
    }
    const bool at2ms = std::abs(samplePeriod - 0.002) < 1e-12;
    std::vector<std::pair<Starter, const char *>> starters = {
        {Starter::Payload, at2ms ? "with the payload" : "with the payload, for this clock"},
        {Starter::Bare, "bare arm's"}};
    if (!at2ms)
        starters.insert(starters.begin() + 1,
                        {Starter::PayloadFor2ms, "with the payload, for 2 ms"});
    std::printf("robot's clock %g ms\n\n", 1000.0 * samplePeriod);
    std::printf(
        "| robot | prior -> payload [kg] | starter | arm | sessions of 3 trials completed | "
        "worst max tracking error of a payload trial [deg] | worst mass error %% | worst "
        "CoM error [mm] |\n|---|---|---|---|---|---|---|---|\n");
    for (const Case &c : cases) {
        for (const bool wrongArm : {false, true}) {
            for (const auto &[starter, name] : starters) {
                std::printf("| %s | %.1f -> %.1f | %s | %s | %s |\n", c.name, c.prior, c.truth,
                            name, wrongArm ? "30 % off, 1 baseline trial" : "exact",
                            qPrintable(cells(run(c, starter, wrongArm, samplePeriod))));
            }
        }
    }
    return 0;
}
