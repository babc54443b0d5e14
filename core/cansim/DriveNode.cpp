#include "cansim/DriveNode.h"

#include "can/CanLink.h"
#include "can/ManufacturerObjects.h"
#include "can/Pdo.h"
#include "cansim/DriveDictionary.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace learnid {

using cia402::State;
namespace ob = objects;

namespace {

constexpr quint16 controlQuickStop = 0x0002;
constexpr quint16 controlDisableVoltage = 0x0000;

} // namespace

DriveNode::DriveNode(CanLink *link, const DriveNodeSettings &settings, QObject *parent)
    : QObject(parent)
    , m_link(link)
    , m_settings(settings)
    , m_sdo(link, settings.node, &m_dictionary)
    , m_heartbeat(link, settings.node)
{
    addDriveObjects(m_dictionary, settings);
    m_drive.initialise();
    connect(link, &CanLink::frameReceived, this, &DriveNode::handleFrame);
    connect(&m_dictionary, &ObjectDictionary::valueWritten, this, &DriveNode::onWritten);
    m_dictionary.setValue(ob::statusword, 0, statusword());
}

quint16 DriveNode::statusword() const
{
    return quint16(m_drive.statusword() | (m_followed ? cansim::statusFollowsCommand : 0));
}

void DriveNode::bootUp()
{
    m_heartbeat.sendBootUp();
    setNmtState(NmtState::PreOperational);
}

double DriveNode::countAngle() const
{
    return 2.0 * M_PI / m_dictionary.value(cansim::positionEncoderResolution, 1);
}

double DriveNode::torqueUnit() const
{
    return m_dictionary.value(cansim::motorRatedTorque, 0) * 1e-6;
}

double DriveNode::torqueLimit() const
{
    return m_dictionary.value(ob::torqueLimit, 0);
}

void DriveNode::setSilent(bool silent)
{
    m_silent = silent;
    m_heartbeat.setSilent(silent);
    m_sdo.setSilent(silent || m_nmt == NmtState::Stopped);
}

void DriveNode::setFaultAtEnabledSync(int k, quint16 code)
{
    m_faultAtEnabledSync = k;
    m_injectedCode = code;
}

void DriveNode::handleFrame(const QCanBusFrame &frame)
{
    if (const auto command = nmtCommandFor(frame, node())) {
        handleNmt(*command);
        return;
    }
    if (m_nmt != NmtState::Operational || frame.frameType() != QCanBusFrame::DataFrame ||
        frame.hasExtendedFrameFormat() || !trialPdoActive(m_dictionary, true))
        return;
    const quint32 cobId =
        quint32(m_dictionary.value(pdoCommunicationIndex(PdoDirection::Receive, 1), 1));
    if (frame.frameId() == (cobId & 0x7FFu))
        receiveRpdo(frame.payload());
}

void DriveNode::handleNmt(NmtCommand command)
{
    const bool wasOperational = m_nmt == NmtState::Operational;
    if (command == NmtCommand::ResetNode) {
        m_drive = Cia402Drive();
        m_drive.initialise();
        m_pid.reset();
        m_followed = false; // statusword bit 12 belongs to Operation enabled only
        m_dictionary.setValue(ob::errorRegister, 0, 0);
        m_stored.restore(m_dictionary, m_settings);
        updateRatedTorque();
    }
    if (command == NmtCommand::ResetNode || command == NmtCommand::ResetCommunication) {
        resetCommunicationObjects(m_dictionary, node());
        m_heartbeat.setPeriod(0);
        m_fresh = false;
        bootUp();
    } else {
        setNmtState(nmtStateAfter(command, m_nmt));
    }
    // A drive that loses its master while powered stops itself (quick stop, then brakes).
    if (wasOperational && m_nmt != NmtState::Operational &&
        m_drive.state() == State::OperationEnabled)
        applyControlword(controlQuickStop);
    m_dictionary.setValue(ob::statusword, 0, statusword());
}

void DriveNode::setNmtState(NmtState state)
{
    m_nmt = state;
    m_heartbeat.setState(state);
    m_sdo.setSilent(m_silent || state == NmtState::Stopped);
}

void DriveNode::receiveRpdo(const QByteArray &payload)
{
    const PdoMapping mapping = ob::trialRpdoMapping();
    if (payload.size() < mapping.byteLength())
        return; // too short: not a set-point (the SYNC will count it as missed)
    const QList<double> v = mapping.unpack(payload);
    m_received.target = v[0] * countAngle();
    m_received.offset = v[1] * torqueUnit();
    m_received.controlword = quint16(v[2]);
    m_dictionary.setValue(ob::targetPosition, 0, v[0]);
    m_dictionary.setValue(ob::torqueOffset, 0, v[1]);
    m_fresh = true;
}

void DriveNode::onWritten(quint16 index, quint8 subIndex)
{
    if (index == ob::producerHeartbeatTime)
        m_heartbeat.setPeriod(int(m_dictionary.value(index, 0)));
    else if (index == ob::torqueLimit)
        updateRatedTorque();
    else if (index == ob::storeParameters && subIndex == ob::storeAll)
        store();
    else if (index == ob::controlword) {
        applyControlword(quint16(m_dictionary.value(index, 0)));
        flushEmcy();
    }
}

void DriveNode::applyControlword(quint16 controlword)
{
    const State before = m_drive.state();
    m_drive.applyControlword(controlword);
    m_dictionary.setValue(ob::controlword, 0, controlword);
    if (m_drive.state() != before)
        m_followed = false; // e.g. an SDO write of 0x6040 between SYNCs: bit 12 is OE's only
    if (before == State::Fault && m_drive.state() != State::Fault) {
        m_dictionary.setValue(ob::errorRegister, 0, 0);
        queueEmcy(0x0000); // error reset
    }
    m_dictionary.setValue(ob::statusword, 0, statusword());
}

DriveSyncOutput DriveNode::sync(double q)
{
    m_q = q;
    m_followed = false;
    const bool fresh = m_fresh && m_nmt == NmtState::Operational;
    m_fresh = false;
    if (fresh)
        applyControlword(m_received.controlword);

    State state = m_drive.state();
    if (state == State::OperationEnabled && m_stateAtLastSync != State::OperationEnabled)
        enterOperation(q);
    if (state == State::QuickStopActive && m_stateAtLastSync != State::QuickStopActive) {
        m_holdTarget = q;
        m_quickStopSyncs = 0;
    }
    if (state == State::OperationEnabled) {
        if (fresh) {
            m_command = m_received;
            m_missed = 0;
            m_followed = true;
        } else if (++m_missed >= m_settings.setPointTimeoutSyncs) {
            fault(cansim::emcyCommunication, cansim::errorRegisterCommunication);
        }
        if (++m_enabledSyncs == m_faultAtEnabledSync && m_drive.state() == State::OperationEnabled)
            fault(m_injectedCode, cansim::errorRegisterDeviceProfile);
    }
    if (state == State::QuickStopActive && m_quickStopSyncs++ >= cansim::quickStopSyncs)
        applyControlword(controlDisableVoltage); // 12: Switch on disabled, the brake holds

    state = m_drive.state();
    DriveSyncOutput out;
    const double limit = torqueLimit();
    if (state == State::OperationEnabled && m_pid) {
        out.torque = std::clamp(m_command.offset + pidStep(m_command.target - q), -limit, limit);
        out.powered = true;
    } else if (state == State::QuickStopActive && m_pid) {
        out.torque = std::clamp(pidStep(m_holdTarget - q), -limit, limit);
        out.powered = true;
    }
    m_stateAtLastSync = state;
    m_dictionary.setValue(ob::statusword, 0, statusword());
    return out;
}

void DriveNode::enterOperation(double q)
{
    ControllerSettings pid;
    pid.samplePeriod = interpolationPeriod(m_dictionary);
    pid.kp = Eigen::VectorXd::Constant(1, m_dictionary.value(ob::gains, ob::gainKp));
    pid.ki = Eigen::VectorXd::Constant(1, m_dictionary.value(ob::gains, ob::gainKi));
    pid.kd = Eigen::VectorXd::Constant(1, m_dictionary.value(ob::gains, ob::gainKd));
    pid.lambda = m_dictionary.value(ob::gains, ob::gainLambda);
    m_pid.emplace(pid);
    m_command = SetPoint{q, 0.0, 0};
    m_missed = 0;
    m_enabledSyncs = 0;
}

double DriveNode::pidStep(double e)
{
    m_e[0] = e;
    m_pid->step(m_e, m_u);
    return m_u[0];
}

void DriveNode::sendAfterSync(double measuredTorque, bool dropTpdo)
{
    flushEmcy();
    const double inc = std::round(m_q / countAngle());
    const double torque = std::clamp(std::round(measuredTorque / torqueUnit()), -32768.0, 32767.0);
    m_dictionary.setValue(ob::positionActual, 0, std::clamp(inc, -2147483648.0, 2147483647.0));
    m_dictionary.setValue(ob::torqueActual, 0, torque);
    if (dropTpdo || m_silent || m_nmt != NmtState::Operational ||
        !trialPdoActive(m_dictionary, false))
        return;
    const QByteArray payload = ob::trialTpdoMapping().pack(
        {m_dictionary.value(ob::positionActual, 0), torque, double(statusword())});
    const quint32 cobId =
        quint32(m_dictionary.value(pdoCommunicationIndex(PdoDirection::Transmit, 1), 1));
    m_link->send(QCanBusFrame(cobId & 0x7FFu, payload));
}

void DriveNode::fault(quint16 code, quint8 errorBits)
{
    m_drive.raiseFault();
    m_drive.completeFaultReaction(); // the simulated brake engages at once
    m_followed = false;
    m_dictionary.setValue(ob::errorRegister, 0, cansim::errorRegisterGeneric | errorBits);
    queueEmcy(code);
}

void DriveNode::queueEmcy(quint16 code)
{
    EmcyMessage message;
    message.node = node();
    message.errorCode = code;
    message.errorRegister = quint8(m_dictionary.value(ob::errorRegister, 0));
    message.manufacturerData = QByteArray(5, '\0');
    m_pendingEmcy.append(message);
}

void DriveNode::flushEmcy()
{
    const QList<EmcyMessage> pending = std::exchange(m_pendingEmcy, {});
    for (const EmcyMessage &message : pending) {
        if (!m_silent)
            m_link->send(encodeEmcy(message));
        emit emergencySent(message);
    }
}

void DriveNode::store()
{
    m_stored.store(m_dictionary);
    emit parametersStored(node());
}

Eigen::VectorXd DriveNode::storedParameters() const
{
    return m_stored.parameters();
}

void DriveNode::updateRatedTorque()
{
    m_dictionary.setValue(cansim::motorRatedTorque, 0, cansim::ratedTorqueFor(torqueLimit()));
}

} // namespace learnid
