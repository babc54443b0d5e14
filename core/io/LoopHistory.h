#pragma once

#include <Eigen/Core>
#include <QByteArray>
#include <QList>
#include <QString>
#include <QStringList>

namespace learnid {

/// The "schema" of the history index this version reads and writes.
inline constexpr char loopHistorySchema[] = "learnid-history/1";
/// The index's file name in a history folder.
inline constexpr char loopHistoryIndexName[] = "history.json";

/// The history of a learning loop through files (`learnid-cli plan` / `learn`,
/// docs/file-formats.md "Learning history"): the index of a folder that keeps every learned
/// trial's plan and logs, every estimate as a parameter file, and the plans issued but not yet
/// learned from. File names are plain names inside the folder.
struct LoopHistory
{
    struct Trial
    {
        QString planId;                      ///< the plan it ran (PlanCsv.h)
        QString plan;                        ///< its plan file
        QStringList logs;                    ///< the controller's logs, one per repetition
        Eigen::VectorXd maxTrackingErrorDeg; ///< per joint [deg] (n)
        Eigen::VectorXd rmsTrackingErrorDeg; ///< per joint [deg] (n)
    };
    struct PendingPlan
    {
        QString planId;
        QString plan; ///< its plan file
    };

    QString robotModel; ///< model id
    int joints = 0;
    int parameters = 0;
    QString law; ///< learning law id (the payload's loop records it, unused)
    /// The link whose payload the loop learns (a scenario with a payload section,
    /// docs/payload.md); empty: the loop learns the arm. Written as "payload": {"link": ...}
    /// only when set, so that an arm history reads and writes as before.
    QString payloadLink;
    /// parameter files, estimates[k] = estimate k (k = 0: the initial); the payload's loop: the
    /// arm held fixed plus the payload section of estimate k (k = 0: the prior)
    QStringList estimates;
    QList<Trial> trials;             ///< learned trials in order; trial k ran with estimate k
    QList<PendingPlan> pendingPlans; ///< plans written with the newest estimate, not learned yet
};

/// The index as indented JSON. Throws Error when estimates does not hold one file more than
/// trials, or a name or id is malformed (the same rules as the reader's).
QByteArray loopHistoryToJson(const LoopHistory &history);

/// Reads and checks an index: schema, every key present with the right type, no unknown keys,
/// plan-ids of 64 hex digits, plain file names, one estimate more than trials, one figure per
/// joint; the optional "payload" object with its non-empty "link" and nothing else. Throws Error
/// "<source>: <key path>: <problem>".
LoopHistory loopHistoryFromJson(const QByteArray &json, const QString &source);

} // namespace learnid
