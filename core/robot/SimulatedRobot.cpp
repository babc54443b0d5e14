#include "robot/SimulatedRobot.h"

#include "control/PidController.h"

#include <QCoreApplication>
#include <cmath>
#include <limits>

namespace learnid {

namespace {

constexpr double kRadToDeg = 180.0 / M_PI;

QString tr(const char *text)
{
    return QCoreApplication::translate("SimulatedRobot", text);
}

} // namespace

SimulatedRobot::SimulatedRobot(std::shared_ptr<const RobotModel> model, Eigen::VectorXd truePhi,
                               MeasurementOptions options)
    : m_model(std::move(model))
    , m_truePhi(std::move(truePhi))
    , m_options(options)
{}

QString SimulatedRobot::description() const
{
    return tr("simulated %1").arg(m_model->id());
}

TrialRecord SimulatedRobot::runTrial(const TrialPlan &plan, const TrialMonitor &monitor)
{
    std::seed_seq seq{quint64(m_options.seed), quint64(m_trialCount++)};
    std::mt19937_64 rng(seq);
    if (m_model->dof() == 2)
        return simulate<2>(plan, monitor, rng);
    return simulate<Eigen::Dynamic>(plan, monitor, rng);
}

template <int N>
TrialRecord SimulatedRobot::simulate(const TrialPlan &plan, const TrialMonitor &monitor,
                                     std::mt19937_64 &rng) const
{
    using Vector = Eigen::Matrix<double, N, 1>;
    const int n = m_model->dof();
    const int samples = plan.samples();
    const double ts = plan.desired.samplePeriod;
    const int substeps = std::max(1, m_options.substeps);
    const double h = ts / substeps;
    std::normal_distribution<double> normal(0.0, 1.0);
    const double countAngle = m_options.encoderCounts > 0
                                  ? 2.0 * M_PI / double(m_options.encoderCounts)
                                  : 0.0;

    TrialRecord record;
    record.samplePeriod = ts;
    record.q.resize(n, samples);
    record.tau.resize(n, samples);

    PidController pid(plan.controller);
    Vector q = plan.desired.q.col(0); // the robot starts at rest at the path start
    Vector qd = Vector::Zero(n);
    Vector qMeasured(n), e(n), u(n), tauCommand(n), tauPlant(n), disturbance = Vector::Zero(n);
    if (m_faults.disturbanceTorque.size() == n)
        disturbance = m_faults.disturbanceTorque;
    const Vector limit = plan.torqueLimit;

    int recorded = 0;
    for (int k = 0; k < samples; ++k) {
        if (countAngle > 0.0)
            qMeasured = (q / countAngle).array().round() * countAngle;
        else
            qMeasured = q;
        e = plan.desired.q.col(k) - qMeasured;

        pid.step(e, u);
        tauCommand = (plan.feedforward.col(k) + u).cwiseMax(-limit).cwiseMin(limit);
        record.q.col(k) = qMeasured;
        record.tau.col(k) = tauCommand;
        if (m_options.torqueNoise > 0.0)
            for (int j = 0; j < n; ++j)
                record.tau(j, k) += m_options.torqueNoise * limit[j] * normal(rng);
        if (k == m_faults.nanTorqueAtSample)
            record.tau(0, k) = std::numeric_limits<double>::quiet_NaN();
        recorded = k + 1;

        Eigen::Index worst = 0;
        const double worstError = e.cwiseAbs().maxCoeff(&worst);
        if (worstError > plan.maxTrackingError) {
            record.status = TrialStatus::Aborted;
            record.message = tr("tracking error of joint %1 reached %2 deg at t = %3 s "
                                "(limit %4 deg): quick stop")
                                 .arg(worst + 1)
                                 .arg(worstError * kRadToDeg, 0, 'g', 4)
                                 .arg(k * ts, 0, 'f', 3)
                                 .arg(plan.maxTrackingError * kRadToDeg, 0, 'g', 4);
            break;
        }
        if (k == m_faults.driveFaultAtSample) {
            record.status = TrialStatus::Faulted;
            record.message = tr("drive of joint 1 reported a fault at t = %1 s (injected)")
                                 .arg(k * ts, 0, 'f', 3);
            break;
        }
        if (monitor.cancelled()) {
            record.status = TrialStatus::Cancelled;
            record.message = tr("stopped by the operator at t = %1 s").arg(k * ts, 0, 'f', 3);
            break;
        }

        tauPlant = tauCommand;
        if (m_faults.disturbanceFromSample >= 0 && k >= m_faults.disturbanceFromSample)
            tauPlant += disturbance;
        for (int s = 0; s < substeps; ++s)
            m_model->rk4Step(q, qd, tauPlant, m_truePhi, h);

        if (monitor.progress && ((k + 1) % 100 == 0 || k + 1 == samples))
            monitor.progress(k + 1, samples);
    }
    record.q.conservativeResize(n, recorded);
    record.tau.conservativeResize(n, recorded);
    return record;
}

QString SimulatedRobot::applyParameters(const Eigen::VectorXd &phi)
{
    if (m_faults.refuseApply)
        return tr("the simulated controller refused the parameter write (injected fault); "
                  "its stored parameters are unchanged");
    if (phi.size() != m_model->parameterCount() || !phi.allFinite())
        return tr("parameter set has %1 values, the model needs %2 finite values")
            .arg(phi.size())
            .arg(m_model->parameterCount());
    m_stored = phi;
    return {};
}

} // namespace learnid
