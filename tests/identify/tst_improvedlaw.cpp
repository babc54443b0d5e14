#include "../support/LearningRun.h"
#include "identify/ImprovedLaw.h"
#include "model/TwoLinkArm.h"

#include <QTest>

using namespace learnid;

class TestImprovedLaw : public QObject
{
    Q_OBJECT

private slots:
    void noiseFree_withinFiveHundredthsOfAPercentAfterOneTrial();
    void noiseFree_resultDoesNotDependOnInitialEstimate();
    void noisyMeasurements_reportedStdMatchesScatter();
    void accumulatingTrials_reducesScatter();
    void rankDeficientTrajectory_keepsUnobservableParameters();
};

void TestImprovedLaw::noiseFree_withinFiveHundredthsOfAPercentAfterOneTrial()
{
    const Scenario s;
    const test::LearningRun run = test::runLearning(s, 2);
    const double first =
        test::relativeError(run.estimates[1], s.simulation.trueParameters).cwiseAbs().maxCoeff();
    QVERIFY2(first < 5e-4, qPrintable(QString::number(first)));
    const double second =
        test::relativeError(run.estimates[2], s.simulation.trueParameters).cwiseAbs().maxCoeff();
    QVERIFY2(second < 5e-4, qPrintable(QString::number(second)));
    QCOMPARE(run.updates[0].rank, 3);
    QVERIFY(run.updates[0].condition > 1.0 && run.updates[0].condition < 100.0);
}

void TestImprovedLaw::noiseFree_resultDoesNotDependOnInitialEstimate()
{
    Scenario s;
    s.initialParameters = Eigen::Vector3d(26.0, 8.0, 12.0);
    const test::LearningRun run = test::runLearning(s, 1);
    const double err =
        test::relativeError(run.estimates[1], s.simulation.trueParameters).cwiseAbs().maxCoeff();
    QVERIFY2(err < 5e-4, qPrintable(QString::number(err)));
}

// The standard deviations the update reports must describe the actual scatter of the estimate:
// over independent noise seeds, the errors divided by the reported std have an RMS near 1.
void TestImprovedLaw::noisyMeasurements_reportedStdMatchesScatter()
{
    double sumSquares = 0.0;
    int count = 0;
    // 24 seeds x 3 parameters: the RMS of 72 unit normals lies in [0.8, 1.2] with >99 %
    // probability; the band below leaves room for the parameters' correlation.
    for (quint64 seed = 1; seed <= 24; ++seed) {
        Scenario s;
        s.simulation.torqueNoise = 0.01;
        s.simulation.seed = seed;
        s.initialParameters = s.simulation.trueParameters; // full torque: the SNR of later trials
        const test::LearningRun run = test::runLearning(s, 1);
        const Eigen::VectorXd err = run.estimates[1] - s.simulation.trueParameters;
        const Eigen::VectorXd z = err.cwiseQuotient(run.updates[0].phiStd);
        sumSquares += z.squaredNorm();
        count += int(z.size());
    }
    const double rms = std::sqrt(sumSquares / count);
    QVERIFY2(rms > 0.7 && rms < 1.4, qPrintable(QString::number(rms)));
}

void TestImprovedLaw::accumulatingTrials_reducesScatter()
{
    double accumulated = 0.0;
    double single = 0.0;
    for (quint64 seed = 1; seed <= 8; ++seed) {
        Scenario s;
        s.simulation.encoderCounts = qint64(1) << 20;
        s.simulation.torqueNoise = 0.01;
        s.simulation.seed = seed;
        const Eigen::VectorXd a = test::runLearning(s, 4).estimates[4];
        s.estimator.accumulate = false;
        const Eigen::VectorXd b = test::runLearning(s, 4).estimates[4];
        accumulated += test::relativeError(a, s.simulation.trueParameters).squaredNorm();
        single += test::relativeError(b, s.simulation.trueParameters).squaredNorm();
    }
    // Four trials carry about four times the information of the last one alone.
    QVERIFY2(accumulated < 0.6 * single,
             qPrintable(QStringLiteral("%1 vs %2").arg(accumulated).arg(single)));
}

// A motion of joint 1 alone never accelerates joint 2: the column of c (qdd2) stays ~0, so c is
// not observable. The update must keep c, recover a and b, and say which one was kept.
void TestImprovedLaw::rankDeficientTrajectory_keepsUnobservableParameters()
{
    const Scenario s;
    const auto model = std::make_shared<TwoLinkArm>();
    const double ts = s.controller.samplePeriod;
    const int samples = 2400;
    TrialPlan plan;
    plan.desired.samplePeriod = ts;
    plan.desired.q.resize(2, samples);
    plan.desired.qd.resize(2, samples);
    plan.desired.qdd.resize(2, samples);
    // Slow enough that neither joint saturates: peak qdd1 = 5.77 * 0.8 / 16 = 0.29 rad/s^2.
    const double T = 4.0, rest = 0.1, stroke = 0.8; // [s], [s], [rad]
    for (int k = 0; k < samples; ++k) {
        const double u = std::clamp((k * ts - rest) / T, 0.0, 1.0);
        const bool moving = u > 0.0 && u < 1.0;
        plan.desired.q.col(k) << 0.2 + stroke * u * u * u * (10 - 15 * u + 6 * u * u), 1.5;
        plan.desired.qd.col(k) << (moving ? stroke * 30 * u * u * (1 - 2 * u + u * u) / T : 0.0),
            0.0;
        plan.desired.qdd.col(k) << (moving ? stroke * 60 * u * (1 - 3 * u + 2 * u * u) / (T * T)
                                           : 0.0),
            0.0;
    }
    const Eigen::VectorXd phiPrev = Eigen::Vector3d(24.0, 6.0, 11.0);
    plan.feedforward = feedforwardTorque(*model, plan.desired, phiPrev);
    plan.feedforwardParameters = phiPrev;
    plan.controller = s.controller;
    plan.torqueLimit = s.torqueLimits;
    plan.maxTrackingError = 1.0;
    plan.motionDuration = T;

    SimulatedRobot robot(model, s.simulation.trueParameters);
    const TrialRecord record = robot.runTrial(plan, {});
    QVERIFY(record.completed());
    const ParameterUpdate up =
        ImprovedLaw().update(*model, {{&plan, &record}}, phiPrev, s.estimator);

    QCOMPARE(up.rank, 2);
    QCOMPARE(up.observable, (std::vector<bool>{true, true, false}));
    QVERIFY(std::isinf(up.phiStd[2]));
    QVERIFY(up.phi.allFinite());
    QVERIFY2(std::abs(up.phi[2] - phiPrev[2]) < 1e-3 * phiPrev[2],
             qPrintable(QString::number(up.phi[2])));
    QVERIFY2(std::abs(up.phi[0] / s.simulation.trueParameters[0] - 1.0) < 1e-3,
             qPrintable(QString::number(up.phi[0])));
    QVERIFY2(std::abs(up.phi[1] / s.simulation.trueParameters[1] - 1.0) < 1e-2,
             qPrintable(QString::number(up.phi[1])));
}

QTEST_GUILESS_MAIN(TestImprovedLaw)
#include "tst_improvedlaw.moc"
