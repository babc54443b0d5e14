// fitLogs on logs whose truth is known: the PUMA 560 (built-in) with every inertial parameter
// and friction changed by up to 30 % (a real robot: ChainPerturbation), its torques computed by
// the model itself along smooth multi-sine motions. The fit must predict the torque of a motion
// it did not see, give real bodies, and keep at the CAD values what the data cannot see.
#include "identify/LogFit.h"
#include "model/ChainModel.h"
#include "model/ChainPerturbation.h"
#include "model/PhysicalConsistency.h"
#include "model/UrdfChain.h"

#include <QTest>
#include <cmath>
#include <random>

using namespace learnid;

namespace {

constexpr double period = 0.005;

ChainModel puma()
{
    JointTerms terms;
    terms.offset = true;
    return ChainModel(readUrdfChain(QStringLiteral(":/robots/puma560.urdf")), terms,
                      QStringLiteral("puma560"));
}

// A log of the true robot along q_j(t) = c_j + sum_i a sin(w_i t + p_i), 3 sines per joint
// (frequencies 0.3 to 1.5 rad/s times the seed's draw), its torque tau = Y(q, qd, qdd) pi_true
// exactly. Joint `still` (if >= 0) does not move.
UniformLog trueLog(const ChainModel &model, const Eigen::VectorXd &truth, unsigned seed,
                   double seconds, int still = -1)
{
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const int n = model.dof();
    const Eigen::Index samples = Eigen::Index(std::lround(seconds / period)) + 1;
    Eigen::MatrixXd w(n, 3), a(n, 3), p(n, 3);
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < 3; ++i) {
            w(j, i) = (0.3 + 0.4 * i) * (1.0 + u(random));
            a(j, i) = j == still ? 0.0 : 0.25 * (1.0 + u(random)) / (1 + i);
            p(j, i) = 6.28 * u(random);
        }
    }
    const Eigen::VectorXd centre = (Eigen::VectorXd(6) << 0.0, 1.2, -1.5, 0.5, 0.0, 0.0).finished();
    UniformLog log;
    log.source = QStringLiteral("truth-%1.csv").arg(seed);
    log.period = period;
    log.q.resize(n, samples);
    log.dq.resize(n, samples);
    log.tau.resize(n, samples);
    Eigen::VectorXd qdd(n);
    Eigen::MatrixXd y(n, model.standardCount());
    for (Eigen::Index k = 0; k < samples; ++k) {
        const double t = log.time(k);
        for (int j = 0; j < n; ++j) {
            log.q(j, k) = centre[j];
            log.dq(j, k) = qdd[j] = 0.0;
            for (int i = 0; i < 3; ++i) {
                const double phase = w(j, i) * t + p(j, i);
                log.q(j, k) += a(j, i) * std::sin(phase);
                log.dq(j, k) += a(j, i) * w(j, i) * std::cos(phase);
                qdd[j] -= a(j, i) * w(j, i) * w(j, i) * std::sin(phase);
            }
        }
        model.standardRegressor(log.q.col(k), log.dq.col(k), qdd, y);
        log.tau.col(k) = y * truth;
    }
    return log;
}

} // namespace

class TestLogFit : public QObject
{
    Q_OBJECT

private slots:
    void fit_predictsAnUnseenMotion_withRealBodies();
    void stillJoint_keepsItsFrictionAtTheCadValues();
    void laggedSensors_fitLikeUnlaggedOnceTheLagIsUndone();
    void logOfOtherJointCount_isRefused();
};

void TestLogFit::fit_predictsAnUnseenMotion_withRealBodies()
{
    const ChainModel model = puma();
    const Eigen::VectorXd truth = perturbedStandard(model, 0.3, 7);
    const LogFilterSettings filter;
    const std::vector<FilteredLog> training = {filterLog(trueLog(model, truth, 1, 30.0), filter),
                                               filterLog(trueLog(model, truth, 2, 30.0), filter)};
    const FilteredLog validation = filterLog(trueLog(model, truth, 3, 20.0), filter);

    const LogFit fit = fitLogs(model, training, LogFitSettings{});
    const TorqueFigures cad = torqueFigures(model, model.cadStandard(), validation);
    const TorqueFigures found = torqueFigures(model, fit.standard, validation);
    const TorqueFigures exact = torqueFigures(model, truth, validation);
    qInfo("validation torque error: CAD %.3g, fit %.3g, truth %.3g; rank %d of %d", cad.overall,
          found.overall, exact.overall, fit.rank, fit.baseCount);
    // The truth predicts its own torque up to the differentiation filter's error on qdd.
    QVERIFY2(exact.overall < 2e-4, qPrintable(QString::number(exact.overall)));
    QVERIFY2(cad.overall > 0.05, qPrintable(QString::number(cad.overall)));
    QVERIFY2(found.overall < 0.01 * cad.overall,
             qPrintable(QStringLiteral("%1 against CAD %2").arg(found.overall).arg(cad.overall)));
    for (const LinkConsistency &l : checkConsistency(fit.standard, model.dof(), 1e-12))
        QVERIFY2(l.consistent, qPrintable(QStringLiteral("link %1").arg(l.link + 1)));
    QVERIFY(fit.converged);
    QVERIFY(fit.rank > 0 && fit.rank <= fit.baseCount);
    QCOMPARE(fit.jointNoise.size(), Eigen::Index(model.dof()));
}

void TestLogFit::stillJoint_keepsItsFrictionAtTheCadValues()
{
    const ChainModel model = puma();
    const Eigen::VectorXd truth = perturbedStandard(model, 0.3, 11);
    const LogFilterSettings filter;
    const LogFit fit =
        fitLogs(model, {filterLog(trueLog(model, truth, 4, 30.0, 5), filter)}, LogFitSettings{});
    // Joint 6's viscous and Coulomb friction act only when it moves: undetermined, kept.
    const int terms = model.jointTerms().count();
    const Eigen::Index viscous6 = 10 * 6 + 5 * terms;
    for (const Eigen::Index i : {viscous6, viscous6 + 1}) {
        QVERIFY2(std::abs(fit.standard[i] - fit.prior[i]) <= 1e-6 * std::abs(fit.prior[i]),
                 qPrintable(QStringLiteral("%1: %2, CAD %3")
                                .arg(model.standardParameters()[int(i)].name)
                                .arg(fit.standard[i])
                                .arg(fit.prior[i])));
    }
    bool reported = false;
    const QList<ParameterInfo> names = model.parameters();
    for (const int b : fit.undetermined())
        reported =
            reported || names[b].name.contains(model.standardParameters()[int(viscous6)].name);
    QVERIFY2(reported, "joint 6's viscous friction is not reported undetermined");
}

void TestLogFit::laggedSensors_fitLikeUnlaggedOnceTheLagIsUndone()
{
    // Torque sensors with a 20 ms first-order lag, sampled y_k = y_k-1 + a (x_k - y_k-1), settled
    // at the start. Undone (LogFilterSettings::torqueSensorLag, --torque-sensor-lag), the fit is
    // the one the sensors' input gives, to rounding; taken as measured, the lag biases it.
    const ChainModel model = puma();
    const Eigen::VectorXd truth = perturbedStandard(model, 0.3, 7);
    const double lag = 0.02;
    const double a = 1.0 - std::exp(-period / lag);
    const auto lagged = [a](UniformLog log) {
        for (Eigen::Index k = 1; k < log.tau.cols(); ++k)
            log.tau.col(k) = log.tau.col(k - 1) + a * (log.tau.col(k) - log.tau.col(k - 1));
        return log;
    };
    const auto fit = [&](bool delay, double undo) {
        LogFilterSettings filter;
        filter.torqueSensorLag = undo;
        std::vector<FilteredLog> logs;
        for (const unsigned seed : {1u, 2u}) {
            const UniformLog log = trueLog(model, truth, seed, 30.0);
            logs.push_back(filterLog(delay ? lagged(log) : log, filter));
        }
        return fitLogs(model, logs, LogFitSettings{}).standard;
    };
    const FilteredLog validation = filterLog(trueLog(model, truth, 3, 20.0), LogFilterSettings{});
    const double unlagged = torqueFigures(model, fit(false, 0.0), validation).overall;
    const double undone = torqueFigures(model, fit(true, lag), validation).overall;
    const double asMeasured = torqueFigures(model, fit(true, 0.0), validation).overall;
    qInfo("validation torque error: unlagged %.4g, lag undone %.4g, lag as measured %.4g", unlagged,
          undone, asMeasured);
    QVERIFY2(std::abs(undone - unlagged) <= 1e-6 + 1e-3 * unlagged,
             qPrintable(QStringLiteral("%1 against %2").arg(undone).arg(unlagged)));
    QVERIFY2(asMeasured > 3.0 * unlagged,
             qPrintable(QStringLiteral("%1 against %2").arg(asMeasured).arg(unlagged)));

    LogFilterSettings negative;
    negative.torqueSensorLag = -0.001;
    QVERIFY_THROWS_EXCEPTION(Error, filterLog(trueLog(model, truth, 1, 5.0), negative));
}

void TestLogFit::logOfOtherJointCount_isRefused()
{
    const ChainModel model = puma();
    FilteredLog log;
    log.source = QStringLiteral("two.csv");
    log.q = log.qd = log.qdd = log.tau = Eigen::MatrixXd::Zero(2, 10);
    try {
        fitLogs(model, {log}, LogFitSettings{});
        QFAIL("no error");
    } catch (const Error &e) {
        QCOMPARE(e.message(), QStringLiteral("two.csv has 2 joints, the robot 6"));
    }
}

QTEST_APPLESS_MAIN(TestLogFit)
#include "tst_logfit.moc"
