#include "canrobot/SetpointWriter.h"

#include "can/CanLink.h"
#include "can/CanOpen.h"
#include "can/Cia402.h"

namespace learnid {

void SetpointWriter::reset(CanLink *link, const QList<int> &nodes)
{
    m_link = link;
    m_nodes = nodes;
    m_last.fill(0, nodes.size());
    m_error.clear();
}

bool SetpointWriter::write(int joint, qint32 targetIncrements, qint16 torquePermille,
                           quint16 controlword)
{
    QByteArray payload(8, '\0');
    canopen::writeU32(payload, 0, quint32(targetIncrements));
    canopen::writeU16(payload, 4, quint16(torquePermille));
    canopen::writeU16(payload, 6, controlword);
    m_last[joint] = controlword;
    if (m_link->send(QCanBusFrame(canopen::rpdoCobId(1, quint8(m_nodes.at(joint))), payload)))
        return true;
    m_error = m_link->lastError();
    return false;
}

quint16 SetpointWriter::enableControlword(int joint, quint16 statusword) const
{
    const auto command =
        cia402::nextCommandTowardsOperationEnabled(cia402::stateFromStatusword(statusword));
    if (!command)
        return m_last.value(joint);
    if (*command == cia402::Command::FaultReset &&
        (m_last.value(joint) & cia402::controlFaultReset))
        return 0;
    return cia402::controlword(*command);
}

} // namespace learnid
