// Fuzz target: SDO responses through SdoClient (core/can SdoClient, SdoProtocol), as a drive on
// a memory bus would send them. Input: one byte choosing the transfers, then frames, each a
// header byte (bits 0-3 data length, cut to 8; bit 4 node 6 instead of 5; bit 5 the COB-ID of
// the next byte's node; bit 6 extended format; bit 7 remote request) and its data bytes.
// A frame is put on the bus after the client has sent what the previous one asked for. Bad
// answers must end a transfer with an error (and an abort on the bus), never a crash; every
// transfer must be finished once the input ends and the rest are cancelled.

#include "FuzzSupport.h"

#include "can/CanLink.h"
#include "can/CanOpen.h"
#include "can/MemoryCanBus.h"
#include "can/MemoryCanDevice.h"
#include "can/SdoClient.h"

#include <QCanBusFrame>

using namespace learnid;

namespace {

constexpr quint8 node = 5;
constexpr quint8 otherNode = 6;

// Queued deliveries and queued transfer starts may post further events; a few rounds empty them.
void settle()
{
    for (int i = 0; i < 4; ++i)
        QCoreApplication::processEvents();
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz::application();
    fuzz::InputReader in(data, size);

    MemoryCanBus bus;
    MemoryCanDevice *master = bus.createDevice(QStringLiteral("master"));
    MemoryCanDevice *drive = bus.createDevice(QStringLiteral("drive"));
    master->connectDevice();
    drive->connectDevice();
    CanLink link(master);
    SdoClient client(&link);
    client.setTimeout(600000); // the input decides when a transfer ends, not the clock

    int started = 0;
    int finished = 0;
    QObject::connect(&client, &SdoClient::finished, [&](const SdoResult &r) {
        ++finished;
        if (!r.ok() && r.upload && !r.data.isEmpty())
            fuzz::fuzzFailure("a failed upload returned data", r.errorMessage);
        if (r.ok() && !r.upload && r.data.isEmpty())
            fuzz::fuzzFailure("an empty download succeeded");
    });

    const quint8 choice = in.byte();
    if (choice & 0x01) {
        client.upload(node, 0x2000, 1);
    } else {
        QByteArray written(1 + ((choice >> 1) & 0x1F), '\0');
        for (int i = 0; i < written.size(); ++i)
            written[i] = char(0x11 * (i + 1));
        client.download(node, 0x2000, 1, written);
    }
    ++started;
    if (choice & 0x40) {
        client.upload(node, 0x1008, 0); // queued behind the first
        ++started;
    }
    if (choice & 0x80) {
        client.download(otherNode, 0x6040, 0, QByteArray::fromHex("0f00"));
        ++started;
    }
    settle();

    while (!in.atEnd()) {
        const quint8 header = in.byte();
        quint8 from = (header & 0x10) ? otherNode : node;
        if (header & 0x20)
            from = quint8(in.byte() & 0x7F);
        QCanBusFrame frame(canopen::sdoTxCobId(from), in.take(qMin(header & 0x0F, 8)));
        if (header & 0x40)
            frame.setExtendedFrameFormat(true);
        if (header & 0x80)
            frame.setFrameType(QCanBusFrame::RemoteRequestFrame);
        drive->writeFrame(frame);
        settle();
    }

    client.cancelAll(QStringLiteral("the fuzz input ended"));
    settle();
    if (finished != started) {
        fuzz::fuzzFailure("transfers were lost",
                          QStringLiteral("%1 started, %2 finished").arg(started).arg(finished));
    }
    if (client.pendingTransfers(node) != 0 || client.pendingTransfers(otherNode) != 0)
        fuzz::fuzzFailure("transfers pending after cancelAll()");
    return 0;
}
