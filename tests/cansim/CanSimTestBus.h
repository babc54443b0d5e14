#pragma once

#include "CanTestBus.h"
#include "can/CanOpen.h"
#include "can/ManufacturerObjects.h"
#include "can/Nmt.h"
#include "can/SdoClient.h"

#include <QCoreApplication>
#include <QSignalSpy>
#include <QTest>

namespace learnid::test {

/// The memory bus of CanTestBus with an SDO client on the master side and helpers that drive
/// the robot side as a master would, without real time: frames are delivered by flush().
struct CanSimTestBus : CanTestBus
{
    SdoClient sdo{&masterLink};

    /// Delivers every frame in flight (the bus delivers through the event loop, in rounds).
    void flush()
    {
        for (int i = 0; i < 4; ++i)
            QCoreApplication::processEvents();
    }

    SdoResult read(quint8 node, quint16 index, quint8 sub)
    {
        QSignalSpy done(&sdo, &SdoClient::finished);
        sdo.upload(node, index, sub);
        if (!done.wait(2000))
            return {};
        return done.at(0).at(0).value<SdoResult>();
    }
    double readValue(quint8 node, quint16 index, quint8 sub, canopen::DataType type)
    {
        const SdoResult r = read(node, index, sub);
        if (!r.ok())
            return qQNaN();
        return canopen::decodeValue(type, r.data);
    }
    SdoResult write(quint8 node, quint16 index, quint8 sub, canopen::DataType type, double value)
    {
        return writeRaw(node, index, sub, canopen::encodeValue(type, value));
    }
    SdoResult writeRaw(quint8 node, quint16 index, quint8 sub, const QByteArray &raw)
    {
        QSignalSpy done(&sdo, &SdoClient::finished);
        sdo.download(node, index, sub, raw);
        if (!done.wait(2000))
            return {};
        return done.at(0).at(0).value<SdoResult>();
    }

    void nmt(NmtCommand command, quint8 node)
    {
        masterLink.send(nmtCommandFrame(command, node));
        flush();
    }
    /// RPDO1 of node: target position [inc], torque offset [per mille], controlword.
    void rpdo(quint8 node, double targetInc, double offsetPermille, quint16 controlword)
    {
        masterLink.send(QCanBusFrame(
            canopen::rpdoCobId(1, node),
            objects::trialRpdoMapping().pack({targetInc, offsetPermille, double(controlword)})));
        flush();
    }

    /// The TPDO1 values (position inc, torque per mille, statusword) in frame f.
    static QList<double> tpdoValues(const QCanBusFrame &f)
    {
        return objects::trialTpdoMapping().unpack(f.payload());
    }
    /// The last TPDO1 of node on the wire, or an empty list.
    QList<double> lastTpdo(quint8 node) const
    {
        const QList<QCanBusFrame> frames = framesWithId(canopen::tpdoCobId(1, node));
        return frames.isEmpty() ? QList<double>{} : tpdoValues(frames.last());
    }
};

} // namespace learnid::test
