// The phases of TrialStreamer, one step per SYNC: enable, stream, disable, stop
// (docs/can-protocol.md, "A trial", steps 2 to 5). The SYNC handling and the checks are in
// TrialStreamer.cpp.
#include "can/CanLogging.h"
#include "can/Cia402.h"
#include "canrobot/TrialStreamer.h"

#include <QElapsedTimer>

namespace learnid {

namespace {

constexpr int maxStoppingSyncs = 15; // quick stop active lasts 10 SYNCs
constexpr int maxDisablingSyncs = 10;

bool powered(cia402::State s)
{
    return s == cia402::State::OperationEnabled || s == cia402::State::QuickStopActive ||
           s == cia402::State::FaultReactionActive;
}

} // namespace

void TrialStreamer::enableStep()
{
    bool allEnabled = true;
    for (int j = 0; j < m_nodes.size(); ++j) {
        if (!m_collector->hasFeedback(j))
            return sendDisableVoltage(); // the first TPDOs after NMT start are still to come
        allEnabled =
            allEnabled && cia402::stateFromStatusword(m_collector->feedback(j).statusword) ==
                              cia402::State::OperationEnabled;
    }
    if (allEnabled) {
        m_deadline.stop();
        if (m_schedule.size() == 0)
            buildSchedule();
        m_phase = Phase::Streaming;
        m_phaseSyncs = 0;
        m_sentColumn = 0;
        sendSetpoints(0, cia402::controlword(cia402::Command::EnableOperation));
        return;
    }
    for (int j = 0; j < m_nodes.size(); ++j) {
        const DriveFeedback &f = m_collector->feedback(j);
        // Hold where it stands while the drive walks towards Operation enabled.
        if (!m_writer.write(j, f.position, 0, m_writer.enableControlword(j, f.statusword)))
            return abort(TrialStatus::Aborted, tr("%1 %2").arg(m_writer.error(), where()));
    }
    // The brakes hold the arm until it is enabled: plan the move now, after this SYNC's
    // answer is out, so that the first streamed SYNC is not late. The enable walk's time
    // counts from the plan's end, as the watchdog's (buildSchedule).
    if (m_schedule.size() == 0) {
        buildSchedule();
        m_deadline.start(enableTimeoutMs());
    }
}

void TrialStreamer::buildSchedule()
{
    Eigen::VectorXd q0(m_nodes.size());
    for (int j = 0; j < m_nodes.size(); ++j)
        q0[j] = m_collector->position(j);
    QElapsedTimer planning;
    planning.start();
    m_schedule = buildSetpointSchedule(*m_model, m_plan, q0, ReturnMoveLimits{});
    // This thread read no frame while it planned (1 ms on a PC, 150 ms in the VM of
    // scripts/test-socketcan, whose emulated CPU is slow at floating point): the SYNCs and
    // heartbeats of that time wait in the socket. The robot side did not pause, the master
    // did: the SYNC gap and the heartbeat timeouts count from here (docs/can-protocol.md §8.2).
    m_watchdog.restartClocks();
    qCDebug(lcCan) << "return move planned in" << planning.elapsed() << "ms";
}

void TrialStreamer::streamStep()
{
    const int total = m_plan.samples();
    const int done = m_collector->recordedSamples();
    if (m_monitor.progress && done > m_progressReported && (done % 100 == 0 || done == total)) {
        m_progressReported = done;
        m_monitor.progress(done, total);
    }
    if (m_sentColumn + 1 < m_schedule.size()) {
        ++m_sentColumn;
        sendSetpoints(m_sentColumn, cia402::controlword(cia402::Command::EnableOperation));
        return;
    }
    // The last column is applied now: power off (the brakes hold) from the next SYNC on.
    m_phase = Phase::Disabling;
    m_phaseSyncs = 0;
    sendSetpoints(m_sentColumn, cia402::controlword(cia402::Command::Shutdown));
}

bool TrialStreamer::allWithoutPower() const
{
    for (int j = 0; j < m_nodes.size(); ++j) {
        if (!m_collector->hasFeedback(j) ||
            powered(cia402::stateFromStatusword(m_collector->feedback(j).statusword)))
            return false;
    }
    return true;
}

void TrialStreamer::disableStep()
{
    if (allWithoutPower() || m_phaseSyncs > maxDisablingSyncs)
        return finish();
    sendSetpoints(m_sentColumn, cia402::controlword(cia402::Command::Shutdown));
}

void TrialStreamer::stopStep()
{
    if (allWithoutPower() || m_phaseSyncs > maxStoppingSyncs)
        return finish();
    sendQuickStop();
}

} // namespace learnid
