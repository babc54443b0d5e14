// A session survives a bad first model (issue 23, robot (a)): the simulated real KUKA LWR4+ has
// link masses x0.8 / x1.25, centres of mass 2 cm off, inertia x1.4 and the joint friction real
// arms show (joint 5: Coulomb 0.93 N m where the CAD model says 0.2); learnid starts from the
// CAD URDF with docs/scenario.md's gains and path and the 5 deg abort limit. Trial 0 stops at
// the limit; what it recorded up to the stop lets a later trial complete, and the error falls.
// The CAD URDF is read in place from ../shared/data; skipped without it.
#include "../support/SharedData.h"
#include "../support/ZooRobot.h"
#include "io/ScenarioFile.h"
#include "model/ModelFactory.h"
#include "service/SessionExport.h"
#include "session/CommissioningSession.h"
#include "session/RobotScenario.h"
#include "session/ScenarioRobot.h"
#include "session/TrialSeries.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>
#include <algorithm>
#include <array>

using namespace learnid;

namespace {

// Robot (a) of issue 23 from the CAD URDF's text: masses alternately x0.8 and x1.25 (the fixed
// base's block first), centres of mass 2 cm off along x.
QString robotA(const QString &cad)
{
    return support::robotAUrdf(
        cad, [](int i) { return i % 2 ? 1.25 : 0.8; },
        [](int) {
            return std::array<double, 3>{0.02, 0.0, 0.0};
        });
}

double maxErrorDeg(const TrialResult &t)
{
    return t.maxTrackingErrorDeg.maxCoeff();
}

} // namespace

class TestLearnFromAbort : public QObject
{
    Q_OBJECT

private slots:
    void robotA_learnsFromTheAbortedFirstTrialAndCompletesLater();
    void starterScenario_holdsRobotAsFrictionAndLearns();
};

void TestLearnFromAbort::robotA_learnsFromTheAbortedFirstTrialAndCompletesLater()
{
    const QString cadPath = test::sharedDataFile(QStringLiteral("kuka-lwr4/kuka_lwr4.urdf"));
    if (cadPath.isEmpty())
        QSKIP(qPrintable(test::sharedDataMissing()));
    QFile cadFile(cadPath);
    QVERIFY(cadFile.open(QIODevice::ReadOnly));
    const QString cad = QString::fromUtf8(cadFile.readAll());
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString realPath = dir.filePath(QStringLiteral("lwr-a.urdf"));
    QFile real(realPath);
    QVERIFY(real.open(QIODevice::WriteOnly));
    const QString a = robotA(cad);
    QVERIFY(a != cad);
    real.write(a.toUtf8());
    real.close();

    // docs/scenario.md's KUKA scenario, the simulated robot robot (a).
    Scenario requested = support::docsLwrScenario(cadPath);
    support::simulateRealUrdf(requested, realPath);
    const auto model = makeRobotModel(requested.model, requested.urdf);
    const Scenario s = withRobotDefaults(requested, *model);
    CommissioningSession session(s, model, makeSimulatedRobot(s, model));
    session.runTrials(6);

    const QVector<TrialResult> &h = session.history();
    QString figures;
    for (const TrialResult &t : h)
        figures +=
            QStringLiteral(" %1%2 %3 deg")
                .arg(t.index)
                .arg(t.record.completed()
                         ? QString()
                         : QStringLiteral(" (aborted at t = %1 s)")
                               .arg((t.record.samples() - 1) * t.record.samplePeriod, 0, 'f', 3))
                .arg(maxErrorDeg(t), 0, 'f', 4);
    qInfo("robot (a), 5 deg limit, max tracking error per trial:%s", qPrintable(figures));

    // Trial 0 stops at the limit and is learned from, up to the stop.
    QVERIFY(h.size() >= 2);
    const TrialResult &first = h.at(0);
    QVERIFY2(first.record.stoppedAtTrackingLimit(), qPrintable(first.message));
    QVERIFY2(first.learnedFromPartial(), qPrintable(first.message));
    QCOMPARE(h.at(1).phiUsed, session.estimates().at(1));
    // A later trial completes, and the error falls: the last trial tracks within a fifth of
    // the error trial 0 stopped with.
    int completed = -1;
    for (const TrialResult &t : h)
        if (t.record.completed() && completed < 0)
            completed = t.index;
    QVERIFY2(completed > 0, "no trial completed");
    QVERIFY(h.constLast().record.completed());
    QVERIFY2(maxErrorDeg(h.constLast()) < 0.2 * maxErrorDeg(first), qPrintable(figures));

    // The abort cost nothing: the same robot under a 15 deg limit, whose trial 0 completes,
    // tracks no better after as many trials.
    Scenario loose = s;
    loose.maxTrackingErrorDeg = 15;
    CommissioningSession reference(loose, model, makeSimulatedRobot(loose, model));
    reference.runTrials(6);
    QString looseFigures;
    double looseBest = 1e9;
    for (const TrialResult &t : reference.history()) {
        QVERIFY(t.record.completed());
        looseFigures += QStringLiteral(" %1 %2 deg").arg(t.index).arg(maxErrorDeg(t), 0, 'f', 4);
        looseBest = std::min(looseBest, maxErrorDeg(t));
    }
    qInfo("the same robot, 15 deg limit:%s", qPrintable(looseFigures));
    double best = 1e9;
    for (const TrialResult &t : h)
        if (t.record.completed())
            best = std::min(best, maxErrorDeg(t));
    QVERIFY2(best < 1.1 * looseBest, qPrintable(figures + looseFigures));

    // The report marks the partial trial and, as Accept would, the estimate to propose.
    const QJsonObject report =
        QJsonDocument::fromJson(exportFiles(session,
                                            [&] {
                                                ExportRequest r;
                                                r.reportPath =
                                                    dir.filePath(QStringLiteral("r.json"));
                                                return r;
                                            }())
                                    .constFirst()
                                    .second)
            .object();
    const QJsonObject row0 = report.value(QStringLiteral("trials")).toArray().at(0).toObject();
    QVERIFY(row0.value(QStringLiteral("learnedFromPartialTrial")).toBool());
    QVERIFY(row0.value(QStringLiteral("learnedSeconds")).toDouble() > 0.0);
    QCOMPARE(report.value(QStringLiteral("proposedEstimate")).toInt(),
             proposedEstimate(h, int(session.estimates().size())));
}

void TestLearnFromAbort::starterScenario_holdsRobotAsFrictionAndLearns()
{
    // `learnid-cli scenario --print --robot kuka_lwr4.urdf` on robot (a): the starter's gains are
    // designed to hold a Coulomb friction of 1 % of each joint's torque limit within 0.05 rad
    // (RobotScenario.h), about what the real arm has, where the CAD model says 0.2 N m. Its
    // gentle first trial then completes under the 5 deg limit, every trial does, and the
    // learned estimate brings the error down.
    const QString cadPath = test::sharedDataFile(QStringLiteral("kuka-lwr4/kuka_lwr4.urdf"));
    if (cadPath.isEmpty())
        QSKIP(qPrintable(test::sharedDataMissing()));
    QFile cadFile(cadPath);
    QVERIFY(cadFile.open(QIODevice::ReadOnly));
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString realPath = dir.filePath(QStringLiteral("lwr-a.urdf"));
    QFile real(realPath);
    QVERIFY(real.open(QIODevice::WriteOnly));
    real.write(robotA(QString::fromUtf8(cadFile.readAll())).toUtf8());
    real.close();

    Scenario requested = scenarioForRobotName(cadPath);
    QCOMPARE(requested.maxTrackingErrorDeg, 5.0);
    // The gain rule itself: kp_j >= 1 % of joint j's limit / 0.05 rad.
    const auto model = makeRobotModel(requested.model, requested.urdf);
    const Scenario limits = withRobotDefaults(requested, *model);
    for (int j = 0; j < model->dof(); ++j)
        QVERIFY2(requested.controller.kp[j] >= 0.01 * limits.torqueLimits[j] / 0.05 - 1e-9,
                 qPrintable(
                     QStringLiteral("joint %1: kp %2").arg(j + 1).arg(requested.controller.kp[j])));
    requested.simulation = SimulationSettings{};
    requested.simulation.trueParameters.resize(0);
    support::simulateRealUrdf(requested, realPath);
    const Scenario s = withRobotDefaults(requested, *model);
    CommissioningSession session(s, model, makeSimulatedRobot(s, model));
    QVERIFY(session.runTrials(6));

    const QVector<TrialResult> &h = session.history();
    QString figures;
    for (const TrialResult &t : h)
        figures += QStringLiteral(" %1 %2 deg").arg(t.index).arg(maxErrorDeg(t), 0, 'f', 4);
    qInfo("robot (a), the starter scenario: max tracking error per trial:%s", qPrintable(figures));
    QCOMPARE(h.size(), 6);
    for (const TrialResult &t : h)
        QVERIFY2(t.record.completed(), qPrintable(t.message));
    double best = maxErrorDeg(h.at(1));
    for (const TrialResult &t : h)
        best = std::min(best, maxErrorDeg(t));
    QVERIFY2(best < 0.2 * maxErrorDeg(h.at(0)), qPrintable(figures));
}

QTEST_GUILESS_MAIN(TestLearnFromAbort)
#include "tst_learnfromabort.moc"
