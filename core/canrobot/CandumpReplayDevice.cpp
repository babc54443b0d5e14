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

namespace {

bool isNmt(const QCanBusFrame &frame, quint8 command)
{
    return frame.frameType() == QCanBusFrame::DataFrame && !frame.hasExtendedFrameFormat() &&
           frame.frameId() == canopen::nmtCobId && frame.payload().size() >= 2 &&
           quint8(frame.payload().at(0)) == command && frame.payload().at(1) == 0;
}

constexpr quint8 nmtStart = 0x01;
constexpr quint8 nmtPreOperational = 0x80;

} // namespace

QList<QList<CandumpEntry>> recordedTrials(const QList<CandumpEntry> &entries)
{
    QList<QList<CandumpEntry>> trials;
    qsizetype open = -1;
    bool started = false;
    for (qsizetype i = 0; i < entries.size(); ++i) {
        const QCanBusFrame &f = entries.at(i).frame;
        if (isNmt(f, nmtPreOperational)) {
            if (started) {
                trials.append(entries.mid(open, i - open + 1));
                started = false;
                open = -1;
            } else {
                open = i; // the latest one before a start opens the trial
            }
        } else if (isNmt(f, nmtStart) && open >= 0) {
            started = true;
        }
    }
    return trials;
}

QList<CandumpEntry> replayEntries(const QList<CandumpEntry> &entries, int *trials)
{
    const QList<QList<CandumpEntry>> found = recordedTrials(entries);
    if (found.size() <= 1) {
        *trials = 1;
        return entries;
    }
    *trials = int(found.size());
    QList<CandumpEntry> played;
    for (const QList<CandumpEntry> &t : found)
        played += t;
    return played;
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
    // The master's next frame in the log. A recording of the bus (candump of a session) may
    // hold robot frames before it that the master had not handled yet when it wrote it (two
    // processes answering the same SYNC): those stay to be played after it.
    qsizetype next = m_position;
    while (next < m_entries.size() && !isMasterFrame(m_entries.at(next).frame))
        ++next;
    const qsizetype shown = next < m_entries.size() ? next : m_position;
    const QCanBusFrame &expected = m_entries.at(shown).frame;
    if (next == m_entries.size() || expected.frameId() != frame.frameId() ||
        expected.payload() != frame.payload()) {
        fail(tr("The master wrote %1 where the log holds %2 (log frame %3): the replayed trial "
                "differs from the recorded one.")
                 .arg(frame.toString(), expected.toString())
                 .arg(shown + 1 + m_matchedAhead));
        return false;
    }
    if (next == m_position) {
        ++m_position;
    } else {
        m_entries.remove(next);
        ++m_matchedAhead;
    }
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
