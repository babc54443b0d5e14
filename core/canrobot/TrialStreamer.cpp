#include "canrobot/TrialStreamer.h"

#include "can/CanLink.h"
#include "can/CanLogging.h"
#include "can/CanOpen.h"
#include "can/CanTimeouts.h"
#include "can/Cia402.h"
#include "can/Nmt.h"

#include <QCoreApplication>
#include <cmath>

namespace learnid {

namespace {

constexpr double kRadToDeg = 180.0 / M_PI;
constexpr quint16 statusSetpointFollowed = 0x1000; // bit 12 in cyclic synchronous position

} // namespace

TrialStreamer::TrialStreamer(CanLink *link, Nmt *nmt, HeartbeatConsumer *heartbeat,
                             EmcyConsumer *emcy, QObject *parent)
    : QObject(parent)
    , m_link(link)
    , m_nmt(nmt)
    , m_watchdog(heartbeat, emcy)
{
    m_deadline.setSingleShot(true);
    connect(&m_watchdog, &TrialWatchdog::fault, this,
            [this](TrialStatus status, const QString &reason) {
                abort(status, tr("%1 %2").arg(reason, where()));
            });
    connect(&m_deadline, &QTimer::timeout, this, [this] {
        if (m_phase == Phase::Stopping)
            return finish();
        for (int j = 0; j < m_nodes.size(); ++j) {
            const auto state =
                m_collector->hasFeedback(j)
                    ? cia402::stateFromStatusword(m_collector->feedback(j).statusword)
                    : cia402::State::Unknown;
            if (state != cia402::State::OperationEnabled) {
                abort(
                    TrialStatus::Aborted,
                    tr("%1 did not reach Operation enabled within %2 ms: it reports %3 "
                       "(statusword 0x%4)")
                        .arg(nodeName(j))
                        .arg(enableTimeoutMs())
                        .arg(m_collector->hasFeedback(j) ? cia402::stateName(state) : tr("no TPDO"))
                        .arg(m_collector->feedback(j).statusword, 4, 16, QLatin1Char('0')));
                return;
            }
        }
    });
}

TrialStreamer::~TrialStreamer() = default;

void TrialStreamer::start(const RobotModel &model, const TrialPlan &plan, const QList<int> &nodes,
                          const QVector<DriveScaling> &scaling, const CanRobotOptions &options,
                          const TrialMonitor &monitor, Done done)
{
    m_model = &model;
    m_plan = plan;
    m_nodes = nodes;
    m_names.clear();
    for (int j = 0; j < nodes.size(); ++j)
        m_names << nodeName(j);
    m_options = options;
    m_monitor = monitor;
    m_done = std::move(done);
    m_scaling = scaling;
    m_collector.emplace(scaling, plan.samples(), plan.desired.samplePeriod);
    m_schedule = {};
    m_sentColumn = -1;
    m_phaseSyncs = 0;
    m_writer.reset(m_link, nodes);
    m_progressReported = 0;
    m_status = TrialStatus::Completed;
    m_cause = TrialStopCause::None;
    m_message.clear();
    m_stats = {};
    m_phase = Phase::Enabling;

    m_connections << connect(m_link, &CanLink::frameReceived, this, &TrialStreamer::onFrame);
    // The options' SYNC period is the plan's (CanRobotWorker::runTrial).
    m_watchdog.start(nodes,
                     effectiveHeartbeatPeriodMs(options) * cantimeouts::heartbeatLossFactor +
                         options.extraWaitMs,
                     effectiveSyncTimeoutMs(options) + options.extraWaitMs);
    m_deadline.start(enableTimeoutMs());
    if (!m_nmt->startNode(0))
        QMetaObject::invokeMethod(
            this, [this] { abort(TrialStatus::Aborted, m_link->lastError()); },
            Qt::QueuedConnection);
}

void TrialStreamer::onFrame(const QCanBusFrame &frame)
{
    if (frame.frameType() != QCanBusFrame::DataFrame || frame.hasExtendedFrameFormat())
        return;
    const quint32 id = frame.frameId();
    if (id == canopen::syncCobId) {
        onSync(frame.payload().isEmpty() ? 0 : quint8(frame.payload().at(0)));
    } else if (id > canopen::tpdoCobId(1, 0) && id <= canopen::tpdoCobId(1, 127)) {
        const int joint = jointOfNode(canopen::nodeOfCobId(id));
        if (joint >= 0)
            onTpdo(joint, frame.payload());
    }
}

void TrialStreamer::onSync(quint8 counter)
{
    if (m_phase == Phase::Idle)
        return;
    const qint64 arrival = m_clock.arrival ? m_clock.arrival() : 0;
    m_watchdog.syncReceived();
    const int applied = m_phase == Phase::Streaming ? m_sentColumn : -1;
    const int planSample = applied >= 0 ? m_schedule.sample.at(applied) : -1;
    // From the first streamed SYNC on, every node must answer every SYNC.
    const bool requireComplete = m_phase == Phase::Streaming && applied >= 0;
    const QString error = m_collector->beginCycle(counter, planSample, requireComplete, m_names);
    ++m_stats.syncs;
    ++m_phaseSyncs;
    if (!error.isEmpty())
        return abort(TrialStatus::Aborted, tr("%1 %2").arg(error, where()),
                     TrialStopCause::MissingSamples);
    if (m_phase != Phase::Stopping && m_monitor.cancelled())
        return abort(TrialStatus::Cancelled, tr("stopped by the operator %1").arg(where()));
    switch (m_phase) {
    case Phase::Enabling:
        return enableStep();
    case Phase::Streaming:
        streamStep();
        if (m_clock.now && m_phase == Phase::Streaming)
            m_stats.syncToRpdoUs.append(double(m_clock.now() - arrival) / 1000.0);
        return;
    case Phase::Disabling:
        return disableStep();
    case Phase::Stopping:
        return stopStep();
    case Phase::Idle:
        return;
    }
}

void TrialStreamer::onTpdo(int joint, const QByteArray &payload)
{
    if (m_phase == Phase::Idle || !m_collector || m_collector->syncCount() == 0)
        return;
    const QString error = m_collector->addTpdo(joint, payload);
    if (!error.isEmpty())
        return abort(TrialStatus::Aborted, tr("%1: %2 %3").arg(nodeName(joint), error, where()));
    if (m_collector->cycleComplete())
        checkCycle();
}

void TrialStreamer::checkCycle()
{
    if (m_phase != Phase::Streaming)
        return;
    const int applied = m_sentColumn - 1; // this cycle answers the SYNC before the last send
    if (applied < 0)
        return;
    for (int j = 0; j < m_nodes.size(); ++j) {
        const DriveFeedback &f = m_collector->feedback(j);
        const cia402::State state = cia402::stateFromStatusword(f.statusword);
        if (state != cia402::State::OperationEnabled) {
            return abort(TrialStatus::Faulted,
                         tr("%1 left Operation enabled: it reports %2 (0x6041 = 0x%3) %4")
                             .arg(nodeName(j), cia402::stateName(state))
                             .arg(f.statusword, 4, 16, QLatin1Char('0'))
                             .arg(where()));
        }
        m_stats.lateSetpoints += (f.statusword & statusSetpointFollowed) ? 0 : 1;
        const double error = std::abs(m_schedule.q(j, applied) - m_collector->position(j));
        if (error > m_plan.maxTrackingError) {
            return abort(TrialStatus::Aborted,
                         tr("tracking error of %1 reached %2 deg (limit %3 deg) %4: quick stop")
                             .arg(nodeName(j))
                             .arg(error * kRadToDeg, 0, 'g', 4)
                             .arg(m_plan.maxTrackingError * kRadToDeg, 0, 'g', 4)
                             .arg(where()),
                         TrialStopCause::TrackingLimit);
        }
    }
}

bool TrialStreamer::sendSetpoints(int column, quint16 controlword)
{
    for (int j = 0; j < m_nodes.size(); ++j) {
        if (!m_writer.write(j, m_scaling[j].toIncrements(m_schedule.q(j, column)),
                            m_scaling[j].toPermille(m_schedule.tau(j, column)), controlword)) {
            abort(TrialStatus::Aborted, tr("%1 %2").arg(m_writer.error(), where()));
            return false;
        }
    }
    return true;
}

void TrialStreamer::sendDisableVoltage()
{
    // Answers every SYNC even before the drives report: a silent master lets a TCP-carried
    // bus (virtualcan) stall in delayed ACKs. Disable voltage keeps a drive without power.
    for (int j = 0; j < m_nodes.size(); ++j)
        m_writer.write(j, 0, 0, cia402::controlword(cia402::Command::DisableVoltage));
}

void TrialStreamer::sendQuickStop()
{
    for (int j = 0; j < m_nodes.size(); ++j)
        m_writer.write(j, m_collector->feedback(j).position, 0,
                       cia402::controlword(cia402::Command::QuickStop));
}

void TrialStreamer::abort(TrialStatus status, const QString &message,
                          std::optional<TrialStopCause> cause)
{
    if (m_phase == Phase::Idle || m_phase == Phase::Stopping)
        return;
    qCWarning(lcCan).noquote() << "trial stopped:" << message;
    m_status = status;
    m_cause = cause.value_or(defaultStopCause(status));
    m_message = message;
    m_phase = Phase::Stopping;
    m_phaseSyncs = 0;
    sendQuickStop();
    m_deadline.start(cantimeouts::stopBoundMs(m_options.syncPeriod)); // also on a silent bus
}

void TrialStreamer::finish()
{
    if (m_phase == Phase::Idle)
        return;
    const bool stopped = m_phase == Phase::Stopping;
    m_phase = Phase::Idle;
    m_watchdog.stop();
    m_deadline.stop();
    for (const auto &c : std::as_const(m_connections))
        disconnect(c);
    m_connections.clear();
    m_nmt->enterPreOperational(0);

    TrialStatus status = m_status;
    TrialStopCause cause = m_cause;
    QString message = m_message;
    if (!stopped && m_collector->recordedSamples() < m_plan.samples()) {
        status = TrialStatus::Aborted;
        cause = TrialStopCause::MissingSamples;
        message = tr("only %1 of %2 samples were recorded")
                      .arg(m_collector->recordedSamples())
                      .arg(m_plan.samples());
    }
    TrialRecord record = m_collector->record(status, message);
    record.lateSetpoints = m_stats.lateSetpoints;
    record.stopCause = status == TrialStatus::Completed ? TrialStopCause::None : cause;
    if (Done done = std::exchange(m_done, nullptr))
        done(record);
}

QString TrialStreamer::where() const
{
    return m_collector ? m_collector->where() : QString();
}

QString TrialStreamer::nodeName(int joint) const
{
    if (joint < 0 || joint >= m_nodes.size())
        return tr("an unknown node");
    return tr("node %1 (joint %2)").arg(m_nodes[joint]).arg(joint + 1);
}

int TrialStreamer::jointOfNode(quint8 node) const
{
    return int(m_nodes.indexOf(int(node)));
}

} // namespace learnid
