#include "canrobot/CanRobotWorker.h"

#include "can/CanLink.h"
#include "can/CanLogging.h"
#include "can/EmcyConsumer.h"
#include "can/HeartbeatConsumer.h"
#include "can/JointIdentity.h"
#include "can/Nmt.h"
#include "can/SdoClient.h"
#include "can/SocketCanInterface.h"
#include "canrobot/ApplySteps.h"
#include "canrobot/CanConnection.h"
#include "canrobot/CandumpRecorder.h"
#include "canrobot/JointIdentityCheck.h"
#include "canrobot/NodeConfiguration.h"
#include "canrobot/SdoSequence.h"
#include "model/Error.h"

#include <QCoreApplication>
#include <QDir>

namespace learnid {

/// The CANopen units on one open connection. Members are built in declaration order: the
/// recorder first, so that it sees each received frame before a unit answers it.
struct ConnectionUnits
{
    explicit ConnectionUnits(CanConnection *connection, const CanRobotOptions &options)
        : recorder(connection->link(), options.interface)
        , sdo(connection->link())
        , sequence(&sdo)
        , nmt(connection->link())
        , heartbeat(connection->link())
        , emcy(connection->link())
        , streamer(connection->link(), &nmt, &heartbeat, &emcy)
    {
        sdo.setTimeout(options.sdoTimeoutMs);
        streamer.setLatencyClock({[connection] { return connection->lastArrivalNs(); },
                                  [connection] {
                                      return connection->nowNs();
                                  }});
    }

    CandumpRecorder recorder;
    SdoClient sdo;
    SdoSequence sequence;
    Nmt nmt;
    HeartbeatConsumer heartbeat;
    EmcyConsumer emcy;
    TrialStreamer streamer;
};

namespace {

TrialRecord notStarted(double ts, TrialStatus status, const QString &message)
{
    TrialRecord r;
    r.samplePeriod = ts;
    r.status = status;
    r.stopCause = defaultStopCause(status);
    r.message = message;
    return r;
}

} // namespace

CanRobotWorker::CanRobotWorker(std::shared_ptr<const RobotModel> model, CanRobotOptions options,
                               CanDeviceFactory factory, QObject *parent)
    : QObject(parent)
    , m_model(std::move(model))
    , m_options(std::move(options))
{
    m_connection =
        new CanConnection(std::move(factory), connectionName(), m_options.connectTimeoutMs, this);
    connect(m_connection, &CanConnection::lost, this, &CanRobotWorker::onLost);
    if (m_options.plugin == QLatin1String("socketcan"))
        m_connection->watchSocketCanInterface(m_options.interface);
}

CanRobotWorker::~CanRobotWorker()
{
    shutdown();
}

QString CanRobotWorker::connectionName() const
{
    return QStringLiteral("%1/%2").arg(m_options.plugin, m_options.interface);
}

void CanRobotWorker::connectBus(std::function<void(const QString &)> done)
{
    const QString invalid = canRobotOptionsError(m_options);
    if (!invalid.isEmpty()) {
        QMetaObject::invokeMethod(
            this, [done, invalid] { done(invalid); }, Qt::QueuedConnection);
        return;
    }
    if (m_units && !m_connection->isConnected())
        m_units.reset(); // built on the link of a connection that was lost
    m_connection->open([this, done](const QString &error) {
        if (!error.isEmpty())
            return done(error);
        if (m_options.plugin == QLatin1String("socketcan")) {
            // The bus load at the bitrate the interface really has, where the driver tells it.
            const quint32 bitrate = readSocketCanInterface(m_options.interface).bitrate;
            if (bitrate > 0 && bitrate != m_options.bitrate) {
                m_options.bitrate = bitrate;
                const QString load = busLoadError(m_options);
                if (!load.isEmpty()) {
                    m_connection->close();
                    return done(tr("%1: %2").arg(m_options.interface, load));
                }
            }
        }
        ensureUnits();
        done({});
    });
}

void CanRobotWorker::ensureUnits()
{
    if (!m_units)
        m_units = std::make_unique<ConnectionUnits>(m_connection, m_options);
}

void CanRobotWorker::onLost(const QString &reason)
{
    qCWarning(lcCan).noquote() << reason;
    if (!m_units)
        return;
    if (m_units->sequence.isRunning())
        m_units->sequence.cancel(reason);
    if (m_units->streamer.isRunning())
        m_units->streamer.abort(TrialStatus::Faulted,
                                tr("%1 %2").arg(asClause(reason), m_units->streamer.where()));
    // The units stay until the next call reconnects and builds new ones (connectBus).
}

void CanRobotWorker::runTrial(const TrialPlan &plan, const TrialMonitor &monitor,
                              std::function<void(const TrialRecord &)> done)
{
    const double ts = plan.desired.samplePeriod;
    if (m_model->dof() != m_options.nodes.size() || plan.samples() < 1) {
        done(notStarted(ts, TrialStatus::Refused,
                        tr("the model has %1 joints but %2 CAN nodes are configured, or the plan "
                           "is empty")
                            .arg(m_model->dof())
                            .arg(m_options.nodes.size())));
        return;
    }
    m_trialDone = std::move(done);
    m_samplePeriod = ts;
    // The robot side's SYNC period is the plan's (0x1006 is checked in step 1): the bus load
    // is checked at it before anything is sent (connectBus), with the offer of what fits.
    setSyncPeriod(m_options, ts);
    connectBus([this, plan, monitor](const QString &error) {
        if (!error.isEmpty())
            return endTrial(notStarted(m_samplePeriod, TrialStatus::Refused, error));
        if (monitor.cancelled())
            return endTrial(notStarted(m_samplePeriod, TrialStatus::Cancelled,
                                       tr("stopped by the operator before the drives moved")));
        checkIdentity([this, plan, monitor](const QString &refused, bool unread) {
            if (!refused.isEmpty())
                return endTrial(notStarted(m_samplePeriod,
                                           unread ? TrialStatus::Faulted : TrialStatus::Refused,
                                           tr("refused before any motion: %1").arg(refused)));
            configure(plan, monitor);
        });
    });
}

quint32 CanRobotWorker::robotIdentity() const
{
    return m_options.robotIdentity != 0 ? m_options.robotIdentity
                                        : objects::robotIdentityOf(m_model->id());
}

void CanRobotWorker::checkIdentity(std::function<void(const QString &, bool)> next)
{
    if (!m_options.checkJointIdentity)
        return next({}, false);
    auto found = std::make_shared<JointIdentityFound>();
    const QList<int> nodes = m_options.nodes;
    m_units->sequence.run(
        jointIdentityReads(nodes, found), [this, found, nodes, next](const QString &error) {
            if (!error.isEmpty())
                return next(tr("reading the drives' identity failed: %1").arg(error), true);
            m_drives = QList<DriveIdentity>(found->drives.begin(), found->drives.end());
            next(jointIdentityError(
                     nodes, *found,
                     {robotIdentity(), m_options.commissioning, m_options.recordedDrives}),
                 false);
        });
}

void CanRobotWorker::configure(const TrialPlan &plan, const TrialMonitor &monitor)
{
    m_configuration = std::make_shared<NodeConfigurationResult>();
    QList<SdoStep> steps;
    try {
        steps = trialConfigurationSteps(m_options.nodes, plan, m_options, m_configuration);
    } catch (const Error &e) {
        return endTrial(notStarted(m_samplePeriod, TrialStatus::Refused, e.message()));
    }
    ConnectionUnits &units = *m_units; // connectBus succeeded just now
    units.recorder.start();
    units.heartbeat.stopAll();
    if (!units.nmt.enterPreOperational(0))
        return endTrial(
            notStarted(m_samplePeriod, TrialStatus::Faulted, m_connection->link()->lastError()));
    units.sequence.run(steps, [this, plan, monitor](const QString &error) {
        if (!error.isEmpty())
            return endTrial(
                notStarted(m_samplePeriod, TrialStatus::Faulted,
                           tr("configuring the drives failed, nothing moved: %1").arg(error)));
        if (monitor.cancelled())
            return endTrial(notStarted(m_samplePeriod, TrialStatus::Cancelled,
                                       tr("stopped by the operator before the drives moved")));
        m_units->streamer.start(*m_model, plan, m_options.nodes, m_configuration->scaling,
                                m_options, monitor,
                                [this](const TrialRecord &record) { endTrial(record); });
    });
}

void CanRobotWorker::endTrial(TrialRecord record)
{
    CandumpRecorder *recorder = m_units ? &m_units->recorder : nullptr;
    if (m_units)
        m_stats = m_units->streamer.statistics();
    if (recorder && recorder->isRecording()) {
        recorder->stop();
        if (!m_options.candumpDir.isEmpty()) {
            QDir().mkpath(m_options.candumpDir);
            const QString file =
                QDir(m_options.candumpDir)
                    .filePath(
                        QStringLiteral("trial-%1.log").arg(m_trials, 3, 10, QLatin1Char('0')));
            const QString error = recorder->save(file);
            if (!error.isEmpty()) {
                qCWarning(lcCan).noquote() << error;
                if (record.completed()) {
                    record.status = TrialStatus::Aborted;
                    record.stopCause = TrialStopCause::Other;
                    record.message =
                        tr("the trial's candump log could not be written: %1").arg(error);
                }
            }
        }
    }
    ++m_trials;
    if (auto done = std::exchange(m_trialDone, nullptr))
        done(record);
}

void CanRobotWorker::apply(const Eigen::VectorXd &phi, std::function<void(const QString &)> done)
{
    try {
        runApply(applySteps(m_options.nodes, phi, robotIdentity()),
                 QStringLiteral("0x2200, 0x2400 and 0x1010"), std::move(done));
    } catch (const Error &e) {
        done(e.message());
    }
}

void CanRobotWorker::applyPayload(int joint, const Eigen::VectorXd &body,
                                  std::function<void(const QString &)> done)
{
    try {
        runApply(payloadApplySteps(m_options.nodes, joint, body),
                 QStringLiteral("0x2500 and 0x1010"), std::move(done));
    } catch (const Error &e) {
        done(e.message());
    }
}

void CanRobotWorker::runApply(const QList<SdoStep> &steps, const QString &written,
                              std::function<void(const QString &)> done)
{
    connectBus([this, steps, written, done](const QString &error) {
        if (!error.isEmpty())
            return done(tr("%1; the stored parameters are unchanged").arg(asClause(error)));
        checkIdentity([this, steps, written, done](const QString &refused, bool) {
            if (!refused.isEmpty())
                return done(
                    tr("%1; nothing was stored (%2 not written)").arg(asClause(refused), written));
            int stores = 0;
            for (const SdoStep &s : steps)
                stores += s.index == 0x1010 ? 1 : 0;
            const int firstStore = int(steps.size()) - stores;
            SdoSequence *sequence = &m_units->sequence; // connectBus succeeded just now
            sequence->run(steps, [done, firstStore, sequence](const QString &error) {
                if (error.isEmpty())
                    return done({});
                if (sequence->stepsDone() < firstStore)
                    return done(
                        tr("%1; nothing was stored (0x1010 not written)").arg(asClause(error)));
                done(tr("%1; storing stopped at node %2 of the list")
                         .arg(asClause(error))
                         .arg(sequence->stepsDone() - firstStore + 1));
            });
        });
    });
}

void CanRobotWorker::shutdown()
{
    m_units.reset();
    m_connection->close();
}

} // namespace learnid
