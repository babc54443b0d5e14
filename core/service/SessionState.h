#pragma once

#include <QMetaType>

namespace learnid {

/// Where the commissioning workflow stands. The session service (SessionController) moves
/// between these; the window only reflects them through allowedActions().
enum class SessionState {
    NotConnected, ///< no robot, no session
    Connecting,   ///< building the robot (a CAN robot connects) and the session
    Idle,         ///< connected, nothing running
    RunningTrial, ///< one or more trials in progress
    Stopping,     ///< a stop was requested: the running trial ends at its next sample
    Applying,     ///< writing a parameter set to the robot (apply or revert)
};

/// The operations whose failure the service reports (operationFailed).
enum class SessionOperation { Run, Accept, Apply, Revert };

/// What the service knows besides its state that decides what may be done next.
struct SessionFacts
{
    bool checkPassed = false;  ///< the pre-trial check of the next trial passed
    bool learned = false;      ///< at least one learning step was made (an estimate to accept)
    bool ranTrial = false;     ///< a trial ran (trial data and plots to export)
    bool accepted = false;     ///< an estimate is accepted (to apply and export)
    bool applied = false;      ///< a set was applied in this session (there is one to revert)
    bool scenarioValid = true; ///< the scenario on hand is valid (to start a new session with)
};

/// The workflow's steps, each allowed or not.
struct AllowedActions
{
    bool connect = false; ///< connect a robot and open a session
    bool disconnect = false;
    bool newSession = false; ///< start over with the current scenario on the same robot
    bool editScenario = false;
    bool run = false; ///< run one trial or a series
    bool stop = false;
    bool accept = false;
    bool apply = false;
    bool revert = false;
    bool exportParameters = false;
    bool exportTrialData = false; ///< trial CSV and tracking-error plots
    bool exportReport = false;

    bool operator==(const AllowedActions &o) const;
};

/// The rules of the workflow: nothing starts while something runs; a trial needs a passed
/// pre-trial check; apply needs an accepted estimate; revert needs an applied one.
AllowedActions allowedActions(SessionState state, const SessionFacts &facts);

/// Whether the robot and session exist (every state but NotConnected and Connecting).
bool isConnected(SessionState state);

} // namespace learnid

Q_DECLARE_METATYPE(learnid::SessionState)
Q_DECLARE_METATYPE(learnid::SessionOperation)
