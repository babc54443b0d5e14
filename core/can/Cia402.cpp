#include "can/Cia402.h"

#include <QCoreApplication>

namespace learnid::cia402 {

State stateFromStatusword(quint16 sw)
{
    // The patterns of CiA 402-2 table 30: x = bits that do not matter for the state.
    if ((sw & 0x4F) == 0x00)
        return State::NotReadyToSwitchOn; // xxxx xxxx x0xx 0000
    if ((sw & 0x4F) == 0x40)
        return State::SwitchOnDisabled; // xxxx xxxx x1xx 0000
    if ((sw & 0x6F) == 0x21)
        return State::ReadyToSwitchOn; // xxxx xxxx x01x 0001
    if ((sw & 0x6F) == 0x23)
        return State::SwitchedOn; // xxxx xxxx x01x 0011
    if ((sw & 0x6F) == 0x27)
        return State::OperationEnabled; // xxxx xxxx x01x 0111
    if ((sw & 0x6F) == 0x07)
        return State::QuickStopActive; // xxxx xxxx x00x 0111
    if ((sw & 0x4F) == 0x0F)
        return State::FaultReactionActive; // xxxx xxxx x0xx 1111
    if ((sw & 0x4F) == 0x08)
        return State::Fault; // xxxx xxxx x0xx 1000
    return State::Unknown;
}

QString stateName(State state)
{
    const char *text = "";
    switch (state) {
    case State::NotReadyToSwitchOn:
        text = QT_TRANSLATE_NOOP("Cia402", "Not ready to switch on");
        break;
    case State::SwitchOnDisabled:
        text = QT_TRANSLATE_NOOP("Cia402", "Switch on disabled");
        break;
    case State::ReadyToSwitchOn:
        text = QT_TRANSLATE_NOOP("Cia402", "Ready to switch on");
        break;
    case State::SwitchedOn:
        text = QT_TRANSLATE_NOOP("Cia402", "Switched on");
        break;
    case State::OperationEnabled:
        text = QT_TRANSLATE_NOOP("Cia402", "Operation enabled");
        break;
    case State::QuickStopActive:
        text = QT_TRANSLATE_NOOP("Cia402", "Quick stop active");
        break;
    case State::FaultReactionActive:
        text = QT_TRANSLATE_NOOP("Cia402", "Fault reaction active");
        break;
    case State::Fault:
        text = QT_TRANSLATE_NOOP("Cia402", "Fault");
        break;
    case State::Unknown:
        text = QT_TRANSLATE_NOOP("Cia402", "Unknown drive state");
        break;
    }
    return QCoreApplication::translate("Cia402", text);
}

quint16 controlword(Command command)
{
    switch (command) {
    case Command::Shutdown:
        return 0x0006;
    case Command::SwitchOn:
    case Command::DisableOperation:
        return 0x0007;
    case Command::EnableOperation:
        return 0x000F;
    case Command::DisableVoltage:
        return 0x0000;
    case Command::QuickStop:
        return 0x0002;
    case Command::FaultReset:
        return controlFaultReset;
    }
    return 0;
}

std::optional<Command> nextCommandTowardsOperationEnabled(State state)
{
    switch (state) {
    case State::SwitchOnDisabled:
        return Command::Shutdown;
    case State::ReadyToSwitchOn:
        return Command::SwitchOn;
    case State::SwitchedOn:
        return Command::EnableOperation;
    case State::QuickStopActive:
        return Command::DisableVoltage;
    case State::Fault:
        return Command::FaultReset;
    case State::OperationEnabled:
    case State::NotReadyToSwitchOn:
    case State::FaultReactionActive:
    case State::Unknown:
        break;
    }
    return std::nullopt;
}

std::optional<Command> nextCommandTowardsDisabled(State state)
{
    switch (state) {
    case State::ReadyToSwitchOn:
    case State::SwitchedOn:
    case State::OperationEnabled:
    case State::QuickStopActive:
        return Command::DisableVoltage;
    default:
        return std::nullopt;
    }
}

Command commandFromControlword(quint16 cw)
{
    // Bits: 0 switch on, 1 enable voltage, 2 quick stop (active low), 3 enable operation.
    if (!(cw & 0x0002))
        return Command::DisableVoltage; // xxxx xx0x
    if (!(cw & 0x0004))
        return Command::QuickStop; // xxxx x01x
    if (!(cw & 0x0001))
        return Command::Shutdown; // xxxx x110
    if (!(cw & 0x0008))
        return Command::SwitchOn;    // xxxx 0111 (also disable operation)
    return Command::EnableOperation; // xxxx 1111
}

} // namespace learnid::cia402
