// learnid-bench-payload --arm-error FRACTION (issue 25): the bias a wrong arm model puts into the
// payload learned in the loop, and what a baseline trial takes out. The simulated KUKA LWR4+
// (3 kg) and Panda (1.5 kg) of --loop (tests/session/PayloadScenarios.h), but the real arm's links
// and friction changed at random by up to +-FRACTION (simulation.inertiaPerturbation, a new arm
// per seed) while the session's arm model stays the CAD one; 8 seeds, 3 payload trials. Each seed
// runs twice: without a baseline, and with payload.baselineTrials 1 (the same timed path run
// first without the payload, its residual taken out of every payload trial).
#include "../tests/session/PayloadScenarios.h"
#include "../tests/support/SharedData.h"
#include "BenchSupport.h"
#include "model/ModelFactory.h"
#include "model/PayloadPrior.h"
#include "session/PayloadSession.h"
#include "session/ScenarioRobot.h"

#include <cstdio>

using namespace learnid;

namespace {

struct Errors
{
    double mass = qQNaN(), com = qQNaN(), inertia = qQNaN();
    QString failure;
};

Errors learn(Scenario s, int baselineTrials)
{
    s.payload.baselineTrials = baselineTrials;
    const auto model = makeRobotModel(s.model, s.urdf);
    s = withRobotDefaults(s, *model);
    PayloadSession session(s, model, makeSimulatedRobot(s, model),
                           makeSimulatedBareRobot(s, model));
    Errors e;
    if (!session.runTrials(s.iterations)) {
        e.failure = session.history().back().message;
        return e;
    }
    const PayloadBody &b = session.history().back().fit->estimate.body;
    const PayloadBody truth =
        payloadBody(simulatedPayloadParameters(s.simulation.payload, s.payload));
    e.mass = 100.0 * std::abs(b.mass - truth.mass) / truth.mass;
    e.com = 1000.0 * (b.com - truth.com).norm();
    e.inertia = 100.0 * (b.inertiaAtCom - truth.inertiaAtCom).norm() / truth.inertiaAtCom.norm();
    return e;
}

QString cells(const Errors &e)
{
    if (!e.failure.isEmpty())
        return e.failure + QStringLiteral(" | | ");
    return QStringLiteral("%1 | %2 | %3")
        .arg(e.mass, 0, 'f', 2)
        .arg(e.com, 0, 'f', 2)
        .arg(e.inertia, 0, 'f', 0);
}

void runRobot(const char *name, Scenario given, double fraction)
{
    given.simulation.inertiaPerturbation = fraction;
    given.simulation.trueParameters.resize(0);
    std::printf("\n%s, %.1f kg payload, the real arm +-%.0f %% off its model:\n\n| seed | mass "
                "error %% | CoM error [mm] | inertia error %% | with a baseline trial: mass %% | "
                "CoM [mm] | inertia %% |\n|---|---|---|---|---|---|---|\n",
                name, given.simulation.payload.mass, 100.0 * fraction);
    std::vector<double> mass[2], com[2];
    for (quint64 seed = 1; seed <= 8; ++seed) {
        given.simulation.seed = seed;
        const Errors plain = learn(given, 0), baseline = learn(given, 1);
        for (int k = 0; k < 2; ++k) {
            const Errors &e = k == 0 ? plain : baseline;
            if (e.failure.isEmpty()) {
                mass[k].push_back(e.mass);
                com[k].push_back(e.com);
            }
        }
        std::printf("| %llu | %s | %s |\n", static_cast<unsigned long long>(seed),
                    qPrintable(cells(plain)), qPrintable(cells(baseline)));
    }
    for (int k = 0; k < 2; ++k) {
        if (mass[k].empty())
            continue;
        std::printf("%s: %zu of 8 seeds learned; mass error median %.2f %%, worst %.2f %%; "
                    "centre of mass median %.2f mm, worst %.2f mm\n",
                    k == 0 ? "without a baseline" : "with a baseline trial", mass[k].size(),
                    bench::median(mass[k]), *std::max_element(mass[k].begin(), mass[k].end()),
                    bench::median(com[k]), *std::max_element(com[k].begin(), com[k].end()));
    }
}

} // namespace

int payloadArmErrorBench(double fraction)
{
    const QString kuka = test::sharedDataFile(QStringLiteral("kuka-lwr4/kuka_lwr4.urdf"));
    if (kuka.isEmpty())
        std::printf("KUKA LWR4+ skipped: %s\n", qPrintable(test::sharedDataMissing()));
    else
        runRobot("KUKA LWR4+", test::kukaWithPayload(kuka), fraction);
    runRobot("Panda", test::pandaWithPayload(), fraction);
    return 0;
}
