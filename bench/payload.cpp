// learnid-bench-payload (issue 25): a 3 kg payload 5 cm off the KUKA LWR4+'s flange axis fitted
// to a simulated 5 s log at 500 Hz (the arm's URDF from ../shared/data held fixed, 1 % of each
// joint's limit as torque noise, 2^20-count encoders), 8 seeds: the errors of mass, centre of
// mass and inertia, and the CPU of one payload update (filtering the log, the regressor, the
// fit), the median of 20. With --loop: the payload learned in the learning loop instead
// (payloadloop.cpp); with --arm-error FRACTION: the bias of a wrong arm model, with and without a
// baseline trial (payloadarmerror.cpp); with --starter: the starting scenario for an arm with a
// payload (payloadstarter.cpp); with --starter MS: the same at a robot's clock of MS ms.
#include "../tests/identify/PayloadPaths.h"
#include "BenchSupport.h"
#include "identify/LogSignals.h"
#include "identify/PayloadBaseline.h"
#include "identify/PayloadFit.h"
#include "model/ChainPerturbation.h"
#include "service/PayloadIdentification.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>

using namespace learnid;

namespace {

PayloadBody truePayload()
{
    PayloadBody b;
    b.mass = 3.0;
    b.com = Eigen::Vector3d(0.05, 0.0, 0.08);
    b.inertiaAtCom << 0.012, 0.001, 0.0, 0.001, 0.011, 0.0, 0.0, 0.0, 0.006;
    return b;
}

UniformLog simulatedLog(const PayloadModel &model, const test::JointPath &path, unsigned seed,
                        const InertialParameters &payload = truePayload().parameters())
{
    std::mt19937 random(seed);
    std::normal_distribution<double> normal(0.0, 1.0);
    const double count = 2.0 * M_PI / double(1 << 20);
    UniformLog log;
    log.source = QStringLiteral("simulated");
    log.period = path.period;
    log.q = (path.q / count).array().round() * count;
    log.dq = path.qd;
    log.tau.resize(model.dof(), path.q.cols());
    for (Eigen::Index k = 0; k < path.q.cols(); ++k) {
        log.tau.col(k) = model.torqueAt(path.q.col(k), path.qd.col(k), path.qdd.col(k), payload);
        for (int j = 0; j < model.dof(); ++j)
            log.tau(j, k) +=
                0.01 * model.arm().chain().joints[size_t(j)].effortLimit * normal(random);
    }
    return log;
}

// From logs with the real arm +-fraction off the URDF held fixed: a 5 s log with the payload and a
// baseline log of the same motion without it (other noise), recorded 0.3 s earlier.
void armErrorFromLogs(const std::shared_ptr<const ChainModel> &arm, double fraction)
{
    const PayloadModel model(arm, arm->cadStandard());
    PayloadPrior prior;
    prior.mass = 2.5;
    prior.com = Eigen::Vector3d(0.0, 0.0, 0.05);
    const LogFilterSettings filter;
    const test::JointPath path = test::richPath(*arm, 5.3, 0.002);
    test::JointPath part = path;
    part.q = path.q.middleCols(150, 2501);
    part.qd = path.qd.middleCols(150, 2501);
    part.qdd = path.qdd.middleCols(150, 2501);
    std::printf(
        "\nKUKA LWR4+ from logs, the real arm +-%.0f %% off the URDF held fixed:\n\n| seed | "
        "mass error %% | CoM error [mm] | with a baseline log: mass %% | CoM [mm] | "
        "shift [s] |\n|---|---|---|---|---|---|\n",
        100.0 * fraction);
    double worst[2][2] = {{0, 0}, {0, 0}};
    for (unsigned seed = 1; seed <= 8; ++seed) {
        const PayloadModel real(arm, perturbedStandard(*arm, fraction, seed));
        const FilteredLog with = filterLog(simulatedLog(real, part, seed), filter);
        const FilteredLog without =
            filterLog(simulatedLog(real, path, seed + 100, InertialParameters::Zero()), filter);
        std::vector<BaselineAlignment> laid;
        const FilteredLog subtracted =
            withBaselineSubtracted(model, with, {without}, recordedBaselineSettings(), &laid);
        double e[2][2];
        for (int k = 0; k < 2; ++k) {
            const PayloadBody b =
                fitPayload(model, {k == 0 ? with : subtracted}, prior).estimate.body;
            e[k][0] = 100.0 * std::abs(b.mass - 3.0) / 3.0;
            e[k][1] = 1000.0 * (b.com - truePayload().com).norm();
            worst[k][0] = std::max(worst[k][0], e[k][0]);
            worst[k][1] = std::max(worst[k][1], e[k][1]);
        }
        std::printf("| %u | %.2f | %.2f | %.2f | %.2f | %.3f |\n", seed, e[0][0], e[0][1], e[1][0],
                    e[1][1], laid.front().shiftSeconds);
    }
    std::printf("worst of 8 seeds: without a baseline mass %.2f %%, centre of mass %.2f mm; with "
                "a baseline log %.2f %%, %.2f mm\n",
                worst[0][0], worst[0][1], worst[1][0], worst[1][1]);
}

} // namespace

int payloadLoopBench();
int payloadArmErrorBench(double fraction);
int payloadStarterBench(double samplePeriod);

int main(int argc, char **argv)
{
    if (argc > 1 && std::strcmp(argv[1], "--loop") == 0)
        return payloadLoopBench();
    if (argc > 1 && std::strcmp(argv[1], "--starter") == 0) {
        const double ms = argc > 2 ? std::atof(argv[2]) : 2.0;
        if (!(ms > 0.0 && ms <= 100.0)) {
            std::printf("--starter: a clock in ms, above 0 and at most 100, not %s\n", argv[2]);
            return 2;
        }
        return payloadStarterBench(ms / 1000.0);
    }
    if (argc > 2 && std::strcmp(argv[1], "--arm-error") == 0) {
        const double fraction = std::atof(argv[2]);
        if (!(fraction >= 0.0 && fraction < 1.0)) {
            std::printf("--arm-error: a fraction in [0, 1), not %s\n", argv[2]);
            return 2;
        }
        if (const auto arm = test::kukaArm())
            armErrorFromLogs(arm, fraction);
        return payloadArmErrorBench(fraction);
    }
    const auto arm = test::kukaArm();
    if (!arm) {
        std::printf("%s\n", qPrintable(test::sharedDataMissing()));
        return 1;
    }
    const PayloadModel model(arm, arm->cadStandard());
    PayloadPrior prior;
    prior.mass = 2.5;
    prior.com = Eigen::Vector3d(0.0, 0.0, 0.05);
    const LogFilterSettings filter;
    std::printf("| seed | mass error %% | CoM error [mm] | inertia error (Frobenius, of |I_c|) %% "
                "| cz std. error [mm] |\n|---|---|---|---|---|\n");
    std::vector<double> cpu;
    const test::JointPath path = test::richPath(*arm, 5.0, 0.002);
    double worstMass = 0.0, worstCom = 0.0;
    for (unsigned seed = 1; seed <= 8; ++seed) {
        const UniformLog log = simulatedLog(model, path, seed);
        const PayloadFit fit = fitPayload(model, {filterLog(log, filter)}, prior);
        const PayloadBody &b = fit.estimate.body;
        const double mass = 100.0 * std::abs(b.mass - 3.0) / 3.0;
        const double com = 1000.0 * (b.com - truePayload().com).norm();
        worstMass = std::max(worstMass, mass);
        worstCom = std::max(worstCom, com);
        std::printf("| %u | %.3f | %.2f | %.0f | %.2f |\n", seed, mass, com,
                    100.0 * (b.inertiaAtCom - truePayload().inertiaAtCom).norm() /
                        truePayload().inertiaAtCom.norm(),
                    1000.0 * fit.estimate.bodyStandardError[3]);
    }
    const UniformLog log = simulatedLog(model, path, 99);
    for (int i = 0; i < 20; ++i) {
        const double start = bench::cpuSeconds();
        const PayloadFit fit = fitPayload(model, {filterLog(log, filter)}, prior);
        cpu.push_back(bench::cpuSeconds() - start);
        if (!(fit.estimate.body.mass > 0.0))
            return 1;
    }
    std::printf("\nworst of 8 seeds: mass %.3f %%, centre of mass %.2f mm\n", worstMass, worstCom);
    std::printf("one payload update (filter, regressor, fit) of %lld samples x 7 joints: %.1f ms "
                "CPU (median of 20)\n",
                static_cast<long long>(log.q.cols()), 1000.0 * bench::median(cpu));
    return 0;
}
