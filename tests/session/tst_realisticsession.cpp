// Sessions on simulated robots with realistic joints (simulation keys of docs/scenario.md):
// the keys resolved against the simulated robot (simulatedJoints), their errors, and a 6-trial
// KUKA LWR4+ session with every option on, its CPU time printed (the budget: 2 s).
#include "../support/ErrorOf.h"
#include "../support/SharedData.h"
#include "model/ChainModel.h"
#include "model/ModelFactory.h"
#include "session/CommissioningSession.h"
#include "session/ScenarioRobot.h"
#include "session/ScenarioRobotJoints.h"

#include <QFile>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>
#include <ctime>

using namespace learnid;

namespace {

Scenario doublePendulum()
{
    Scenario s;
    s.model = QStringLiteral("double-pendulum");
    s.torqueLimits.resize(0);
    s.initialParameters.resize(0);
    s.simulation.trueParameters.resize(0);
    s.path.kind = PathKind::Waypoints;
    s.path.waypoints = {Eigen::Vector2d(0, 0), Eigen::Vector2d(1.2, -0.8)};
    s.controller.kp = Eigen::Vector2d(20, 8);
    s.controller.ki = Eigen::Vector2d(2, 1);
    s.controller.kd = Eigen::Vector2d(1.5, 0.6);
    return s;
}

// Robot (a) of issue 23 as a real robot's URDF: the CAD LWR4+ with link masses x0.8 and x1.25
// in turn, centres of mass moved 2 cm along x, inertia x1.4, joint 5's Coulomb friction 0.93 N m.
QString robotA(const QTemporaryDir &dir, const QString &cadPath)
{
    QFile cad(cadPath);
    if (!cad.open(QIODevice::ReadOnly))
        return {};
    QString text = QString::fromUtf8(cad.readAll());
    int link = 0;
    QString out;
    static const QRegularExpression inertial(QStringLiteral("<inertial>.*?</inertial>"),
                                             QRegularExpression::DotMatchesEverythingOption);
    qsizetype at = 0;
    for (auto it = inertial.globalMatch(text); it.hasNext();) {
        const auto m = it.next();
        QString block = m.captured();
        const double massFactor = link++ % 2 == 0 ? 0.8 : 1.25;
        static const QRegularExpression number(
            QStringLiteral("(mass value|ixx|iyy|izz)=\"([^\"]+)\""));
        QString scaled;
        qsizetype from = 0;
        for (auto n = number.globalMatch(block); n.hasNext();) {
            const auto v = n.next();
            const double factor = v.captured(1) == QLatin1String("mass value") ? massFactor : 1.4;
            scaled += block.mid(from, v.capturedStart() - from) +
                      QStringLiteral("%1=\"%2\"")
                          .arg(v.captured(1))
                          .arg(v.captured(2).toDouble() * factor, 0, 'g', 17);
            from = v.capturedEnd();
        }
        scaled += block.mid(from);
        static const QRegularExpression com(QStringLiteral("xyz=\"([^ ]+) "));
        const auto c = com.match(scaled);
        if (c.hasMatch())
            scaled.replace(c.capturedStart(1), c.capturedLength(1),
                           QString::number(c.captured(1).toDouble() + 0.02, 'g', 17));
        out += text.mid(at, m.capturedStart() - at) + scaled;
        at = m.capturedEnd();
    }
    out += text.mid(at);
    static const QRegularExpression joint5(
        QStringLiteral("name=\"lwr_4_joint\".*?friction=\"([^\"]+)"),
        QRegularExpression::DotMatchesEverythingOption);
    const auto friction = joint5.match(out);
    if (!friction.hasMatch())
        return {};
    out.replace(friction.capturedStart(1), friction.capturedLength(1), QStringLiteral("0.93"));
    const QString path = dir.filePath(QStringLiteral("robot-a.urdf"));
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return {};
    file.write(out.toUtf8());
    return path;
}

} // namespace

class TestRealisticSession : public QObject
{
    Q_OBJECT

private slots:
    void staticFrictionRatio_scalesTheTrueCoulombFriction();
    void staticFrictionBelowCoulomb_isRefusedWithKeyPath();
    void elasticJointWithoutRotorInertia_isRefused();
    void armatureFactorWithoutUrdf_isRefused();
    void armatureFactor_isTheLinksInertiaAboutItsAxis();
    void lwr4AllOptions_sixTrialsRunAndCpuTimeIsPrinted();
};

void TestRealisticSession::staticFrictionRatio_scalesTheTrueCoulombFriction()
{
    Scenario s = doublePendulum();
    s.simulation.staticFrictionRatio = 1.5;
    const auto model = makeRobotModel(s.model, s.urdf);
    s = withRobotDefaults(s, *model);
    const JointRealism r = simulatedJoints(s, *model);
    const auto &chain = dynamic_cast<const ChainModel &>(*model);
    // The double pendulum's URDF friction is its Coulomb term (CAD = truth here).
    for (int j = 0; j < 2; ++j) {
        const double fc = chain.chain().joints[size_t(j)].friction;
        QVERIFY(fc > 0.0);
        QVERIFY(std::abs(r.coulomb[j] - fc) < 1e-12 * fc);
        QVERIFY(std::abs(r.staticFriction[j] - 1.5 * fc) < 1e-12 * fc);
    }
    // The rigid dynamics run without the Coulomb term: at q' = 0.3 the bias torques differ by
    // exactly fc tanh(0.3 / coulombVelocity).
    const Eigen::Vector2d q(0.2, -0.4), qd(0.3, 0.3);
    Eigen::VectorXd with(2), without(2);
    model->biasTorque(q, qd, s.simulation.trueParameters, with);
    model->biasTorque(q, qd, r.linkParameters, without);
    for (int j = 0; j < 2; ++j) {
        const double smooth = r.coulomb[j] * std::tanh(0.3 / s.urdf.jointTerms.coulombVelocity);
        QVERIFY(std::abs(with[j] - without[j] - smooth) < 1e-9);
    }
}

void TestRealisticSession::staticFrictionBelowCoulomb_isRefusedWithKeyPath()
{
    Scenario s = doublePendulum();
    s.simulation.staticFriction = Eigen::Vector2d(1.0, 0.0);
    const auto model = makeRobotModel(s.model, s.urdf);
    s = withRobotDefaults(s, *model);
    const QString message = test::errorOf([&] { makeSimulatedRobot(s, model); });
    QVERIFY2(
        message.startsWith(QStringLiteral("simulation.staticFriction[1]: must be at least "
                                          "the simulated robot's Coulomb friction of joint 2, ")),
        qPrintable(message));
    QVERIFY(message.endsWith(QStringLiteral(" N m, got 0")));
}

void TestRealisticSession::elasticJointWithoutRotorInertia_isRefused()
{
    Scenario s = doublePendulum();
    s.simulation.jointStiffness = Eigen::Vector2d(5000, 5000);
    s.simulation.armature = Eigen::Vector2d(0.01, 0.0);
    const auto model = makeRobotModel(s.model, s.urdf);
    s = withRobotDefaults(s, *model);
    QCOMPARE(test::errorOf([&] { makeSimulatedRobot(s, model); }),
             QStringLiteral("simulation.jointStiffness: an elastic joint needs its motor's rotor "
                            "inertia: give simulation.armature or simulation.armatureFactor "
                            "above 0 for joint 2"));
}

void TestRealisticSession::armatureFactorWithoutUrdf_isRefused()
{
    Scenario s;
    s.simulation.armatureFactor = Eigen::Vector2d(1, 1);
    const auto model = makeRobotModel(s.model);
    QCOMPARE(test::errorOf([&] { makeSimulatedRobot(s, model); }),
             QStringLiteral("simulation.armatureFactor: needs a URDF robot (the link's inertia "
                            "about its axis); paper-2link has none: give simulation.armature in "
                            "kg m^2"));
}

void TestRealisticSession::armatureFactor_isTheLinksInertiaAboutItsAxis()
{
    Scenario s = doublePendulum();
    s.simulation.armatureFactor = Eigen::Vector2d(0.5, 2.0);
    s.simulation.armature = Eigen::Vector2d(0.1, 0.0);
    const auto model = makeRobotModel(s.model, s.urdf);
    s = withRobotDefaults(s, *model);
    const JointRealism r = simulatedJoints(s, *model);
    const auto &chain = dynamic_cast<const ChainModel &>(*model);
    for (int j = 0; j < 2; ++j) {
        // I_axis = a^T (I_c + m (|c|^2 E - c c^T)) a, from the URDF link's inertial.
        const ChainJoint &joint = chain.chain().joints[size_t(j)];
        const InertialParameters &p = joint.inertial;
        const double m = p[0];
        const Eigen::Vector3d c = p.segment<3>(1) / m;
        const Eigen::Matrix3d ic =
            rotationalInertia(p) -
            m * (c.squaredNorm() * Eigen::Matrix3d::Identity() - c * c.transpose());
        const Eigen::Matrix3d io =
            ic + m * (c.squaredNorm() * Eigen::Matrix3d::Identity() - c * c.transpose());
        const double own = joint.axis.dot(io * joint.axis);
        QVERIFY(own > 0.0);
        const double expected = s.simulation.armature[j] + s.simulation.armatureFactor[j] * own;
        QVERIFY(std::abs(r.armature[j] - expected) < 1e-12 * expected);
    }
}

void TestRealisticSession::lwr4AllOptions_sixTrialsRunAndCpuTimeIsPrinted()
{
    const QString cad = test::sharedDataFile(QStringLiteral("kuka-lwr4/kuka_lwr4.urdf"));
    if (cad.isEmpty())
        QSKIP(qPrintable(test::sharedDataMissing()));
    QTemporaryDir dir;
    Scenario s;
    s.model = QStringLiteral("urdf");
    s.urdf.file = cad;
    s.torqueLimits.resize(0);
    s.initialParameters.resize(0);
    s.simulation.trueParameters.resize(0);
    s.simulation.realUrdf = robotA(dir, cad);
    QVERIFY(!s.simulation.realUrdf.isEmpty());
    s.path.kind = PathKind::Waypoints;
    s.path.waypoints = {(Eigen::VectorXd(7) << 0, 0.3, 0, -1.2, 0, 0.5, 0).finished(),
                        (Eigen::VectorXd(7) << 0.8, 0.8, 0.5, -0.6, 0.6, -0.4, 0.9).finished(),
                        (Eigen::VectorXd(7) << -0.4, 0.5, -0.5, -1.4, -0.5, 0.6, -0.7).finished()};
    s.planningFraction = 0.3;
    s.controller.kp = (Eigen::VectorXd(7) << 340, 600, 100, 140, 15, 14, 11).finished();
    s.controller.ki = s.controller.kp / 10.0;
    s.controller.kd = (Eigen::VectorXd(7) << 45, 80, 14, 19, 2, 1.9, 1.5).finished();
    s.controller.lambda = 1000;
    s.maxTrackingErrorDeg = 5;
    s.simulation.encoderCounts = 1 << 20;
    s.simulation.torqueNoise = 0.01;
    s.simulation.substeps = 5;
    const Scenario base = s;
    const QByteArray only = qgetenv("LEARNID_ZOO_OPTIONS"); // e.g. "elastic" (default: all)
    for (const char *options : {"none", "stribeck", "armature", "elastic", "sensor", "all"}) {
        if (!only.isEmpty() && only != options)
            continue;
        const QString o = QLatin1String(options);
        const bool all = o == QLatin1String("all");
        s = base;
        if (all || o == QLatin1String("stribeck"))
            s.simulation.staticFrictionRatio = 1.5;
        if (all || o == QLatin1String("armature") || o == QLatin1String("elastic"))
            s.simulation.armatureFactor = Eigen::VectorXd::Constant(7, 1.0);
        if (all || o == QLatin1String("elastic")) {
            s.simulation.jointStiffness = Eigen::VectorXd::Constant(7, 10000.0);
            s.simulation.jointDamping = Eigen::VectorXd::Constant(7, 5.0);
        }
        if (all || o == QLatin1String("sensor")) {
            s.simulation.torqueSensorOffset = Eigen::VectorXd::Constant(7, 0.05);
            s.simulation.torqueSensorLag = 0.001;
        }
        const auto model = makeRobotModel(s.model, s.urdf);
        s = withRobotDefaults(s, *model);
        CommissioningSession session(s, model, makeSimulatedRobot(s, model));
        const std::clock_t start = std::clock();
        QStringList rows;
        QString firstStop;
        for (int k = 0; k < 6; ++k) {
            const TrialResult &result = session.runTrial();
            QVERIFY(result.record.tau.allFinite());
            QVERIFY(result.record.q.allFinite());
            QVERIFY2(result.record.status != TrialStatus::Faulted, qPrintable(result.message));
            if (!result.record.completed() && firstStop.isEmpty())
                firstStop = result.message;
            rows << QStringLiteral("%1%2")
                        .arg(result.maxTrackingErrorDeg.size() > 0
                                 ? result.maxTrackingErrorDeg.maxCoeff()
                                 : qQNaN(),
                             0, 'g', 3)
                        .arg(result.record.completed() ? "" : " (stopped)");
        }
        const double cpu = double(std::clock() - start) / CLOCKS_PER_SEC;
        qInfo("LWR4+ (a), %s: 6 trials in %.2f s CPU; max tracking error [deg] %s%s%s", options,
              cpu, qPrintable(rows.join(QStringLiteral(", "))),
              firstStop.isEmpty() ? "" : "; first stop: ", qPrintable(firstStop));
    }
}

QTEST_GUILESS_MAIN(TestRealisticSession)
#include "tst_realisticsession.moc"
