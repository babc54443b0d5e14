#include "can/Cia402Drive.h"

namespace learnid {

using cia402::Command;
using cia402::State;

void Cia402Drive::initialise()
{
    if (m_state == State::NotReadyToSwitchOn)
        m_state = State::SwitchOnDisabled;
}

State Cia402Drive::applyControlword(quint16 controlword)
{
    const bool faultResetEdge = (controlword & cia402::controlFaultReset) &&
                                !(m_lastControlword & cia402::controlFaultReset);
    m_lastControlword = controlword;
    if (m_state == State::Fault) {
        if (faultResetEdge)
            m_state = State::SwitchOnDisabled; // 15
        return m_state;
    }
    if (controlword & cia402::controlFaultReset)
        return m_state; // bit 7 set outside Fault: no device control command

    const Command c = cia402::commandFromControlword(controlword);
    switch (m_state) {
    case State::SwitchOnDisabled:
        if (c == Command::Shutdown)
            m_state = State::ReadyToSwitchOn; // 2
        break;
    case State::ReadyToSwitchOn:
        if (c == Command::SwitchOn)
            m_state = State::SwitchedOn; // 3
        else if (c == Command::EnableOperation)
            m_state = State::OperationEnabled; // 3 + 4
        else if (c == Command::DisableVoltage || c == Command::QuickStop)
            m_state = State::SwitchOnDisabled; // 7
        break;
    case State::SwitchedOn:
        if (c == Command::EnableOperation)
            m_state = State::OperationEnabled; // 4
        else if (c == Command::Shutdown)
            m_state = State::ReadyToSwitchOn; // 6
        else if (c == Command::DisableVoltage || c == Command::QuickStop)
            m_state = State::SwitchOnDisabled; // 10
        break;
    case State::OperationEnabled:
        if (c == Command::DisableOperation || c == Command::SwitchOn)
            m_state = State::SwitchedOn; // 5
        else if (c == Command::Shutdown)
            m_state = State::ReadyToSwitchOn; // 8
        else if (c == Command::DisableVoltage)
            m_state = State::SwitchOnDisabled; // 9
        else if (c == Command::QuickStop)
            m_state = State::QuickStopActive; // 11
        break;
    case State::QuickStopActive:
        if (c == Command::DisableVoltage)
            m_state = State::SwitchOnDisabled; // 12
        else if (c == Command::EnableOperation)
            m_state = State::OperationEnabled; // 16
        break;
    case State::NotReadyToSwitchOn:
    case State::FaultReactionActive:
    case State::Fault:
    case State::Unknown:
        break; // automatic transitions only
    }
    return m_state;
}

void Cia402Drive::raiseFault()
{
    if (m_state != State::Fault)
        m_state = State::FaultReactionActive; // 13
}

void Cia402Drive::completeFaultReaction()
{
    if (m_state == State::FaultReactionActive)
        m_state = State::Fault; // 14
}

quint16 Cia402Drive::statusword() const
{
    quint16 pattern = 0;
    switch (m_state) {
    case State::NotReadyToSwitchOn:
        pattern = 0x0000;
        break;
    case State::SwitchOnDisabled:
        pattern = 0x0040;
        break;
    case State::ReadyToSwitchOn:
        pattern = 0x0021 | cia402::statusVoltageEnabled;
        break;
    case State::SwitchedOn:
        pattern = 0x0023 | cia402::statusVoltageEnabled;
        break;
    case State::OperationEnabled:
        pattern = 0x0027 | cia402::statusVoltageEnabled;
        break;
    case State::QuickStopActive:
        pattern = 0x0007 | cia402::statusVoltageEnabled;
        break;
    case State::FaultReactionActive:
        pattern = 0x000F;
        break;
    case State::Fault:
    case State::Unknown:
        pattern = 0x0008;
        break;
    }
    return quint16(pattern | cia402::statusRemote);
}

bool Cia402Drive::powerApplied() const
{
    return m_state == State::OperationEnabled || m_state == State::QuickStopActive;
}

} // namespace learnid
