// What a session offers for accept, apply and export is a set of plausible bodies
// (EstimateConsistency.h, NearestEstimate::Always): on the PUMA 560, an estimate whose CAD
// completion holds a needle is reported link by link, and its plausible estimate keeps the path
// torques, passes the plausibility rule in every link and says which standard parameters the
// path determines.
#include "../support/NumericAssert.h"
#include "model/CadPrior.h"
#include "model/ChainModel.h"
#include "model/ModelFactory.h"
#include "model/Plausibility.h"
#include "model/SerialChain.h"
#include "session/ConvergenceFigures.h"
#include "session/EstimateConsistency.h"
#include "session/ScenarioRobot.h"
#include "session/TrialPlanner.h"

#include <QTest>

using namespace learnid;

namespace {

struct Puma
{
    std::shared_ptr<const RobotModel> model;
    const ChainModel *chain = nullptr;
    JointTrajectory path;
};

Puma puma()
{
    Scenario s;
    s.model = QStringLiteral("puma560");
    s.torqueLimits.resize(0);
    s.initialParameters.resize(0);
    s.simulation.trueParameters.resize(0);
    s.path.kind = PathKind::Waypoints;
    s.path.waypoints = {Eigen::VectorXd::Zero(6), Eigen::VectorXd::Constant(6, 0.6),
                        Eigen::VectorXd::Constant(6, -0.3)};
    s.planningFraction = 0.5;
    s.controller.kp = Eigen::VectorXd::Constant(6, 400.0);
    s.controller.ki = Eigen::VectorXd::Constant(6, 40.0);
    s.controller.kd = Eigen::VectorXd::Constant(6, 40.0);
    s.controller.lambda = 1000;
    Puma p;
    p.model = makeRobotModel(s.model, s.urdf);
    p.chain = dynamic_cast<const ChainModel *>(p.model.get());
    const TrialPlanner planner(withRobotDefaults(s, *p.model), p.model);
    p.path = planner.plan(p.chain->baseFromStandard(p.chain->cadStandard())).desired;
    return p;
}

// The CAD with link 3 turned into a needle along its x axis: its mass and centre of mass as
// before, principal moments about the centre of mass (1e-3 I, I, I), so I1 + I2 ~ I3.
Eigen::VectorXd needleLink3(const ChainModel &chain)
{
    Eigen::VectorXd pi = realBodyPrior(chain.cadStandard(), chain.dof());
    const double m = pi[20];
    const Eigen::Vector3d c = pi.segment<3>(21) / m;
    const double moment = 0.5 * (pi[26] + pi[29]) - m * c.squaredNorm();
    pi.segment<10>(20) =
        inertialParameters(m, c, Eigen::Vector3d(1e-3 * moment, moment, moment).asDiagonal());
    return pi;
}

} // namespace

class TestPlausibleSession : public QObject
{
    Q_OBJECT

private slots:
    void needleEstimate_isReportedAndTheAcceptedEstimateIsPlausible();
};

void TestPlausibleSession::needleEstimate_isReportedAndTheAcceptedEstimateIsPlausible()
{
    const Puma p = puma();
    const ChainModel &chain = *p.chain;
    const Eigen::VectorXd needle = needleLink3(chain);
    const Eigen::VectorXd phi = chain.baseFromStandard(needle);
    const Eigen::VectorXd prior = realBodyPrior(chain.cadStandard(), chain.dof());
    const auto volumes = linkVolumes(chain.chain(), prior);

    // The verdict on the estimate as it stands (its base parameters completed from the CAD
    // model, which makes the needle no real body at all): link 3 is reported, nothing else.
    const std::vector<LinkPlausibility> verdict =
        checkPlausibility(chain.base().standardFromBase(phi, prior), prior, 6, volumes);
    QVERIFY(!verdict[2].plausible);
    const EstimateFigures figures = estimateFigures(chain, p.path, {phi}, std::nullopt);
    QVERIFY(figures.consistencyChecked);
    const QString link3 = chain.standardParameters()[20].group;
    QVERIFY(figures.inconsistentGroups.contains(link3) ||
            figures.implausibleGroups.contains(link3));
    QVERIFY(!figures.inconsistentGroups.contains(chain.standardParameters()[10].group));
    QVERIFY(figures.consistencyLines.join(QLatin1Char(' ')).contains(QLatin1String("link 3")));

    // What accept and export take: every link plausible, the path torques kept.
    const EstimateConsistency c =
        checkEstimateConsistency(chain, phi, p.path, NearestEstimate::Always);
    QVERIFY2(c.nearestError.isEmpty(), qPrintable(c.nearestError));
    QCOMPARE(c.nearestStandard.size(), Eigen::Index(chain.standardCount()));
    // (where the CAD link itself is one: the published link 1 has no mass, link 3's moments
    // break the triangle inequality's margin)
    const auto cadVerdict = checkPlausibility(prior, prior, 6, volumes);
    for (const LinkPlausibility &l : checkPlausibility(c.nearestStandard, prior, 6, volumes)) {
        if (cadVerdict[size_t(l.link)].plausible)
            QVERIFY2(
                l.plausible,
                qPrintable(
                    QStringLiteral("link %1: %2").arg(l.link + 1).arg(plausibilityProblem(l))));
    }
    // Link 3 is no needle any more: thicker than the estimate, as thick as the floor allows.
    const auto nearest3 = checkPlausibility(c.nearestStandard, prior, 6, volumes)[2];
    QVERIFY2(
        nearest3.triangleRatio > verdict[2].triangleRatio,
        qPrintable(
            QStringLiteral("%1 vs %2").arg(nearest3.triangleRatio).arg(verdict[2].triangleRatio)));
    QVERIFY(tinyJointTerms(c.nearestStandard, chain.nonnegativeStandard()).empty());
    LEARNID_COMPARE_MATRIX(chain.baseFromStandard(c.nearestStandard), c.nearest, 1e-12);
    QVERIFY2(c.pathTorqueChangePercent < 1.0,
             qPrintable(QString::number(c.pathTorqueChangePercent)));
    LEARNID_COMPARE_NEAR(c.pathTorqueChangePercent,
                         pathTorqueErrorPercent(chain, p.path, c.nearest, phi), 1e-6);
    // Which standard parameters the path determines: a share each; link 1's mass is never seen
    // (the first axis is vertical).
    QCOMPARE(c.standardDetermined.size(), size_t(chain.standardCount()));
    for (const double share : c.standardDetermined)
        QVERIFY(share >= 0.0 && share <= 1.0);
    QVERIFY(c.standardDetermined[0] < 0.5);
}

QTEST_GUILESS_MAIN(TestPlausibleSession)
#include "tst_plausiblesession.moc"
