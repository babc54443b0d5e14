#pragma once

#include "can/CandumpLog.h"

#include <QCanBusDevice>

namespace learnid {

/// Whether the master wrote this frame (NMT, RPDO, SDO request), judged by its COB-ID in the
/// pre-defined connection set; everything else (SYNC, TPDO, EMCY, SDO answer, heartbeat) came
/// from the robot side.
bool isMasterFrame(const QCanBusFrame &frame);

/// The trials in a recording of the bus (e.g. `candump -l` of a whole session): each runs from
/// the master's NMT enter pre-operational (`000#8000`) that precedes an NMT start (`000#0100`)
/// to the next enter pre-operational after that start, both included, as the master's own
/// trial logs do (docs/can-protocol.md §8.4). What lies between trials (apply, heartbeats) and a
/// trial that never started is left out.
QList<QList<CandumpEntry>> recordedTrials(const QList<CandumpEntry> &entries);

/// What the replay plays of one log file: its trials one after another when it holds more
/// than one (a recording of a session), else the whole file (a trial log of --can-log); trials
/// is set to their number (at least 1).
QList<CandumpEntry> replayEntries(const QList<CandumpEntry> &entries, int *trials);

/// A QCanBusDevice that plays back the robot side of a recorded candump log in lock step with
/// the master: the robot's frames up to the master's next logged frame are received, then the
/// device waits until the master writes that frame (which must be equal in identifier and
/// payload) before it plays on; a master frame written before robot frames that the recording
/// placed ahead of it matches too (in a recording of the bus, both sides answer the same SYNC). A
/// master that runs the same plan on the recorded answers thus sees the same trial again, whatever
/// the speed; a master that sends something else ends the replay with a ReadError naming the log
/// line, and the device goes unconnected.
class CandumpReplayDevice : public QCanBusDevice
{
    Q_OBJECT

public:
    explicit CandumpReplayDevice(QList<CandumpEntry> entries, QObject *parent = nullptr);

    bool writeFrame(const QCanBusFrame &frame) override;
    QString interpretErrorFrame(const QCanBusFrame &errorFrame) override;
    QCanBusDeviceInfo deviceInfo() const override;

    /// Log entries consumed so far (played or matched).
    int position() const { return m_position + m_matchedAhead; }
    bool atEnd() const { return m_position >= m_entries.size(); }

protected:
    bool open() override;
    void close() override;

private:
    void schedulePlay();
    void play();
    void fail(const QString &reason);

    QList<CandumpEntry> m_entries;
    int m_position = 0;
    int m_matchedAhead = 0; ///< master frames matched ahead of robot frames (taken out)
    bool m_playScheduled = false;
};

} // namespace learnid
