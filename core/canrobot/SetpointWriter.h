#pragma once

#include <QList>
#include <QString>
#include <QVector>

namespace learnid {

class CanLink;

/// Writes RPDO1 (objects::trialRpdoMapping(): target position, torque offset, controlword) to
/// the trial's nodes, and remembers the controlword each node got last.
class SetpointWriter
{
public:
    void reset(CanLink *link, const QList<int> &nodes);

    /// RPDO1 of joint; false (see error()) when the device refused the frame.
    bool write(int joint, qint32 targetIncrements, qint16 torquePermille, quint16 controlword);
    /// The controlword that walks a drive reporting statusword towards Operation enabled: the
    /// CiA 402 command, and for Fault a fault reset on a rising edge of bit 7 (0 first when the
    /// last controlword already had it set). Drives leaving a state on their own get the last
    /// controlword again.
    quint16 enableControlword(int joint, quint16 statusword) const;
    quint16 lastControlword(int joint) const { return m_last.value(joint); }
    QString error() const { return m_error; }

private:
    CanLink *m_link = nullptr;
    QList<int> m_nodes;
    QVector<quint16> m_last;
    QString m_error;
};

} // namespace learnid
