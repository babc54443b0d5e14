#pragma once

#include <QMetaType>
#include <QString>
#include <QtGlobal>
#include <optional>

/// The CiA 402 drive state machine seen from the master: the state a statusword (0x6041)
/// reports and the controlword (0x6040) commands that move a drive (CiA 402-2 §8.1).
namespace learnid::cia402 {

enum class State {
    NotReadyToSwitchOn,
    SwitchOnDisabled,
    ReadyToSwitchOn,
    SwitchedOn,
    OperationEnabled,
    QuickStopActive,
    FaultReactionActive,
    Fault,
    Unknown, ///< a statusword matching no state pattern
};

enum class Command {
    Shutdown,         ///< 0x0006: transitions 2, 6, 8
    SwitchOn,         ///< 0x0007: transition 3 (same bits as DisableOperation)
    EnableOperation,  ///< 0x000F: transitions 4, 16 (and 3 + 4 from Ready to switch on)
    DisableVoltage,   ///< 0x0000: transitions 7, 9, 10, 12
    QuickStop,        ///< 0x0002: transitions 7, 10, 11
    DisableOperation, ///< 0x0007: transition 5
    FaultReset,       ///< 0x0080 (rising edge of bit 7): transition 15
};

// Statusword bits used besides the state pattern.
constexpr quint16 statusVoltageEnabled = 0x0010;
constexpr quint16 statusWarning = 0x0080;
constexpr quint16 statusRemote = 0x0200;
constexpr quint16 statusTargetReached = 0x0400;
constexpr quint16 controlFaultReset = 0x0080;

/// The state a statusword reports (bits 0-3, 5, 6).
State stateFromStatusword(quint16 statusword);
/// The state's name as CiA 402 gives it, translated ("Operation enabled").
QString stateName(State state);

/// The controlword of a command, with the mode-specific and manufacturer bits (4-6, 8-15)
/// clear. Fault reset needs a rising edge: the previous controlword must have bit 7 clear.
quint16 controlword(Command command);

/// The command that takes a drive in state one step closer to Operation enabled; nullopt when
/// it is there, or in a state it leaves on its own (Not ready to switch on, Fault reaction
/// active), or Unknown. From Quick stop active the walk goes through Switch on disabled.
std::optional<Command> nextCommandTowardsOperationEnabled(State state);
/// The command that removes power from the motor from any state (Disable voltage), or
/// nullopt when the drive is already without power (Switch on disabled, Not ready, Fault).
std::optional<Command> nextCommandTowardsDisabled(State state);

/// Slave side: the command a controlword encodes (device control, CiA 402-2 table 34).
/// A rising edge of bit 7 is recognised by the caller; here bit 7 is ignored.
Command commandFromControlword(quint16 controlword);

} // namespace learnid::cia402

Q_DECLARE_METATYPE(learnid::cia402::State)
