#include "service/SessionState.h"

#include <tuple>

namespace learnid {

namespace {

auto asTuple(const AllowedActions &a)
{
    return std::tie(a.connect, a.disconnect, a.newSession, a.editScenario, a.run, a.stop, a.accept,
                    a.apply, a.revert, a.exportParameters, a.exportTrialData, a.exportReport);
}

} // namespace

bool AllowedActions::operator==(const AllowedActions &o) const
{
    return asTuple(*this) == asTuple(o);
}

bool isConnected(SessionState state)
{
    return state != SessionState::NotConnected && state != SessionState::Connecting;
}

AllowedActions allowedActions(SessionState state, const SessionFacts &facts)
{
    const bool idle = state == SessionState::Idle;
    AllowedActions a;
    a.connect = state == SessionState::NotConnected;
    a.disconnect = idle;
    a.newSession = idle && facts.scenarioValid;
    // Editing the scenario re-opens the session with it (before the first trial): allowed
    // while a previous open is still on its way, the last one wins.
    a.editScenario = idle || !isConnected(state);
    a.run = idle && facts.checkPassed;
    a.stop = state == SessionState::RunningTrial;
    a.accept = idle && facts.learned;
    a.apply = idle && facts.accepted;
    a.revert = idle && facts.applied;
    // Exports read what the service holds; they may run beside a trial.
    a.exportParameters = isConnected(state) && facts.accepted;
    a.exportTrialData = facts.ranTrial;
    a.exportReport = isConnected(state);
    return a;
}

} // namespace learnid
