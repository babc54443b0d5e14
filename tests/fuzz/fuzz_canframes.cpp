// Fuzz target: decoding of the CANopen frames a master receives besides SDO (core/can): PDO
// payloads through PdoMapping::unpack, emergencies through decodeEmcy and EmcyConsumer,
// heartbeats through nmtStateFromByte and HeartbeatConsumer, NMT commands through nmtCommandFor.
// Input: one byte with the number of mapped objects (0..8, modulo 9), one type byte per object,
// one byte with the node the heartbeat consumer watches, then frames: two bytes of COB-ID (11
// bits, bit 15 extended format, bit 14 remote request), a length byte (cut to 8) and the data.
// Frames go through a memory bus to a CanLink as a drive would send them. A payload that unpacks
// must pack back to the same bytes, unless a value has no encoding (a NaN REAL32 is refused).

#include "FuzzSupport.h"

#include "can/CanLink.h"
#include "can/CanOpen.h"
#include "can/EmcyConsumer.h"
#include "can/HeartbeatConsumer.h"
#include "can/MemoryCanBus.h"
#include "can/MemoryCanDevice.h"
#include "can/Nmt.h"
#include "can/Pdo.h"
#include "model/Error.h"

#include <QCanBusFrame>
#include <iterator>
#include <optional>

using namespace learnid;
using canopen::DataType;

namespace {

constexpr DataType types[] = {
    DataType::Integer8,    DataType::Integer16,  DataType::Integer32, DataType::Unsigned8,
    DataType::Unsigned16,  DataType::Unsigned32, DataType::Real32,    DataType::VisibleString,
    DataType::OctetString, DataType::Domain,
};

void settle()
{
    for (int i = 0; i < 3; ++i)
        QCoreApplication::processEvents();
}

void checkPdo(const PdoMapping &mapping, const QByteArray &payload)
{
    QList<double> values;
    try {
        values = mapping.unpack(payload);
    } catch (const Error &) {
        if (payload.size() >= mapping.byteLength())
            fuzz::fuzzFailure("a payload long enough for its mapping was refused");
        return;
    }
    if (values.size() != mapping.entries().size())
        fuzz::fuzzFailure("unpack() gave a value count other than the mapping's");
    QByteArray packed;
    try {
        packed = mapping.pack(values);
    } catch (const Error &) {
        return; // e.g. a NaN REAL32: decoded, but not a value learnid would ever send
    }
    if (packed != payload.left(mapping.byteLength()))
        fuzz::fuzzFailure("a PDO payload does not pack back to its bytes",
                          canopen::hexBytes(payload));
}

void decodeDirectly(const QCanBusFrame &frame)
{
    if (const std::optional<EmcyMessage> m = decodeEmcy(frame)) {
        if (m->manufacturerData.size() != 5)
            fuzz::fuzzFailure("an EMCY message without 5 manufacturer bytes");
        if (m->text().isEmpty())
            fuzz::fuzzFailure("an EMCY message without text");
        encodeEmcy(*m);
    }
    const QByteArray p = frame.payload();
    if (!p.isEmpty()) {
        if (const std::optional<NmtState> s = nmtStateFromByte(quint8(p.at(0))))
            nmtStateName(*s);
    }
    for (quint8 node : {quint8(1), quint8(5), quint8(127)}) {
        if (const std::optional<NmtCommand> c = nmtCommandFor(frame, node))
            nmtStateAfter(*c, NmtState::Operational);
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz::application();
    fuzz::InputReader in(data, size);

    QList<PdoMappingEntry> entries;
    const int count = in.byte() % 9;
    for (int i = 0; i < count; ++i) {
        PdoMappingEntry e;
        e.index = quint16(0x6000 + i);
        e.type = types[in.byte() % std::size(types)];
        entries.append(e);
    }
    std::optional<PdoMapping> mapping;
    const bool valid = PdoMapping::validationError(entries).isEmpty();
    try {
        mapping.emplace(entries);
    } catch (const Error &) {
    }
    if (mapping.has_value() != valid)
        fuzz::fuzzFailure("PdoMapping and validationError() disagree");

    MemoryCanBus bus;
    MemoryCanDevice *master = bus.createDevice(QStringLiteral("master"));
    MemoryCanDevice *drive = bus.createDevice(QStringLiteral("drive"));
    master->connectDevice();
    drive->connectDevice();
    CanLink link(master);
    EmcyConsumer emcy(&link);
    HeartbeatConsumer heartbeat(&link);
    const quint8 watched = quint8(1 + in.byte() % 127);
    heartbeat.monitor(watched, 600000);
    heartbeat.expectBootUp(watched);

    while (!in.atEnd()) {
        const quint8 high = in.byte();
        const quint16 id = quint16((high << 8) | in.byte());
        QCanBusFrame frame(id & 0x7FF, in.take(qMin(in.byte() & 0x0F, 8)));
        if (id & 0x8000)
            frame.setExtendedFrameFormat(true);
        if (id & 0x4000)
            frame.setFrameType(QCanBusFrame::RemoteRequestFrame);
        decodeDirectly(frame);
        if (mapping)
            checkPdo(*mapping, frame.payload());
        drive->writeFrame(frame);
        settle();
    }
    if (heartbeat.isMonitoring(watched) && heartbeat.lastState(watched).has_value() &&
        !heartbeat.isAlive(watched))
        fuzz::fuzzFailure("a node that sent a heartbeat counts as lost within its timeout");
    return 0;
}
