#pragma once

#include "io/LoopHistory.h"
#include "model/RobotModel.h"
#include "session/CommissioningSession.h"
#include "session/PayloadSession.h"
#include "types/Scenario.h"

#include <QList>
#include <QPair>
#include <QString>
#include <QStringList>
#include <memory>
#include <optional>

namespace learnid {

// The learning loop through files, "bring your own controller" (docs/design.md §7, docs/cli.md
// "learnid-cli plan" and "learnid-cli learn"): planNextTrial() writes the next trial's q_d(t)
// and tau_f(t) for the robot's own controller, which runs it and logs q and tau;
// learnFromTrial() reads the log and learns. The history folder keeps the loop's state
// (io/LoopHistory.h); learning replays it through a CommissioningSession whose robot answers
// with the logged trials (RecordedTrialRobot), so the estimates are exactly a session's.
// A scenario with a payload section runs the payload's loop the same way: planning and learning
// replay a PayloadSession over the history's trials (FileLoopPayload*.cpp, docs/payload.md).

/// A scenario as the loop runs it: its model, and the scenario with what a URDF robot leaves
/// to the robot filled in (withRobotDefaults).
struct LoopScenario
{
    Scenario scenario;
    std::shared_ptr<const RobotModel> model;
};

/// Throws Error for an unknown model or a robot that cannot be made (as opening a session does).
LoopScenario loopScenario(const Scenario &scenario);

/// What a loop step writes: folders to create, files written all or none, and files of the
/// history no longer referenced, removed after the others are written.
struct LoopFiles
{
    QStringList folders;
    QList<QPair<QString, QByteArray>> files;
    QStringList obsolete;
};

/// Creates the folders, writes the files (writeFilesAtomically) and removes the obsolete ones
/// (a file that cannot be removed stays; nothing refers to it). Returns the paths written.
/// Throws Error naming the path and the reason.
QStringList writeLoopFiles(const LoopFiles &files);

/// The history in folder dir, or nullopt when the folder has no index. Throws Error naming the
/// file for an index it cannot read.
std::optional<LoopHistory> readLoopHistory(const QString &dir);

/// Throws Error when the history was not made for this scenario's robot (model, joints,
/// parameters), or by the other loop (the arm's for a scenario with a payload section, the
/// payload's for one without), or for the arm by another learning law, naming both.
void checkHistoryFits(const LoopHistory &history, const QString &dir, const LoopScenario &s);

/// The values of the parameter file at path, checked against the robot: its model and its
/// parameters. what names it in messages (e.g. "--estimate"). Throws Error.
Eigen::VectorXd readEstimateFile(const QString &path, const RobotModel &model, const QString &what);

/// The pre-trial check as text (check.txt): the verdict, the planned motion, the closed loop,
/// per joint the planned peak torque against its limit, then what the trial can learn.
QString preTrialCheckText(const PreTrialCheck &check, int trialIndex, const QString &estimateSource,
                          const QStringList &identifiability);

struct PlanRequest
{
    QString estimatePath; ///< --estimate; empty: the history's newest, or the scenario's initial
    QString historyDir;   ///< absolute
    QString outDir;       ///< absolute; receives plan.csv and check.txt
};

/// The next trial, planned and checked.
struct PlannedTrial
{
    PreTrialCheck check;
    QString planId;         ///< empty when the check failed
    int trialIndex = 0;     ///< the trial of the history it will be
    QString estimateSource; ///< in words: which estimate the feedforward is built with
    QString checkText;      ///< preTrialCheckText()
    LoopFiles files;        ///< plan.csv, check.txt and the history's; empty when refused

    bool passed() const { return check.passed(); }
};

/// Plans the next trial with the estimate of request.estimatePath, else the history's newest,
/// else the scenario's initial one, and checks it (as CommissioningSession::checkNextTrial()).
/// A plan that passes is recorded in the history as pending; a new history starts with the
/// estimate as estimate 0. Throws Error for input it cannot use: an unreadable history or
/// estimate, a history of another robot or law, --estimate for a history that has learned.
/// With a payload section: planned with the arm plus the payload the history's trials give
/// (PayloadSession::checkNextTrial() after replaying them); --estimate is refused.
PlannedTrial planNextTrial(const LoopScenario &s, const PlanRequest &request);

struct LearnRequest
{
    QStringList trialLogs; ///< the controller's logs of one plan, one per repetition
    QString historyDir;    ///< absolute
};

/// A trial learned from (or not).
struct LearnedTrial
{
    /// The history's trials replayed with the new one: its history, estimates and figures are
    /// what a session that ran these trials has. Null when the log ended early, and for a
    /// scenario with a payload section.
    std::unique_ptr<CommissioningSession> session;
    /// The same for a scenario with a payload section: the payload's session (PayloadSession)
    /// replayed over the history's trials and the new one; null otherwise.
    std::unique_ptr<PayloadSession> payloadSession;
    int trialIndex = 0;
    QString planId;
    QString failure; ///< why nothing was learned (trial ended early, law failed); empty: learned
    LoopFiles files; ///< the history's new files; empty on failure
};

/// Reads the logs of a plan the history holds as pending, replays the history with them and
/// learns. Throws Error for input it cannot use: no history, a log without or with an unknown
/// plan-id, a plan already learned, a log off the plan's grid or longer than the plan, a scenario
/// that plans the history's trials differently (naming both plan-ids), a damaged history.
/// With a payload section: one log per trial, replayed through a PayloadSession.
LearnedTrial learnFromTrial(const LoopScenario &s, const LearnRequest &request);

} // namespace learnid
