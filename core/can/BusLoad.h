#pragma once

#include <QCanBusFrame>
#include <QList>
#include <QString>

namespace learnid {

/// The cyclic traffic of a trial (docs/can-protocol.md §8.5): per sample one SYNC, and per
/// joint an RPDO (target position, torque offset, controlword) and a TPDO (position, torque,
/// statusword).
struct BusLoadConfig
{
    int joints = 2;
    double sampleRate = 500.0;       ///< SYNC rate [Hz]
    int framesPerJointPerSample = 2; ///< RPDO + TPDO
    int payloadBytes = 8;            ///< data bytes of each PDO frame (0..8)
    bool sync = true;                ///< one SYNC frame per sample
    int syncPayloadBytes = 1;        ///< its counter (0x1019 > 0, docs/can-protocol.md §4.3)
    double bitrate = 1'000'000.0;    ///< [bit/s]
};

struct BusLoad
{
    double framesPerSecond = 0;
    double bitsPerSecond = 0; ///< worst case, with bit stuffing
    double percent = 0;       ///< of the bitrate

    /// "30.3 % of 1000 kbit/s (2500 frames/s)", translated.
    QString text(double bitrate) const;
};

/// Worst-case length of a classic CAN data frame with bit stuffing, including the
/// interframe space [bits] (Davis et al. 2007): standard ids 47 + 8 dlc + floor((34 + 8 dlc -
/// 1)/4), extended ids 67 + 8 dlc + floor((54 + 8 dlc - 1)/4). dlc is 0..8.
int worstCaseFrameBits(int dlc, bool extended = false);

/// The load a configuration puts on the bus. Throws learnid::Error for non-positive rates or
/// a payload outside 0..8.
BusLoad estimateBusLoad(const BusLoadConfig &config);

/// The load of recorded frames over a window of seconds (e.g. a candump log of a trial).
BusLoad measureBusLoad(const QList<QCanBusFrame> &frames, double seconds, double bitrate);

} // namespace learnid
