#pragma once

#include <QCanBusFrame>
#include <QString>

namespace learnid {

/// What an error frame (CAN_ERR_FLAG, how SocketCAN reports the controller's and the bus's
/// errors, linux/can/error.h) means for a trial.
struct CanBusErrorReport
{
    bool fatal = false; ///< the bus can no longer be trusted: a running trial stops
    QString what;       ///< the error in words, e.g. "bus off", "controller error passive (rx)"
};

/// Classifies an error frame: bus off, error passive, a buffer overflow (frames were lost), a
/// transmit timeout, a protocol violation, a transceiver error, no acknowledgement or a bus
/// error are fatal; the warning level, lost arbitration, back to error active and a restarted
/// controller are not. A frame that is not an error frame gives an empty report.
CanBusErrorReport classifyErrorFrame(const QCanBusFrame &frame);

/// The kernel's state of a CAN controller (IFLA_CAN_STATE, linux/can/netlink.h).
enum class CanControllerState { Unknown, ErrorActive, ErrorWarning, ErrorPassive, BusOff, Stopped };

/// "error active", "error passive", "bus off", ...
QString canControllerStateName(CanControllerState state);

/// A state in which a trial must not run or go on: error passive, bus off, stopped.
bool isFatalControllerState(CanControllerState state);

} // namespace learnid
