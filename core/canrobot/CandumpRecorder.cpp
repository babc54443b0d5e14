#include "canrobot/CandumpRecorder.h"

#include "can/CanLink.h"
#include "model/Error.h"

namespace learnid {

CandumpRecorder::CandumpRecorder(CanLink *link, QString interface, QObject *parent)
    : QObject(parent)
    , m_interface(std::move(interface))
{
    connect(link, &CanLink::frameReceived, this, &CandumpRecorder::add);
    connect(link, &CanLink::frameSent, this, &CandumpRecorder::add);
}

void CandumpRecorder::start()
{
    m_entries.clear();
    m_startUs = QDateTime::currentMSecsSinceEpoch() * 1000;
    m_clock.start();
    m_recording = true;
}

void CandumpRecorder::stop()
{
    m_recording = false;
}

QString CandumpRecorder::save(const QString &fileName) const
{
    try {
        candump::writeFile(fileName, m_entries);
    } catch (const Error &e) {
        return e.message();
    }
    return {};
}

void CandumpRecorder::add(const QCanBusFrame &frame)
{
    if (!m_recording)
        return;
    QCanBusFrame stamped = frame;
    stamped.setTimeStamp(
        QCanBusFrame::TimeStamp::fromMicroSeconds(m_startUs + m_clock.nsecsElapsed() / 1000));
    m_entries.append({m_interface, stamped});
}

} // namespace learnid
