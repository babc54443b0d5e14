#pragma once

#include "canrobot/DriveScaling.h"
#include "types/Trial.h"

#include <QByteArray>
#include <QList>
#include <QString>
#include <QVector>

namespace learnid {

/// One TPDO1 of a drive (objects::trialTpdoMapping()).
struct DriveFeedback
{
    qint32 position = 0;    ///< 0x6064 [inc]
    qint16 torque = 0;      ///< 0x6077 [per mille]
    quint16 statusword = 0; ///< 0x6041
};

/// Collects a trial's TPDOs into the TrialRecord, indexed by SYNC (docs/can-protocol.md,
/// "SYNC and the sample clock"): the TPDOs arriving after SYNC c and before SYNC c+1 are the
/// drives' answer to SYNC c; the caller says which plan sample was applied at each SYNC. The
/// same collector serves a live trial and one replayed from a candump log.
class TrialCollector
{
public:
    /// samples: the plan's sample count; ts: its sample period [s]; one scaling per joint.
    TrialCollector(QVector<DriveScaling> scaling, int samples, double ts);

    /// SYNC with counter (1..240; 0 when the frame carries none) arrived; planSample is the plan
    /// sample applied at this SYNC, -1 for none. Returns why the trial must stop, or empty:
    /// when requireComplete and a joint's TPDO of the previous SYNC is missing, or when the
    /// counter skipped (a SYNC was lost). jointNames name the joints in messages ("node 2").
    QString beginCycle(quint8 counter, int planSample, bool requireComplete,
                       const QStringList &jointNames);
    /// The TPDO of joint for the current SYNC. Returns an error for a payload shorter than the
    /// mapping; a second TPDO of the same joint in one cycle replaces the first.
    QString addTpdo(int joint, const QByteArray &payload);

    bool cycleComplete() const;
    bool hasFeedback(int joint) const { return m_latestValid.at(joint); }
    const DriveFeedback &feedback(int joint) const { return m_latest.at(joint); }
    /// Position [rad] and torque [N m] of the joint's latest TPDO.
    double position(int joint) const;
    double torque(int joint) const;

    qint64 syncCount() const { return m_syncs; } ///< SYNCs seen, the current one included
    quint8 counter() const { return m_counter; }
    int planSample() const { return m_planSample; }
    /// Complete plan samples from 0 on, without a gap.
    int recordedSamples() const { return m_recorded; }

    /// Where the trial is, for messages: "at SYNC 812 (counter 92), plan sample 300, t = 0.600 s"
    /// or "at SYNC 12 (counter 52), 0.024 s after NMT start".
    QString where() const;

    /// The record of samples 0 .. recordedSamples()-1 with status and message.
    TrialRecord record(TrialStatus status, const QString &message) const;

private:
    void storeSample();

    QVector<DriveScaling> m_scaling;
    double m_ts;
    Eigen::MatrixXd m_q;
    Eigen::MatrixXd m_tau;
    QVector<DriveFeedback> m_latest;
    QVector<bool> m_latestValid;
    QVector<bool> m_received; ///< in the current cycle
    qint64 m_syncs = 0;
    quint8 m_counter = 0;
    int m_planSample = -1;
    int m_recorded = 0;
};

} // namespace learnid
