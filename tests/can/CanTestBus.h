#pragma once

#include "can/CanLink.h"
#include "can/MemoryCanBus.h"
#include "can/MemoryCanDevice.h"

#include <QCanBusFrame>
#include <QList>
#include <QTest>
#include <memory>

namespace learnid::test {

/// A memory bus with a connected master device and slave device, each behind a CanLink,
/// and a record of every frame on the wire.
struct CanTestBus
{
    MemoryCanBus bus;
    MemoryCanDevice *master = bus.createDevice(QStringLiteral("master"));
    MemoryCanDevice *slave = bus.createDevice(QStringLiteral("slave"));
    CanLink masterLink{master};
    CanLink slaveLink{slave};
    QList<QCanBusFrame> wire;

    CanTestBus()
    {
        QObject::connect(&bus, &MemoryCanBus::frameTransmitted,
                         [this](const QCanBusFrame &f) { wire.append(f); });
        master->connectDevice();
        slave->connectDevice();
    }

    /// The frames on the wire with this identifier.
    QList<QCanBusFrame> framesWithId(quint32 id) const
    {
        QList<QCanBusFrame> result;
        for (const QCanBusFrame &f : wire) {
            if (f.frameId() == id)
                result.append(f);
        }
        return result;
    }
};

/// 8 data bytes from hex ("4300100012345678").
inline QByteArray bytes(const char *hex)
{
    return QByteArray::fromHex(hex);
}

} // namespace learnid::test
