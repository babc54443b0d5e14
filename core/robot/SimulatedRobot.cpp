#include "robot/SimulatedRobot.h"

#include "control/PidController.h"
#include "model/VectorState.h"

#include <QCoreApplication>
#include <cmath>
#include <limits>

namespace learnid {

namespace {

constexpr double kRadToDeg = 180.0 / M_PI;

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(SimulatedRobot)
};

} // namespace

SimulatedRobot::SimulatedRobot(std::shared_ptr<const RobotModel> model, Eigen::VectorXd truePhi,
                               MeasurementOptions options)
    : m_model(std::move(model))
    , m_truePhi(std::move(truePhi))
    , m_options(options)
{}

QString SimulatedRobot::description() const
{
    return Text::tr("simulated %1").arg(m_model->id());
}

TrialRecord SimulatedRobot::runTrial(const TrialPlan &plan, const TrialMonitor &monitor)
{
    clearUpperVectorState();
    const quint64 noiseStream = m_options.firstNoiseStream + m_trialCount++;
    if (m_model->dof() == 2)
        return simulate<2>(plan, monitor, noiseStream);
    return simulate<Eigen::Dynamic>(plan, monitor, noiseStream);
}

template <int N>
TrialRecord SimulatedRobot::simulate(const TrialPlan &plan, const TrialMonitor &monitor,
                                     quint64 noiseStream) const
{
    using Vector = typename ArmSimulation<N>::Vector;
    const int n = m_model->dof();
    const int samples = plan.samples();
    const double ts = plan.desired.samplePeriod;
    ArmSimulation<N> arm(m_model, m_truePhi, m_options, ts, noiseStream);

    TrialRecord record;
    record.samplePeriod = ts;
    record.q.resize(n, samples);
    record.tau.resize(n, samples);

    PidController pid(plan.controller);
    arm.reset(plan.desired.q.col(0)); // the robot starts at rest at the path start
    Vector qMeasured(n), e(n), u(n), tauCommand(n), tauPlant(n), disturbance = Vector::Zero(n);
    if (m_faults.disturbanceTorque.size() == n)
        disturbance = m_faults.disturbanceTorque;
    const Vector limit = plan.torqueLimit;

    int recorded = 0;
    for (int k = 0; k < samples; ++k) {
        arm.measureAngles(qMeasured);
        e = plan.desired.q.col(k) - qMeasured;

        pid.step(e, u);
        tauCommand = (plan.feedforward.col(k) + u).cwiseMax(-limit).cwiseMin(limit);
        record.q.col(k) = qMeasured;
        arm.measureTorques(tauCommand, record.tau.col(k));
        arm.addTorqueNoise(record.tau.col(k), limit);
        if (k == m_faults.nanTorqueAtSample)
            record.tau(0, k) = std::numeric_limits<double>::quiet_NaN();
        recorded = k + 1;

        Eigen::Index worst = 0;
        const double worstError = e.cwiseAbs().maxCoeff(&worst);
        if (worstError > plan.maxTrackingError) {
            record.status = TrialStatus::Aborted;
            record.stopCause = TrialStopCause::TrackingLimit;
            record.message = Text::tr("tracking error of joint %1 reached %2 deg at t = %3 s "
                                      "(limit %4 deg): quick stop")
                                 .arg(worst + 1)
                                 .arg(worstError * kRadToDeg, 0, 'g', 4)
                                 .arg(k * ts, 0, 'f', 3)
                                 .arg(plan.maxTrackingError * kRadToDeg, 0, 'g', 4);
            break;
        }
        if (k == m_faults.driveFaultAtSample) {
            record.status = TrialStatus::Faulted;
            record.stopCause = TrialStopCause::RobotFault;
            record.message = Text::tr("drive of joint 1 reported a fault at t = %1 s (injected)")
                                 .arg(k * ts, 0, 'f', 3);
            break;
        }
        if (monitor.cancelled()) {
            record.status = TrialStatus::Cancelled;
            record.stopCause = TrialStopCause::Operator;
            record.message = Text::tr("stopped by the operator at t = %1 s").arg(k * ts, 0, 'f', 3);
            break;
        }

        tauPlant = tauCommand;
        if (m_faults.disturbanceFromSample >= 0 && k >= m_faults.disturbanceFromSample)
            tauPlant += disturbance;
        arm.integrate(tauPlant);

        if (monitor.progress && ((k + 1) % 100 == 0 || k + 1 == samples)) {
            monitor.progress(k + 1, samples);
            clearUpperVectorState(); // the report may have run Qt code (a signal)
        }
    }
    record.q.conservativeResize(n, recorded);
    record.tau.conservativeResize(n, recorded);
    return record;
}

QString SimulatedRobot::applyParameters(const Eigen::VectorXd &phi)
{
    if (m_faults.refuseApply)
        return Text::tr("the simulated controller refused the parameter write (injected fault); "
                        "its stored parameters are unchanged");
    if (phi.size() != m_model->parameterCount() || !phi.allFinite())
        return Text::tr("parameter set has %1 values, the model needs %2 finite values")
            .arg(phi.size())
            .arg(m_model->parameterCount());
    m_stored = phi;
    return {};
}

} // namespace learnid
