#include "cansim/StoredParameterSet.h"

#include "can/JointIdentity.h"
#include "can/ManufacturerObjects.h"
#include "can/PayloadObjects.h"
#include "cansim/DriveDictionary.h"

namespace learnid {

namespace ob = objects;

void StoredParameterSet::store(const ObjectDictionary &dictionary)
{
    m_raw.clear();
    for (quint8 sub = ob::gainKp; sub <= ob::gainLambda; ++sub)
        m_raw[key(ob::gains, sub)] = dictionary.bytes(ob::gains, sub);
    const int count = int(dictionary.value(ob::identifiedParameters, 0));
    for (int sub = 0; sub <= count; ++sub) {
        m_raw[key(ob::identifiedParameters, quint8(sub))] =
            dictionary.bytes(ob::identifiedParameters, quint8(sub));
    }
    m_raw[key(ob::torqueLimit, 0)] = dictionary.bytes(ob::torqueLimit, 0);
    for (const quint8 sub : {ob::jointIdentityRobot, ob::jointIdentityJoint})
        m_raw[key(ob::jointIdentity, sub)] = dictionary.bytes(ob::jointIdentity, sub);
    for (quint8 sub = ob::payloadJoint; sub <= ob::payloadHighestSubIndex; ++sub)
        m_raw[key(ob::payload, sub)] = dictionary.bytes(ob::payload, sub);
}

int StoredParameterSet::payloadJoint() const
{
    const auto joint = m_raw.find(key(ob::payload, ob::payloadJoint));
    return joint == m_raw.end() ? 0 : quint8(joint->second.at(0));
}

Eigen::VectorXd StoredParameterSet::payloadParameters() const
{
    if (isEmpty())
        return {};
    Eigen::VectorXd body(ob::payloadParameterCount);
    for (int i = 0; i < body.size(); ++i) {
        body[i] =
            canopen::decodeValue(canopen::DataType::Real32,
                                 m_raw.at(key(ob::payload, quint8(ob::payloadFirstParameter + i))));
    }
    return body;
}

Eigen::VectorXd StoredParameterSet::parameters() const
{
    const auto count = m_raw.find(key(ob::identifiedParameters, 0));
    if (count == m_raw.end())
        return {};
    Eigen::VectorXd phi(quint8(count->second.at(0)));
    for (int i = 0; i < phi.size(); ++i) {
        phi[i] = canopen::decodeValue(canopen::DataType::Real32,
                                      m_raw.at(key(ob::identifiedParameters, quint8(i + 1))));
    }
    return phi;
}

void StoredParameterSet::restore(ObjectDictionary &dictionary,
                                 const DriveNodeSettings &settings) const
{
    if (!isEmpty()) {
        for (const auto &[k, raw] : m_raw)
            dictionary.setBytes(quint16(k >> 8), quint8(k & 0xFF), raw);
        return;
    }
    // Nothing stored: every manufacturer object back to its power-on default.
    for (const ob::ObjectDescription &o : ob::manufacturerObjects(manufacturerDefaults(settings)))
        dictionary.setValue(o.index, o.subIndex, o.defaultValue);
    dictionary.setValue(ob::jointIdentity, ob::jointIdentityRobot, settings.robotIdentity);
    dictionary.setValue(ob::jointIdentity, ob::jointIdentityJoint, settings.commissionedJoint);
    for (quint8 sub = ob::payloadJoint; sub <= ob::payloadHighestSubIndex; ++sub)
        dictionary.setValue(ob::payload, sub, 0);
}

} // namespace learnid
