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

template <typename A, typename B> bool sameMatrix(const A &a, const B &b)
{
    return a.rows() == b.rows() && a.cols() == b.cols() && a.cwiseEqual(b).all();
}

// Whether the arm moves the same under both plans: the same set-points, feedforward, gains,
// limits and abort threshold (the parameters the feedforward came from do not move it).
bool movesTheSame(const TrialPlan &a, const TrialPlan &b)
{
    const ControllerSettings &ca = a.controller, &cb = b.controller;
    return a.desired.samplePeriod == b.desired.samplePeriod &&
           sameMatrix(a.desired.q, b.desired.q) && sameMatrix(a.feedforward, b.feedforward) &&
           ca.samplePeriod == cb.samplePeriod && sameMatrix(ca.kp, cb.kp) &&
           sameMatrix(ca.ki, cb.ki) && sameMatrix(ca.kd, cb.kd) && ca.lambda == cb.lambda &&
           sameMatrix(a.torqueLimit, b.torqueLimit) && a.maxTrackingError == b.maxTrackingError;
}

void stopByOperator(TrialRecord &record, int k)
{
    record.status = TrialStatus::Cancelled;
    record.stopCause = TrialStopCause::Operator;
    record.message =
        Text::tr("stopped by the operator at t = %1 s").arg(k * record.samplePeriod, 0, 'f', 3);
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
    return Text::tr("simulated %1").arg(m_model->id());
}

TrialRecord SimulatedRobot::runTrial(const TrialPlan &plan, const TrialMonitor &monitor)
{
    clearUpperVectorState();
    const quint64 noiseStream = m_options.firstNoiseStream + m_trialCount++;
    TrialRecord record;
    if (!faultsInjected() && m_lastRun && movesTheSame(m_lastRun->plan, plan)) {
        record = replayLastRun(monitor);
    } else {
        m_lastRun.reset();
        record = m_model->dof() == 2 ? simulate<2>(plan, monitor)
                                     : simulate<Eigen::Dynamic>(plan, monitor);
        if (!faultsInjected() && record.status != TrialStatus::Cancelled)
            m_lastRun = NoiseFreeRun{plan, record};
    }
    // The run's noise, drawn sample by sample from its own stream as the arm draws it.
    if (m_options.torqueNoise > 0.0) {
        MeasurementOptions options = m_options;
        options.realism = {}; // the noise only: no plant
        ArmSimulation<> noise(m_model, m_truePhi, options, record.samplePeriod, noiseStream);
        for (int k = 0; k < record.samples(); ++k)
            noise.addTorqueNoise(record.tau.col(k), plan.torqueLimit);
    }
    return record;
}

bool SimulatedRobot::faultsInjected() const
{
    return m_faults.driveFaultAtSample >= 0 || m_faults.nanTorqueAtSample >= 0 ||
           m_faults.disturbanceFromSample >= 0;
}

TrialRecord SimulatedRobot::replayLastRun(const TrialMonitor &monitor) const
{
    const TrialRecord &last = m_lastRun->record;
    const int samples = m_lastRun->plan.samples();
    // simulate()'s checks after each sample, in its order: the tracking limit, then Stop.
    for (int k = 0; k < last.samples(); ++k) {
        if (last.stoppedAtTrackingLimit() && k + 1 == last.samples())
            break;
        if (monitor.cancelled()) {
            TrialRecord out = last;
            out.q.conservativeResize(Eigen::NoChange, k + 1);
            out.tau.conservativeResize(Eigen::NoChange, k + 1);
            stopByOperator(out, k);
            return out;
        }
        if (monitor.progress && ((k + 1) % 100 == 0 || k + 1 == samples)) {
            monitor.progress(k + 1, samples);
            clearUpperVectorState();
        }
    }
    return last;
}

template <int N>
TrialRecord SimulatedRobot::simulate(const TrialPlan &plan, const TrialMonitor &monitor) const
{
    using Vector = typename ArmSimulation<N>::Vector;
    const int n = m_model->dof();
    const int samples = plan.samples();
    const double ts = plan.desired.samplePeriod;
    ArmSimulation<N> arm(m_model, m_truePhi, m_options, ts);

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
            stopByOperator(record, k);
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
