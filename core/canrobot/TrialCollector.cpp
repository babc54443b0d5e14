#include "canrobot/TrialCollector.h"

#include "can/CanOpen.h"

#include <QCoreApplication>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(CanRobot)
};

constexpr int tpdoBytes = 8;
constexpr int syncCounterOverflow = 240; // 0x1019

} // namespace

TrialCollector::TrialCollector(QVector<DriveScaling> scaling, int samples, double ts)
    : m_scaling(std::move(scaling))
    , m_ts(ts)
{
    const int n = int(m_scaling.size());
    m_q.setZero(n, samples);
    m_tau.setZero(n, samples);
    m_latest.resize(n);
    m_latestValid.fill(false, n);
    m_received.fill(false, n);
}

QString TrialCollector::beginCycle(quint8 counter, int planSample, bool requireComplete,
                                   const QStringList &jointNames)
{
    QString error;
    if (requireComplete && m_syncs > 0) {
        for (int j = 0; j < m_received.size() && error.isEmpty(); ++j) {
            if (!m_received[j]) {
                error =
                    Text::tr("%1: the TPDO answering SYNC %2 (counter %3) did not arrive before "
                             "the next SYNC: sample missing")
                        .arg(jointNames.value(j, Text::tr("joint %1").arg(j + 1)))
                        .arg(m_syncs)
                        .arg(m_counter);
            }
        }
    }
    if (error.isEmpty() && m_syncs > 0 && m_counter != 0 && counter != 0) {
        const int expected = m_counter % syncCounterOverflow + 1;
        if (counter != expected) {
            const int lost = (counter - expected + syncCounterOverflow) % syncCounterOverflow;
            error = Text::tr("SYNC counter jumped from %1 to %2 after SYNC %3: %4 SYNC(s) lost")
                        .arg(m_counter)
                        .arg(counter)
                        .arg(m_syncs)
                        .arg(lost);
        }
    }
    ++m_syncs;
    m_counter = counter;
    m_planSample = planSample;
    m_received.fill(false);
    return error;
}

QString TrialCollector::addTpdo(int joint, const QByteArray &payload)
{
    if (joint < 0 || joint >= m_latest.size())
        return {};
    if (payload.size() < tpdoBytes)
        return Text::tr("joint %1: TPDO of %2 bytes, the mapping needs %3 (SYNC %4)")
            .arg(joint + 1)
            .arg(payload.size())
            .arg(tpdoBytes)
            .arg(m_syncs);
    DriveFeedback &f = m_latest[joint];
    f.position = qint32(canopen::readU32(payload, 0));
    f.torque = qint16(canopen::readU16(payload, 4));
    f.statusword = canopen::readU16(payload, 6);
    m_latestValid[joint] = true;
    m_received[joint] = true;
    if (cycleComplete())
        storeSample();
    return {};
}

bool TrialCollector::cycleComplete() const
{
    return m_syncs > 0 && !m_received.contains(false);
}

double TrialCollector::position(int joint) const
{
    return m_scaling.at(joint).toRad(m_latest.at(joint).position);
}

double TrialCollector::torque(int joint) const
{
    return m_scaling.at(joint).toNewtonMetre(m_latest.at(joint).torque);
}

void TrialCollector::storeSample()
{
    const int k = m_planSample;
    if (k < 0 || k >= m_q.cols() || k != m_recorded)
        return; // samples are recorded in order only; a gap ends the trial before this
    for (int j = 0; j < m_latest.size(); ++j) {
        m_q(j, k) = position(j);
        m_tau(j, k) = torque(j);
    }
    m_recorded = k + 1;
}

QString TrialCollector::where() const
{
    if (m_planSample >= 0)
        return Text::tr("at SYNC %1 (counter %2), plan sample %3, t = %4 s")
            .arg(m_syncs)
            .arg(m_counter)
            .arg(m_planSample)
            .arg(m_planSample * m_ts, 0, 'f', 3);
    return Text::tr("at SYNC %1 (counter %2), %3 s after NMT start")
        .arg(m_syncs)
        .arg(m_counter)
        .arg(m_syncs * m_ts, 0, 'f', 3);
}

TrialRecord TrialCollector::record(TrialStatus status, const QString &message) const
{
    TrialRecord r;
    r.samplePeriod = m_ts;
    r.q = m_q.leftCols(m_recorded);
    r.tau = m_tau.leftCols(m_recorded);
    r.status = status;
    r.message = message;
    return r;
}

} // namespace learnid
