#include "canrobot/CandumpReplayDevice.h"

#include "can/CanOpen.h"

namespace learnid {

bool isMasterFrame(const QCanBusFrame &frame)
{
    if (frame.hasExtendedFrameFormat() || frame.frameType() != QCanBusFrame::DataFrame)
        return false;
    const quint32 id = frame.frameId();
    const int function = canopen::functionCodeOfCobId(id);
    const bool rpdo = function == 4 || function == 6 || function == 8 || function == 10;
    return id == canopen::nmtCobId || (rpdo && canopen::nodeOfCobId(id) != 0) ||
           (id > canopen::sdoRxCobId(0) && id <= canopen::sdoRxCobId(canopen::maxNodeId));
}

CandumpReplayDevice::CandumpReplayDevice(QList<CandumpEntry> entries, QObject *parent)
    : QCanBusDevice(parent)
    , m_entries(std::move(entries))
{}

bool CandumpReplayDevice::open()
{
    setState(ConnectedState);
    schedulePlay();
    return true;
}

void CandumpReplayDevice::close()
{
    setState(UnconnectedState);
}

bool CandumpReplayDevice::writeFrame(const QCanBusFrame &frame)
{
    if (state() != ConnectedState) {
        setError(tr("Cannot write a frame: the replay is not connected."), WriteError);
        return false;
    }
    if (atEnd()) {
        fail(tr("The master wrote %1 after the end of the log.").arg(frame.toString()));
        return false;
    }
    const CandumpEntry &expected = m_entries.at(m_position);
    if (!isMasterFrame(expected.frame) || expected.frame.frameId() != frame.frameId() ||
        expected.frame.payload() != frame.payload()) {
        fail(tr("The master wrote %1 where the log holds %2 (log frame %3): the replayed trial "
                "differs from the recorded one.")
                 .arg(frame.toString(), expected.frame.toString())
                 .arg(m_position + 1));
        return false;
    }
    ++m_position;
    emit framesWritten(1);
    schedulePlay();
    return true;
}

QString CandumpReplayDevice::interpretErrorFrame(const QCanBusFrame &)
{
    return {};
}

QCanBusDeviceInfo CandumpReplayDevice::deviceInfo() const
{
    return createDeviceInfo(QStringLiteral("candump"), QStringLiteral("replay"), false, false);
}

void CandumpReplayDevice::schedulePlay()
{
    if (m_playScheduled)
        return;
    m_playScheduled = true;
    // Frames reach the master through the event loop, never inside its writeFrame() call.
    QMetaObject::invokeMethod(this, &CandumpReplayDevice::play, Qt::QueuedConnection);
}

void CandumpReplayDevice::play()
{
    m_playScheduled = false;
    if (state() != ConnectedState)
        return;
    QList<QCanBusFrame> frames;
    while (!atEnd() && !isMasterFrame(m_entries.at(m_position).frame))
        frames.append(m_entries.at(m_position++).frame);
    if (!frames.isEmpty())
        enqueueReceivedFrames(frames);
}

void CandumpReplayDevice::fail(const QString &reason)
{
    setError(reason, ReadError);
    setState(UnconnectedState);
}

} // namespace learnid
