#pragma once

#include "robot-sim/SimOptions.h"

#include <QCanBusDevice>
#include <QEventLoop>
#include <QObject>
#include <QTextStream>
#include <QTimer>
#include <memory>

namespace learnid {
class CanLink;
class CanArmSimulator;
} // namespace learnid

namespace learnid::robotsim {

/// One run of learnid-robot-sim: loads the scenario, creates the CAN device, connects with a
/// timeout, starts the simulated drives, prints "ready", and stops on a stop request or when
/// the device disconnects.
class SimProcess : public QObject
{
    Q_OBJECT

public:
    SimProcess(SimOptions options, QTextStream &out, QTextStream &err);
    ~SimProcess() override;

    /// Runs until stopped; returns the exit code.
    int run();

    /// How long the device may take to connect [ms].
    static constexpr int connectTimeoutMs = 3000;

private:
    int setUp();
    void onStateChanged(QCanBusDevice::CanBusDeviceState state);
    void onDeviceError(QCanBusDevice::CanBusError error);
    void onConnectTimeout();
    void writeState();
    /// A line on stdin: "mount" or "unmount" the payload (--payload-off).
    void command(const QString &line);
    void finish(int code, const QString &error = {});

    SimOptions m_options;
    QTextStream &m_out;
    QTextStream &m_err;
    std::unique_ptr<QCanBusDevice> m_device;
    std::unique_ptr<CanLink> m_link;
    std::unique_ptr<CanArmSimulator> m_simulator;
    QTimer m_connectTimer;
    QTimer m_noDelayTimer; ///< TCP_NODELAY on sockets of peers that connected since
    QEventLoop m_loop;
    bool m_connected = false;
    bool m_finished = false;
};

} // namespace learnid::robotsim
