#include "robot-sim/SimProcess.h"

#include "can/CanLink.h"
#include "can/SocketCanInterface.h"
#include "can/TcpLowLatency.h"
#include "cansim/CanArmSimulator.h"
#include "cansim/ScenarioCanArm.h"
#include "io/AtomicFile.h"
#include "io/ScenarioFile.h"
#include "model/Error.h"
#include "model/ModelFactory.h"
#include "robot-sim/StopRequests.h"

#include <QCanBus>
#include <QCoreApplication>

namespace learnid::robotsim {

SimProcess::SimProcess(SimOptions options, QTextStream &out, QTextStream &err)
    : m_options(std::move(options))
    , m_out(out)
    , m_err(err)
{
    m_connectTimer.setSingleShot(true);
    m_connectTimer.setTimerType(Qt::PreciseTimer);
    connect(&m_connectTimer, &QTimer::timeout, this, &SimProcess::onConnectTimeout);
    connect(&m_noDelayTimer, &QTimer::timeout, this, [] { setNoDelayOnAllTcpSockets(); });
}

SimProcess::~SimProcess()
{
    // The simulator and the link refer to the device: they go first.
    m_simulator.reset();
    m_link.reset();
    m_device.reset();
}

int SimProcess::run()
{
    if (const int code = setUp(); code != ExitOk)
        return code;
    StopRequests stop;
    connect(&stop, &StopRequests::stopRequested, this, [this](const QString &reason) {
        m_err << tr("learnid-robot-sim: stopping (%1)").arg(reason) << Qt::endl;
        finish(ExitOk);
    });
    connect(&stop, &StopRequests::lineReceived, this, &SimProcess::command);
    if (!m_device->connectDevice()) {
        finish(ExitFailure,
               tr("cannot connect the CAN interface %1 with plugin %2: %3")
                   .arg(m_options.interface, m_options.plugin, m_device->errorString()));
    } else if (m_device->state() == QCanBusDevice::ConnectedState) {
        onStateChanged(QCanBusDevice::ConnectedState);
    } else {
        m_connectTimer.start(connectTimeoutMs);
    }
    const int code = m_loop.exec();
    if (m_simulator)
        m_simulator->stop();
    closeCanDevice(m_device.get());
    return code;
}

int SimProcess::setUp()
{
    CanArmSettings settings;
    try {
        Scenario scenario;
        if (!m_options.scenarioPath.isEmpty())
            scenario = readScenarioFile(m_options.scenarioPath);
        validateScenario(scenario);
        const auto model = makeRobotModel(scenario.model, scenario.urdf);
        QList<int> nodes = m_options.nodes;
        if (nodes.isEmpty()) { // --nodes not given: joint j is node j
            for (int j = 1; j <= model->dof(); ++j)
                nodes << j;
        }
        settings = canArmSettings(scenario, model, nodes);
        if (m_options.uncommissioned)
            settings.robotIdentity = 0;
        if (m_options.setPointTimeoutSyncs > 0)
            settings.setPointTimeoutSyncs = m_options.setPointTimeoutSyncs;
    } catch (const Error &e) {
        m_err << tr("learnid-robot-sim: error: %1").arg(e.message()) << Qt::endl;
        return ExitUsage;
    }
    QString error;
    m_device.reset(
        QCanBus::instance()->createDevice(m_options.plugin, m_options.interface, &error));
    if (!m_device) {
        m_err << tr("learnid-robot-sim: error: cannot create the CAN device %1 with plugin %2: %3")
                     .arg(m_options.interface, m_options.plugin, error)
              << Qt::endl;
        return ExitFailure;
    }
    prepareCanDevice(m_device.get(), m_options.plugin); // socketcan: the bitrate is ip link's
    m_link = std::make_unique<CanLink>(m_device.get());
    try {
        m_simulator = std::make_unique<CanArmSimulator>(m_link.get(), settings, m_options.faults);
    } catch (const Error &e) {
        m_err << tr("learnid-robot-sim: error: %1").arg(e.message()) << Qt::endl;
        return ExitUsage;
    }
    if (m_options.payloadOff && !m_simulator->setPayloadMounted(false)) {
        m_err << tr("learnid-robot-sim: error: --payload-off: the scenario has no payload section")
              << Qt::endl;
        return ExitUsage;
    }
    if (!m_options.statePath.isEmpty()) {
        try {
            writeFileAtomically(m_options.statePath, simulatorStateJson(*m_simulator));
        } catch (const Error &e) {
            m_err << tr("learnid-robot-sim: error: --state: %1").arg(e.message()) << Qt::endl;
            return ExitUsage;
        }
        connect(m_simulator.get(), &CanArmSimulator::parametersStored, this,
                &SimProcess::writeState);
    }
    connect(m_simulator.get(), &CanArmSimulator::silenced, this, [this] {
        m_err << tr("learnid-robot-sim: silent after %1 frames (injected fault)")
                     .arg(m_simulator->framesSent())
              << Qt::endl;
    });
    connect(m_device.get(), &QCanBusDevice::stateChanged, this, &SimProcess::onStateChanged);
    connect(m_device.get(), &QCanBusDevice::errorOccurred, this, &SimProcess::onDeviceError);
    return ExitOk;
}

void SimProcess::onStateChanged(QCanBusDevice::CanBusDeviceState state)
{
    if (state == QCanBusDevice::ConnectedState && !m_connected) {
        m_connected = true;
        m_connectTimer.stop();
        // virtualcan is TCP: without TCP_NODELAY frames of consecutive SYNC periods would be
        // held back and arrive at once (see TcpLowLatency.h). The master connects later.
        setNoDelayOnAllTcpSockets();
        m_noDelayTimer.start(50);
        m_simulator->start();
        m_out << "ready" << Qt::endl;
    } else if (state == QCanBusDevice::UnconnectedState && m_connected) {
        finish(ExitFailure, tr("the CAN device %1 disconnected").arg(m_options.interface));
    }
}

void SimProcess::onDeviceError(QCanBusDevice::CanBusError error)
{
    if (error == QCanBusDevice::NoError)
        return;
    if (!m_connected) {
        finish(ExitFailure,
               tr("cannot connect the CAN interface %1 with plugin %2: %3")
                   .arg(m_options.interface, m_options.plugin, m_device->errorString()));
        return;
    }
    m_err << tr("learnid-robot-sim: CAN device error: %1").arg(m_device->errorString()) << Qt::endl;
}

void SimProcess::onConnectTimeout()
{
    if (!m_connected)
        finish(ExitFailure, tr("the CAN interface %1 with plugin %2 did not connect within %3 s")
                                .arg(m_options.interface, m_options.plugin)
                                .arg(connectTimeoutMs / 1000));
}

void SimProcess::writeState()
{
    try {
        writeFileAtomically(m_options.statePath, simulatorStateJson(*m_simulator));
    } catch (const Error &e) {
        m_err << tr("learnid-robot-sim: error: --state: %1").arg(e.message()) << Qt::endl;
    }
}

void SimProcess::finish(int code, const QString &error)
{
    if (m_finished)
        return;
    m_finished = true;
    if (!error.isEmpty())
        m_err << tr("learnid-robot-sim: error: %1").arg(error) << Qt::endl;
    if (m_simulator)
        m_simulator->stop();
    // Queued: finish() may run before the loop has started.
    QMetaObject::invokeMethod(
        &m_loop, [this, code] { m_loop.exit(code); }, Qt::QueuedConnection);
}

void SimProcess::command(const QString &line)
{
    // A technician's hands on the arm: the payload mounted or taken off between trials.
    const bool mount = line == QLatin1String("mount");
    if (!mount && line != QLatin1String("unmount")) {
        m_err << tr("learnid-robot-sim: unknown command '%1' on stdin (mount, unmount)").arg(line)
              << Qt::endl;
        return;
    }
    if (!m_simulator || !m_simulator->setPayloadMounted(mount)) {
        m_err << tr("learnid-robot-sim: %1: the scenario has no payload section").arg(line)
              << Qt::endl;
        return;
    }
    m_out << (mount ? "payload mounted" : "payload off") << Qt::endl;
}

} // namespace learnid::robotsim
