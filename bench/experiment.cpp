#include "identify/LearningLaw.h"
#include "model/TwoLinkArm.h"
#include "robot/SimulatedRobot.h"
#include "session/SafetyCheck.h"
#include "session/TrialPlanner.h"
#include <cstdio>
#include <cstdlib>
using namespace learnid;
int main(int argc, char **argv)
{
    Scenario sc;
    if (argc > 1) sc.law = argv[1];
    if (argc > 2) sc.controller.lambda = atof(argv[2]);
    if (argc > 3) sc.encoderCounts = atoll(argv[3]);
    if (argc > 4) sc.torqueNoise = atof(argv[4]);
    if (argc > 5) sc.seed = atoll(argv[5]);
    auto model = std::make_shared<TwoLinkArm>();
    TrialPlanner planner(sc, model);
    MeasurementOptions mo; mo.encoderCounts = sc.encoderCounts; mo.torqueNoise = sc.torqueNoise; mo.seed = sc.seed;
    SimulatedRobot robot(model, sc.trueParameters, mo);
    auto law = makeLearningLaw(sc.law);
    Eigen::VectorXd phi = sc.initialParameters;
    std::vector<TrialPlan> plans; std::vector<TrialRecord> recs; plans.reserve(10); recs.reserve(10);
    if (getenv("NOACC")) sc.estimator.accumulate = false;
    for (int k = 0; k < 7; ++k) {
        TorqueRuleResult rule;
        TrialPlan plan = planner.plan(phi, &rule);
        SafetyVerdict v = checkTrial(*model, phi, plan);
        SafetyVerdict vt = checkTrial(*model, sc.trueParameters, plan);
        TrialRecord rec = robot.runTrial(plan, {});
        double maxe = ((plan.desired.q.leftCols(rec.samples()) - rec.q).cwiseAbs().maxCoeff()) * 180 / M_PI;
        ParameterUpdate up;
        if (rec.completed()) { plans.push_back(plan); recs.push_back(rec); std::vector<TrialData> td; for (size_t i=0;i<plans.size();++i) td.push_back({&plans[i], &recs[i]}); up = law->update(*model, td, phi, sc.estimator); }
        Eigen::VectorXd err = (phi - sc.trueParameters).cwiseQuotient(sc.trueParameters) * 100;
        printf("k=%d phi=[%.4f %.4f %.4f] err%%=[%.3f %.3f %.3f] T=%.3f N=%d maxe=%.5fdeg rho_est=%.6f rho_true=%.6f cond=%.2f rank=%d status=%s %s\n",
               k, phi[0], phi[1], phi[2], err[0], err[1], err[2], rule.duration, plan.samples(), maxe,
               v.worstSpectralRadius, vt.worstSpectralRadius, up.condition, up.rank, qPrintable(trialStatusName(rec.status)), qPrintable(rec.message));
        if (!rec.completed()) break;
        phi = up.phi;
    }
}
