#pragma once

#include "session/CommissioningSession.h"

#include <QString>

namespace learnid::cli {

/// The paper's Table 1 as text: row k is the estimate after k learning steps with the figures
/// of the trial run with it (tracking error, conditioning of the fit made from that trial), the
/// relative change from the previous row and, for a simulated robot, the error against the truth.
QString resultTable(const CommissioningSession &session);

/// One line about a finished trial for the progress stream (a trial that did not complete gets
/// no reason here: it ends the series, and the reason follows as the error line).
QString trialSummary(const TrialResult &result);

} // namespace learnid::cli
