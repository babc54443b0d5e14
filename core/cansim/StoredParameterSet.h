#pragma once

#include "can/ObjectDictionary.h"
#include "cansim/DriveSettings.h"

#include <Eigen/Core>
#include <map>

namespace learnid {

/// The non-volatile memory of a simulated drive: the controller objects 0x2100:1..4, the
/// identified parameters 0x2200:0..count, the torque limit 0x2300, the joint identity
/// 0x2400:1..2 and the payload 0x2500:1..11 as they were at the last
/// "save" (0x1010:1), restored by NMT reset node.
class StoredParameterSet
{
public:
    bool isEmpty() const { return m_raw.empty(); }
    /// Copies the objects from the dictionary.
    void store(const ObjectDictionary &dictionary);
    /// The identified parameters of the set (0x2200:1..count); empty when nothing was stored.
    Eigen::VectorXd parameters() const;
    /// The payload of the set: its joint (0x2500:01, 0: none or nothing stored) and its 10
    /// parameters (0x2500:02..0B; empty when nothing was stored).
    int payloadJoint() const;
    Eigen::VectorXd payloadParameters() const;
    /// Writes the set back into the dictionary, or the defaults of settings when nothing was
    /// stored (gains, torque limit, parameter count 0, no payload).
    void restore(ObjectDictionary &dictionary, const DriveNodeSettings &settings) const;

private:
    static quint32 key(quint16 index, quint8 sub) { return (quint32(index) << 8) | sub; }
    std::map<quint32, QByteArray> m_raw; ///< (index << 8 | sub) -> raw value
};

} // namespace learnid
