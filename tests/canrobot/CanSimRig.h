#pragma once
// The robot simulator (learnid_cansim) on a memory bus, as a device factory for CanRobot: the
// factory runs in the CAN thread and builds the bus, the simulator and a lock-step SYNC clock
// there. The clock waits (at most 15 ms) for the master's RPDOs before the next SYNC whenever
// the master answered the previous one, so that a loaded test machine cannot put an answer
// behind the next SYNC; simulated time is the same as in real time. The SYNC period is the
// settings' controller sample period in whole milliseconds (2 ms for the paper arm).

#include "can/CanLink.h"
#include "can/MemoryCanBus.h"
#include "can/MemoryCanDevice.h"
#include "canrobot/CanRobotOptions.h"
#include "cansim/CanArmSimulator.h"
#include "cansim/ScenarioCanArm.h"

#include <QElapsedTimer>
#include <QTimer>
#include <algorithm>
#include <cmath>
#include <memory>

namespace learnid::test {

class CanSimRig : public QObject
{
public:
    CanSimRig(MemoryCanBus *bus, const CanArmSettings &settings, const CanSimFaults &faults)
        : QObject(bus)
        , m_device(new MemoryCanDevice(QStringLiteral("sim"), bus, this))
        , m_link(m_device)
        , m_sim(&m_link, settings, faults)
        , m_nodes(int(settings.nodes.size()))
        , m_periodMs(std::max(1, int(std::lround(1000.0 * settings.controller.samplePeriod))))
    {
        m_device->connectDevice();
        connect(&m_link, &CanLink::frameReceived, this, [this](const QCanBusFrame &f) {
            if (f.frameId() > 0x200 && f.frameId() < 0x280)
                ++m_rpdos;
        });
        m_timer.setSingleShot(true);
        m_timer.setTimerType(Qt::PreciseTimer);
        connect(&m_timer, &QTimer::timeout, this, [this] {
            if (m_answering && m_rpdos < m_nodes && m_since.elapsed() < 15) {
                m_timer.start(1);
                return;
            }
            m_answering = m_rpdos >= m_nodes;
            m_rpdos = 0;
            m_sim.syncCycle();
            m_since.start();
            m_timer.start(m_periodMs);
        });
        m_sim.bootUp();
        m_since.start();
        m_timer.start(m_periodMs);
    }

    CanArmSimulator &simulator() { return m_sim; }

private:
    MemoryCanDevice *m_device;
    CanLink m_link;
    CanArmSimulator m_sim;
    int m_nodes;
    int m_periodMs;
    int m_rpdos = 0;
    bool m_answering = false;
    QTimer m_timer;
    QElapsedTimer m_since;
};

/// A factory giving CanRobot a master device on a fresh memory bus with the simulator on it.
inline CanDeviceFactory canSimFactory(const CanArmSettings &settings,
                                      const CanSimFaults &faults = {})
{
    return [settings, faults](QString *) -> QCanBusDevice * {
        auto *bus = new MemoryCanBus;
        auto *master = new MemoryCanDevice(QStringLiteral("master"), bus);
        new CanSimRig(bus, settings, faults);
        bus->setParent(master); // the master device is what CanRobot deletes
        return master;
    };
}

} // namespace learnid::test
