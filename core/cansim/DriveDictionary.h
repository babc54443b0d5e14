#pragma once

#include "can/ManufacturerObjects.h"
#include "can/ObjectDictionary.h"
#include "cansim/DriveSettings.h"

#include <QPair>

namespace learnid {

/// Fills the object dictionary of a simulated CiA 402 drive with every object of
/// docs/can-protocol.md, its defaults from settings and its write checks (value ranges, the
/// "save" signature, PDO mapping rules). Throws learnid::Error when settings do not fit the
/// objects' types.
void addDriveObjects(ObjectDictionary &dictionary, const DriveNodeSettings &settings);

/// The manufacturer objects' power-on defaults of a drive with these settings.
objects::ManufacturerDefaults manufacturerDefaults(const DriveNodeSettings &settings);

/// Resets the communication objects (0x1017, PDO communication and mapping) to their defaults,
/// as NMT reset communication does.
void resetCommunicationObjects(ObjectDictionary &dictionary, quint8 node);

/// Whether PDO 1 of the direction is valid (COB-ID bit 31 clear) with the trial mapping of
/// objects::trialRpdoMapping() / trialTpdoMapping() (3 entries).
bool trialPdoActive(const ObjectDictionary &dictionary, bool receive);

/// The interpolation period value and exponent (0x60C2:1, :2) of a period [us]: the largest
/// exponent of -3..-6 giving a whole value up to 255; (2, -3) for 2000 us.
QPair<quint8, qint8> interpolationPeriodFor(quint32 periodUs);

/// The interpolation period 0x60C2 in seconds.
double interpolationPeriod(const ObjectDictionary &dictionary);

} // namespace learnid
