#pragma once

#include "can/CandumpLog.h"

#include <QCanBusDevice>

namespace learnid {

/// Whether the master wrote this frame (NMT, RPDO, SDO request), judged by its COB-ID in the
/// pre-defined connection set; everything else (SYNC, TPDO, EMCY, SDO answer, heartbeat) came
/// from the robot side.
bool isMasterFrame(const QCanBusFrame &frame);

/// A QCanBusDevice that plays back the robot side of a recorded candump log in lock step with
/// the master: the robot's frames up to the master's next logged frame are received, then the
/// device waits until the master writes that frame (which must be equal in identifier and
/// payload) before it plays on. A master that runs the same plan on the recorded answers thus
/// sees the same trial again, whatever the speed; a master that sends something else ends the
/// replay with a ReadError naming the log line, and the device goes unconnected.
class CandumpReplayDevice : public QCanBusDevice
{
    Q_OBJECT

public:
    explicit CandumpReplayDevice(QList<CandumpEntry> entries, QObject *parent = nullptr);

    bool writeFrame(const QCanBusFrame &frame) override;
    QString interpretErrorFrame(const QCanBusFrame &errorFrame) override;
    QCanBusDeviceInfo deviceInfo() const override;

    /// Log entries consumed so far (played or matched).
    int position() const { return m_position; }
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
    bool m_playScheduled = false;
};

} // namespace learnid
