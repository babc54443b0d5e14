#pragma once

#include <QCanBusFrame>
#include <QObject>
#include <QTimer>

namespace learnid {

/// The SYNC producer's clock and counter (CiA 301 §7.2.5): due() every period of real time
/// (a precise QTimer), and the 1-byte counter 1..240 each SYNC frame carries, wrapping.
class SyncProducer : public QObject
{
    Q_OBJECT

public:
    explicit SyncProducer(QObject *parent = nullptr);

    /// Emits due() every periodUs microseconds (rounded to whole milliseconds, at least 1).
    void start(quint32 periodUs);
    void stop();
    bool isActive() const { return m_timer.isActive(); }

    /// The counter of the next SYNC (1, 2, ... 240, 1, ...).
    quint8 advance();
    /// The counter of the last SYNC; 0 before the first.
    quint8 counter() const { return m_counter; }

    /// The SYNC frame: COB-ID 0x80, one byte, the counter.
    static QCanBusFrame frame(quint8 counter);

signals:
    void due();

private:
    QTimer m_timer;
    quint8 m_counter = 0;
};

} // namespace learnid
