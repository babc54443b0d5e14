#include "model/Error.h"
#include "model/TwoLinkArm.h"
#include "robot/SimulatedRobot.h"
#include "session/CommissioningSession.h"

#include <QSignalSpy>
#include <QTest>

using namespace learnid;

namespace {

// The simulated robot, with drives that report some set-points late at every run (as CanRobot
// counts them from statusword bit 12).
class LateSetpointRobot final : public Robot
{
public:
    LateSetpointRobot(std::shared_ptr<SimulatedRobot> robot, int late)
        : m_robot(std::move(robot))
        , m_late(late)
    {}
    QString description() const override { return m_robot->description(); }
    TrialRecord runTrial(const TrialPlan &plan, const TrialMonitor &monitor) override
    {
        TrialRecord r = m_robot->runTrial(plan, monitor);
        r.lateSetpoints = m_late;
        return r;
    }
    QString applyParameters(const Eigen::VectorXd &phi) override
    {
        return m_robot->applyParameters(phi);
    }
    Eigen::VectorXd storedParameters() const override { return m_robot->storedParameters(); }

private:
    std::shared_ptr<SimulatedRobot> m_robot;
    int m_late = 0;
};

} // namespace

class TestCommissioningSession : public QObject
{
    Q_OBJECT

private slots:
    void paperScenario_learnsAndKeepsHistory();
    void paperLambda40_refusesOnceEstimateNearsTruth();
    void acceptAndApply_onlyWritesAcceptedEstimate();
    void failedApply_leavesRobotAndHistoryUnchanged();
    void revert_restoresPreviouslyStoredSet();
    void cancel_marksTrialAndKeepsEstimate();
    void cancelBetweenTrials_endsTheSeries();
    void robotFault_stopsSeriesKeepingPartialData();
    void nonFiniteMeasurement_isNotLearnedFrom();
    void repetitions_averageTorqueNoise();
    void lateSetpoints_learnedFrom_andSaidInTheMessage();
    void mismatchedScenario_throws();

private:
    struct Fixture
    {
        std::shared_ptr<TwoLinkArm> model = std::make_shared<TwoLinkArm>();
        std::shared_ptr<SimulatedRobot> robot;
        std::unique_ptr<CommissioningSession> session;
    };
    static Fixture make(const Scenario &s, MeasurementOptions options = {})
    {
        Fixture f;
        f.robot = std::make_shared<SimulatedRobot>(f.model, s.simulation.trueParameters, options);
        f.session = std::make_unique<CommissioningSession>(s, f.model, f.robot);
        return f;
    }
};

void TestCommissioningSession::paperScenario_learnsAndKeepsHistory()
{
    const Scenario s;
    Fixture f = make(s);
    QSignalSpy finished(f.session.get(), &CommissioningSession::trialFinished);
    QSignalSpy progress(f.session.get(), &CommissioningSession::progress);
    QVERIFY(f.session->runTrials(3));
    QCOMPARE(finished.count(), 3);
    QCOMPARE(f.session->history().size(), 3);
    QCOMPARE(f.session->estimates().size(), 4);
    QCOMPARE(f.session->estimates().front(), s.initialParameters);
    for (int k = 0; k < 3; ++k) {
        const TrialResult &t = f.session->history().at(k);
        QCOMPARE(t.index, k);
        QCOMPARE(t.phiUsed, f.session->estimates().at(k));
        QVERIFY(t.learned());
        QCOMPARE(t.update->phi, f.session->estimates().at(k + 1));
        QCOMPARE(t.record.samples(), t.plan().samples());
        // The session's tracking figures equal the record's own.
        const double maxDeg =
            (t.plan().desired.q - t.record.q).cwiseAbs().maxCoeff() * 180.0 / M_PI;
        QCOMPARE(t.maxTrackingErrorDeg.maxCoeff(), maxDeg);
    }
    const double err = ((f.session->currentEstimate() - s.simulation.trueParameters)
                            .cwiseQuotient(s.simulation.trueParameters))
                           .cwiseAbs()
                           .maxCoeff();
    QVERIFY2(err < 5e-4, qPrintable(QString::number(err)));
    // Progress ends at the total of the last trial.
    const QList<QVariant> last = progress.constLast();
    QCOMPARE(last.at(1).toInt(), last.at(2).toInt());
}

void TestCommissioningSession::paperLambda40_refusesOnceEstimateNearsTruth()
{
    Scenario s;
    s.controller.lambda = 40.0;
    Fixture f = make(s);
    QVERIFY(!f.session->runTrials(6));
    const TrialResult &refused = f.session->history().constLast();
    QCOMPARE(refused.status(), TrialStatus::Refused);
    QVERIFY(refused.index >= 1);
    QCOMPARE(refused.record.samples(), 0); // the robot did not move
    QVERIFY2(refused.message.contains(QStringLiteral("unstable")), qPrintable(refused.message));
    QCOMPARE(f.session->history().front().status(), TrialStatus::Completed);
    QCOMPARE(f.session->estimates().size(), refused.index + 1); // no estimate from the refusal
}

void TestCommissioningSession::acceptAndApply_onlyWritesAcceptedEstimate()
{
    Fixture f = make(Scenario{});
    QVERIFY(!f.session->apply().isEmpty()); // nothing accepted
    QCOMPARE(f.robot->storedParameters().size(), 0);
    QVERIFY(!f.session->accept(1).isEmpty()); // nothing learned yet
    QVERIFY(f.session->runTrials(2));
    QVERIFY(!f.session->accept(0).isEmpty());
    QVERIFY(!f.session->accept(3).isEmpty());
    QSignalSpy applied(f.session.get(), &CommissioningSession::parametersApplied);
    QVERIFY(f.session->accept(1).isEmpty());
    QCOMPARE(*f.session->acceptedIndex(), 1);
    QVERIFY(f.session->apply().isEmpty());
    QCOMPARE(f.robot->storedParameters(), f.session->estimates().at(1));
    QCOMPARE(applied.count(), 1);
    QCOMPARE(f.session->appliedHistory().size(), 1);
}

void TestCommissioningSession::failedApply_leavesRobotAndHistoryUnchanged()
{
    Fixture f = make(Scenario{});
    QVERIFY(f.session->runTrials(1));
    QVERIFY(f.session->accept(1).isEmpty());
    SimulatedFaults faults;
    faults.refuseApply = true;
    f.robot->setFaults(faults);
    const QString error = f.session->apply();
    QVERIFY(error.contains(QStringLiteral("refused")));
    QCOMPARE(f.robot->storedParameters().size(), 0);
    QVERIFY(f.session->appliedHistory().isEmpty());
}

void TestCommissioningSession::revert_restoresPreviouslyStoredSet()
{
    Fixture f = make(Scenario{});
    const Eigen::VectorXd factory = Eigen::Vector3d(35, 15, 25);
    QVERIFY(f.robot->applyParameters(factory).isEmpty()); // what the machine held before
    QVERIFY(!f.session->revert().isEmpty());              // nothing applied yet
    QVERIFY(f.session->runTrials(2));
    QVERIFY(f.session->accept(2).isEmpty());
    QVERIFY(f.session->apply().isEmpty());
    QCOMPARE(f.robot->storedParameters(), f.session->estimates().at(2));
    QVERIFY(f.session->revert().isEmpty());
    QCOMPARE(f.robot->storedParameters(), factory);
    QVERIFY(!f.session->revert().isEmpty()); // only one apply to undo
}

void TestCommissioningSession::cancel_marksTrialAndKeepsEstimate()
{
    Fixture f = make(Scenario{});
    CommissioningSession *session = f.session.get();
    connect(session, &CommissioningSession::progress, session, [session](int, int done, int) {
        if (done >= 1000)
            session->requestCancel();
    });
    QVERIFY(!session->runTrials(3));
    QCOMPARE(session->history().size(), 1);
    const TrialResult &t = session->history().front();
    QCOMPARE(t.status(), TrialStatus::Cancelled);
    QVERIFY(!t.learned());
    QVERIFY(t.record.samples() >= 1000 && t.record.samples() < t.plan().samples());
    QCOMPARE(session->estimates().size(), 1);
}

// A Stop pressed after a trial has finished but before the next starts must not be lost.
void TestCommissioningSession::cancelBetweenTrials_endsTheSeries()
{
    Fixture f = make(Scenario{});
    CommissioningSession *session = f.session.get();
    connect(session, &CommissioningSession::trialFinished, session,
            [session](const TrialResult &) { session->requestCancel(); });
    QVERIFY(!session->runTrials(3));
    QCOMPARE(session->history().size(), 1);
    QCOMPARE(session->history().front().status(), TrialStatus::Completed);
    QVERIFY(session->history().front().learned());
}

void TestCommissioningSession::robotFault_stopsSeriesKeepingPartialData()
{
    Fixture f = make(Scenario{});
    QVERIFY(f.session->runTrials(1));
    SimulatedFaults faults;
    faults.driveFaultAtSample = 777;
    f.robot->setFaults(faults);
    QVERIFY(!f.session->runTrials(3));
    QCOMPARE(f.session->history().size(), 2);
    const TrialResult &t = f.session->history().at(1);
    QCOMPARE(t.status(), TrialStatus::Faulted);
    QCOMPARE(t.record.samples(), 778);
    QVERIFY(t.maxTrackingErrorDeg.allFinite());
    QCOMPARE(f.session->estimates().size(), 2);
    // The faulted trial ran with estimate 1; nothing has run with estimate 2 (none exists).
    QCOMPARE(f.session->trialRunWith(0), &f.session->history().at(0));
    QCOMPARE(f.session->trialRunWith(1), &t);
    QCOMPARE(f.session->trialRunWith(2), nullptr);
}

void TestCommissioningSession::nonFiniteMeasurement_isNotLearnedFrom()
{
    Fixture f = make(Scenario{});
    SimulatedFaults faults;
    faults.nanTorqueAtSample = 42;
    f.robot->setFaults(faults);
    const TrialResult &t = f.session->runTrial();
    QCOMPARE(t.status(), TrialStatus::Completed);
    QVERIFY(!t.learned());
    QVERIFY2(t.message.contains(QStringLiteral("sample 42")), qPrintable(t.message));
    QCOMPARE(f.session->estimates().size(), 1);
    QVERIFY(f.session->currentEstimate().allFinite());
}

// Averaging r runs divides white torque noise by sqrt(r).
void TestCommissioningSession::repetitions_averageTorqueNoise()
{
    Scenario s;
    s.repetitions = 4;
    MeasurementOptions noisy;
    noisy.torqueNoise = 0.01;
    Fixture averaged = make(s, noisy);
    Scenario once = s;
    once.repetitions = 1;
    Fixture clean = make(once);
    const TrialRecord a = averaged.session->runTrial().record;
    const TrialRecord c = clean.session->runTrial().record;
    QCOMPARE(a.q, c.q);
    const Eigen::MatrixXd d = a.tau - c.tau;
    const double sd = std::sqrt(d.row(0).squaredNorm() / double(d.cols()));
    const double expected = 0.01 * s.torqueLimits[0] / 2.0;
    QVERIFY2(std::abs(sd / expected - 1.0) < 0.1, qPrintable(QString::number(sd)));
}

void TestCommissioningSession::lateSetpoints_learnedFrom_andSaidInTheMessage()
{
    Scenario s;
    s.repetitions = 2;
    const auto model = std::make_shared<TwoLinkArm>();
    const auto sim = std::make_shared<SimulatedRobot>(model, s.simulation.trueParameters);
    CommissioningSession session(s, model, std::make_shared<LateSetpointRobot>(sim, 3));
    const TrialResult &t = session.runTrial();
    QVERIFY(t.learned());
    QCOMPARE(t.record.lateSetpoints, 6); // over both repetitions
    QVERIFY2(t.message.startsWith(QLatin1String("6 set-point")), qPrintable(t.message));
    Fixture onTime = make(s);
    QVERIFY2(onTime.session->runTrial().message.isEmpty(),
             qPrintable(onTime.session->history().constLast().message));
}

void TestCommissioningSession::mismatchedScenario_throws()
{
    Scenario s;
    s.initialParameters = Eigen::Vector2d(1, 2);
    QVERIFY_THROWS_EXCEPTION(Error, make(s));
    Scenario law;
    law.law = QStringLiteral("magic");
    QVERIFY_THROWS_EXCEPTION(Error, make(law));
}

QTEST_GUILESS_MAIN(TestCommissioningSession)
#include "tst_commissioningsession.moc"
