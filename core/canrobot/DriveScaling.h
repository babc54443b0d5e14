#pragma once

#include <QtGlobal>

namespace learnid {

/// The integer units of one drive (docs/can-protocol.md): positions in encoder increments,
/// rad = inc * 2 pi * revolutions / increments; torques in per mille of the rated torque,
/// N m = permille * ratedTorque [mN m] / 1e6.
struct DriveScaling
{
    quint32 increments = 1 << 24; ///< 0x608F:1 position encoder resolution [inc]
    quint32 revolutions = 1;      ///< 0x608F:2 motor revolutions
    quint32 ratedTorque = 1000;   ///< 0x6076 [mN m]

    bool isValid() const { return increments > 0 && revolutions > 0 && ratedTorque > 0; }
    double radPerIncrement() const;
    double newtonMetrePerPermille() const { return double(ratedTorque) * 1e-6; }

    double toRad(double increments) const { return increments * radPerIncrement(); }
    /// Rounded to the nearest increment, saturated to INTEGER32.
    qint32 toIncrements(double rad) const;
    double toNewtonMetre(double permille) const { return permille * newtonMetrePerPermille(); }
    /// Rounded to the nearest per mille, saturated to INTEGER16.
    qint16 toPermille(double newtonMetre) const;
};

} // namespace learnid
