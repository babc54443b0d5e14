#pragma once

#include "can/Cia402.h"

#include <QtGlobal>

namespace learnid {

/// The CiA 402 device control state machine of a simulated drive: reacts to controlwords as a
/// drive does and produces its statusword. A fault can be raised at any time (transition 13);
/// the fault reaction completes on completeFaultReaction() (14). Quick stop active stays until
/// the master disables voltage (12) or enables operation again (16).
class Cia402Drive
{
public:
    /// Starts in Not ready to switch on; initialise() performs transition 1.
    Cia402Drive() = default;

    /// Self test done: Not ready to switch on -> Switch on disabled (transition 1).
    void initialise();
    /// Applies a controlword (from the RPDO or an SDO write of 0x6040); returns the new state.
    cia402::State applyControlword(quint16 controlword);
    /// A drive fault (over-current, following error...): -> Fault reaction active.
    void raiseFault();
    /// The fault reaction (braking) is over: -> Fault.
    void completeFaultReaction();

    cia402::State state() const { return m_state; }
    /// The statusword of the state, with Remote (bit 9) and Voltage enabled (bit 4) set.
    quint16 statusword() const;
    /// The drive applies torque: Operation enabled, or braking in Quick stop active.
    bool powerApplied() const;

private:
    cia402::State m_state = cia402::State::NotReadyToSwitchOn;
    quint16 m_lastControlword = 0;
};

} // namespace learnid
