// learnid-bench-chain, speed (issue 13): inverse dynamics of the LWR4+ against Orocos KDL's
// recursive Newton-Euler on the same random states, the regressors per sample, 6-trial sessions
// (simulation included) and one update of the improved law over 10^5 samples of 7 axes.
#include "chain.h"

#include "../tests/support/KdlChain.h"
#include "BenchSupport.h"
#include "identify/GramBlock.h"
#include "identify/LearningLaw.h"
#include "identify/TaskThreads.h"
#include "model/ChainModel.h"
#include "model/UrdfChain.h"
#include "model/VectorState.h"
#include "session/ConvergenceFigures.h"

#include <chrono>
#include <cstdio>
#include <kdl/chainidsolver_recursive_newton_euler.hpp>
#include <random>

namespace learnid::bench {

namespace {

struct States
{
    Eigen::MatrixXd q, qd, qdd; // 7 x N
    std::vector<KDL::JntArray> kq, kqd, kqdd;
};

States randomStates(int n, int count)
{
    std::mt19937 random(13);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    States s{Eigen::MatrixXd(n, count),
             Eigen::MatrixXd(n, count),
             Eigen::MatrixXd(n, count),
             {},
             {},
             {}};
    for (int i = 0; i < count; ++i) {
        for (int j = 0; j < n; ++j) {
            s.q(j, i) = 2.5 * unit(random);
            s.qd(j, i) = 2.0 * unit(random);
            s.qdd(j, i) = 4.0 * unit(random);
        }
        for (auto [to, from] : {std::pair{&s.kq, &s.q}, {&s.kqd, &s.qd}, {&s.kqdd, &s.qdd}}) {
            to->emplace_back(unsigned(n));
            to->back().data = from->col(i);
        }
    }
    return s;
}

/// Median over repeats of the CPU time of body() per call [ns], body making `calls` calls.
template <typename Body> double nsPerCall(int repeats, int calls, Body body)
{
    std::vector<double> t;
    for (int r = 0; r < repeats; ++r) {
        clearUpperVectorState(); // as the project's numerical entry points do (VectorState.h)
        const double t0 = cpuSeconds();
        body();
        t.push_back((cpuSeconds() - t0) * 1e9 / calls);
    }
    return median(t);
}

void printDynamics(const ChainOptions &o)
{
    const SerialChain chain = readUrdfChain(o.urdf);
    const int n = chain.dof();
    const ChainDynamics dynamics(chain);
    Eigen::VectorXd pi(10 * n);
    for (int k = 0; k < n; ++k)
        pi.segment<10>(10 * k) = chain.joints[size_t(k)].inertial;
    const KDL::Chain kdl =
        test::kdlChainFromUrdf(o.urdf, chain.baseLink.toStdString(), chain.tipLink.toStdString());
    const Eigen::Vector3d g = chain.gravity;
    KDL::ChainIdSolver_RNE rne(kdl, KDL::Vector(g.x(), g.y(), g.z()));
    const KDL::Wrenches none(kdl.getNrOfSegments(), KDL::Wrench::Zero());

    const int count = 20000;
    const States s = randomStates(n, count);
    Eigen::MatrixXd ours(n, count), theirs(n, count);
    KDL::JntArray tau{unsigned(n)};
    const auto runOurs = [&] {
        for (int i = 0; i < count; ++i)
            dynamics.inverseDynamics(s.q.col(i), s.qd.col(i), s.qdd.col(i), pi, ours.col(i));
    };
    const auto runKdl = [&] {
        for (int i = 0; i < count; ++i) {
            rne.CartToJnt(s.kq[size_t(i)], s.kqd[size_t(i)], s.kqdd[size_t(i)], none, tau);
            theirs.col(i) = tau.data;
        }
    };
    std::vector<double> tOurs, tKdl; // alternating, so both see the same machine load
    for (int r = 0; r < o.repeats; ++r) {
        tOurs.push_back(nsPerCall(1, count, runOurs));
        tKdl.push_back(nsPerCall(1, count, runKdl));
    }
    const double a = median(tOurs), b = median(tKdl);
    std::printf("| inverse dynamics, 7 axes (ns per call) | %.0f | %.0f | %.2fx | >= 3x | %s |\n",
                a, b, b / a, b / a >= 3.0 ? "met" : "**not met**");
    std::printf("\n(%d random states, the same for both, median of %d alternating repetitions; "
                "largest torque difference %.1e N m.)\n\n",
                count, o.repeats, (ours - theirs).cwiseAbs().maxCoeff());

    JointTerms all;
    all.armature = all.viscous = all.coulomb = all.offset = true;
    const double b0 = cpuSeconds();
    const ChainModel model(chain, all, QStringLiteral("urdf"));
    const double build = cpuSeconds() - b0;
    const int p = model.standardCount(), m = model.parameterCount();
    Eigen::MatrixXd ys(n, p), yb(n, m);
    const double standard = nsPerCall(o.repeats, count, [&] {
        for (int i = 0; i < count; ++i)
            model.standardRegressor(s.q.col(i), s.qd.col(i), s.qdd.col(i), ys);
    });
    const double base = nsPerCall(o.repeats, count, [&] {
        for (int i = 0; i < count; ++i)
            model.regressor(s.q.col(i), s.qd.col(i), s.qdd.col(i), yb);
    });
    Eigen::MatrixXd series(n * m, count);
    const double batch =
        nsPerCall(o.repeats, count, [&] { model.regressorSeries(s.q, s.qd, s.qdd, series); });
    std::printf("| measurement | µs per sample | target | |\n|---|---|---|---|\n");
    std::printf("| standard regressor, %d columns (70 inertial + 7 x armature, viscous, Coulomb, "
                "offset) | %.2f | < 3 µs | %s |\n",
                p, 1e-3 * standard, 1e-3 * standard < 3.0 ? "met" : "**not met**");
    std::printf("| base regressor, %d columns | %.2f | < 3 µs | %s |\n", m, 1e-3 * base,
                1e-3 * base < 3.0 ? "met" : "**not met**");
    std::printf("| base regressor as a series (what the learning law evaluates) | %.2f | | |\n",
                1e-3 * batch);
    std::printf("\n(Median of %d repetitions over %d states. Building the model from the URDF, "
                "base parameters included, once: %.0f ms.)\n\n",
                o.repeats, count, 1e3 * build);
}

// A long record: the path forward and back, the plan of trial 0 repeated until `samples`.
TrialPlan longPlan(const Scenario &s, const RobotModel &model, const TrialPlan &one, int samples)
{
    TrialPlan plan = one;
    const int n = one.samples();
    for (Eigen::MatrixXd *x : {&plan.desired.q, &plan.desired.qd, &plan.desired.qdd})
        x->resize(model.dof(), samples);
    for (int k = 0; k < samples; ++k) {
        const bool back = (k / n) % 2 == 1;
        const int src = back ? n - 1 - k % n : k % n;
        plan.desired.q.col(k) = one.desired.q.col(src);
        plan.desired.qd.col(k) = (back ? -1.0 : 1.0) * one.desired.qd.col(src);
        plan.desired.qdd.col(k) = one.desired.qdd.col(src);
    }
    plan.feedforward = feedforwardTorque(model, plan.desired, s.initialParameters);
    return plan;
}

bool printLongUpdate(const ChainOptions &o)
{
    const Scenario requested = chainScenario(o, 1);
    const auto model = makeRobotModel(requested.model, requested.urdf);
    const Scenario s = resolvedChainScenario(o, *model, 1);
    const int samples = 100000;
    const TrialPlan one = TrialPlanner(s, model).plan(s.initialParameters);
    const TrialPlan plan = longPlan(s, *model, one, samples);
    auto robot = makeSimulatedRobot(s, model);
    const double s0 = cpuSeconds();
    const TrialRecord record = robot->runTrial(plan, {});
    const double simulation = cpuSeconds() - s0;
    if (!record.completed()) {
        std::printf("| the 10^5-sample trial failed: %s |\n", qPrintable(record.message));
        return false;
    }
    const auto law = makeLearningLaw(QStringLiteral("improved"));
    const int n = model->dof(), m = model->parameterCount();
    std::vector<double> t, wall;
    ParameterUpdate up;
    for (int r = 0; r < 3; ++r) {
        const double t0 = cpuSeconds();
        const auto w0 = std::chrono::steady_clock::now();
        up = law->update(*model, {{&plan, &record}}, s.initialParameters, s.estimator);
        t.push_back(cpuSeconds() - t0);
        wall.push_back(
            std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count());
    }
    // Its parts that do not depend on the law's internals: the regressor at every sample, and
    // the Gram matrices A_j^T A_j of the joints' full rows (GramBlock; the law forms them twice,
    // for the fit and, from the noise-shaped rows, for the standard deviations, over each joint's
    // nonzero columns only).
    Eigen::MatrixXd w(n * m, samples);
    const double regressor =
        1e-9 * samples * nsPerCall(1, samples, [&] {
            model->regressorSeries(plan.desired.q, plan.desired.qd, plan.desired.qdd, w);
        });
    const Eigen::MatrixXd rows = Eigen::MatrixXd::Random(samples, m);
    const Eigen::VectorXd b = Eigen::VectorXd::Random(samples);
    GramBlock block(n, m, samples, s.initialParameters);
    const double gram = 1e-9 * samples * nsPerCall(1, samples, [&] {
                            for (int j = 0; j < n; ++j)
                                block.setJointRows(j, rows, b);
                        });
    const double u = median(t), uWall = median(wall);
    EstimatorSettings finer = s.estimator;
    finer.rankTolerance = 1e-5;
    const Eigen::VectorXd phiFiner =
        law->update(*model, {{&plan, &record}}, s.initialParameters, finer).phi;
    const auto pathError = [&](const Eigen::VectorXd &phi) {
        return pathTorqueErrorPercent(*model, one.desired, phi, s.simulation.trueParameters);
    };
    std::printf("| measurement | CPU | target | |\n|---|---|---|---|\n");
    std::printf("| one `improved` update over %d samples of 7 axes (%d parameters), CPU time of "
                "all its threads | %.0f ms | < 0.5 s | %s |\n",
                samples, m, 1e3 * u, u < 0.5 ? "met" : "**not met**");
    std::printf("| the same update, wall-clock time (%d thread%s) | %.0f ms | < 0.5 s | %s |\n",
                TaskThreads::available(), TaskThreads::available() > 1 ? "s" : "", 1e3 * uWall,
                uWall < 0.5 ? "met" : "**not met**");
    std::printf("| of it: the regressor at every sample (regressorSeries) | %.0f ms | | |\n",
                1e3 * regressor);
    std::printf("| for scale: one pass of the %d joints' Gram matrices over full rows (%d x %d "
                "each; the law makes two, over each joint's nonzero columns only) | %.0f ms | | "
                "|\n",
                n, samples, m, 1e3 * gram);
    std::printf("| simulating those samples (RK4, %d steps per sample) | %.0f ms | | |\n",
                s.simulation.substeps, 1e3 * simulation);
    std::printf(
        "\n(Update: median of 3, its CPU time summed over its threads, its wall-clock time what "
        "a user waits; its parts: once each, on one thread. The record: trial 0's plan, "
        "%.1f s of motion, forward and back for %.0f s with the CAD feedforward, seed 1's "
        "robot and noise. The estimate from it, on trial 0's path: path-torque error "
        "%.3f %% at rank tolerance %g (rank %d), %.3f %% at 1e-5.)\n\n",
        one.motionDuration, samples * s.controller.samplePeriod, pathError(up.phi),
        s.estimator.rankTolerance, up.rank, pathError(phiFiner));
    return true;
}

} // namespace

bool runChainSpeed(const ChainOptions &o)
{
    std::printf("### Speed: KUKA LWR4+ against Orocos KDL\n\n");
    std::printf("| measurement | learnid | KDL | KDL / learnid | target | |\n"
                "|---|---|---|---|---|---|\n");
    printDynamics(o);
    printChainSessions(o);
    return printLongUpdate(o);
}

} // namespace learnid::bench
