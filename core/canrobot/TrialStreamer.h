#pragma once

#include "canrobot/CanRobotOptions.h"
#include "canrobot/SetpointSchedule.h"
#include "canrobot/SetpointWriter.h"
#include "canrobot/TrialCollector.h"
#include "canrobot/TrialWatchdog.h"
#include "types/Trial.h"

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>
#include <QVector>
#include <functional>
#include <optional>

namespace learnid {

class CanLink;
class EmcyConsumer;
class HeartbeatConsumer;
class Nmt;
struct EmcyMessage;

/// Figures of one streamed trial, for the benchmark and the log.
struct TrialStreamStatistics
{
    qint64 syncs = 0;             ///< SYNCs seen from NMT start to the end
    int lateSetpoints = 0;        ///< TPDOs with statusword bit 12 clear while streaming
    QVector<double> syncToRpdoUs; ///< per streamed SYNC: its arrival to the RPDOs written [us]
};

/// The SYNC-driven part of a trial (docs/can-protocol.md, "A trial", steps 2 to 5), on nodes
/// already configured: NMT start, CiA 402 enable through the RPDO controlword, the return move
/// and hold, the plan's samples, the final hold, Shutdown and NMT pre-operational. Every SYNC
/// it sends one RPDO1 per node; the TPDOs go to a TrialCollector. Any fault (EMCY, drive fault,
/// heartbeat loss, unexpected boot-up, SYNC gap, missing TPDO, tracking error, cancel, device
/// refusing a frame) sends quick stop to all nodes and ends the trial with the partial record
/// and a message naming the node, object or code, the SYNC and the time.
class TrialStreamer : public QObject
{
    Q_OBJECT

public:
    using Done = std::function<void(const TrialRecord &record)>;
    /// Times [ns of one steady clock] for the latency figure: when the frames being handled
    /// arrived, and now.
    struct LatencyClock
    {
        std::function<qint64()> arrival;
        std::function<qint64()> now;
    };

    TrialStreamer(CanLink *link, Nmt *nmt, HeartbeatConsumer *heartbeat, EmcyConsumer *emcy,
                  QObject *parent = nullptr);
    ~TrialStreamer() override;

    void setLatencyClock(LatencyClock clock) { m_clock = std::move(clock); }

    /// Starts the trial; done is called once, never from inside start().
    void start(const RobotModel &model, const TrialPlan &plan, const QList<int> &nodes,
               const QVector<DriveScaling> &scaling, const CanRobotOptions &options,
               const TrialMonitor &monitor, Done done);
    bool isRunning() const { return m_phase != Phase::Idle; }
    /// Ends a running trial from outside (e.g. the device went unconnected).
    /// cause: what stopped it, when more specific than the status says (defaultStopCause()).
    void abort(TrialStatus status, const QString &message,
               std::optional<TrialStopCause> cause = std::nullopt);

    const TrialStreamStatistics &statistics() const { return m_stats; }
    /// Where the running trial is, for messages ("at SYNC 812 (counter 92), plan sample ...").
    QString where() const;

private:
    enum class Phase { Idle, Enabling, Streaming, Disabling, Stopping };

    void onFrame(const QCanBusFrame &frame);
    void onSync(quint8 counter);
    void onTpdo(int joint, const QByteArray &payload);
    void enableStep();
    void streamStep();
    void disableStep();
    void stopStep();
    void checkCycle();
    bool allWithoutPower() const;
    bool sendSetpoints(int column, quint16 controlword);
    void sendQuickStop();
    void sendDisableVoltage();
    void buildSchedule();
    void finish();
    QString nodeName(int joint) const;
    /// The enable walk's time limit: the options', longer in a replay.
    int enableTimeoutMs() const { return m_options.enableTimeoutMs + m_options.extraWaitMs; }
    int jointOfNode(quint8 node) const;

    CanLink *m_link;
    Nmt *m_nmt;
    TrialWatchdog m_watchdog;
    LatencyClock m_clock;
    QList<QMetaObject::Connection> m_connections;

    Phase m_phase = Phase::Idle;
    const RobotModel *m_model = nullptr;
    TrialPlan m_plan;
    QList<int> m_nodes;
    QStringList m_names;
    QVector<DriveScaling> m_scaling;
    CanRobotOptions m_options;
    TrialMonitor m_monitor;
    Done m_done;
    std::optional<TrialCollector> m_collector;
    SetpointSchedule m_schedule;
    int m_sentColumn = -1; ///< schedule column sent after the last SYNC (applied at the next)
    int m_phaseSyncs = 0;  ///< SYNCs since the current phase began
    SetpointWriter m_writer;
    int m_progressReported = 0;
    TrialStatus m_status = TrialStatus::Completed;
    TrialStopCause m_cause = TrialStopCause::None;
    QString m_message;
    QTimer m_deadline; ///< enable timeout, then the bound of the stopping phase
    TrialStreamStatistics m_stats;
};

} // namespace learnid
