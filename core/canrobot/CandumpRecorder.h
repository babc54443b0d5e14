#pragma once

#include "can/CandumpLog.h"

#include <QDateTime>
#include <QElapsedTimer>
#include <QObject>

namespace learnid {

class CanLink;

/// Records the frames of a link in both directions while started, each stamped with the wall
/// clock when the master saw or wrote it, for a candump log (can-utils "candump -l" format).
class CandumpRecorder : public QObject
{
    Q_OBJECT

public:
    CandumpRecorder(CanLink *link, QString interface, QObject *parent = nullptr);

    void start();
    void stop();
    bool isRecording() const { return m_recording; }
    const QList<CandumpEntry> &entries() const { return m_entries; }
    /// Writes the entries; returns the error (file and reason) or empty.
    QString save(const QString &fileName) const;

private:
    void add(const QCanBusFrame &frame);

    QString m_interface;
    bool m_recording = false;
    qint64 m_startUs = 0;
    QElapsedTimer m_clock;
    QList<CandumpEntry> m_entries;
};

} // namespace learnid
