#pragma once

#include "session/CommissioningSession.h"

#include <QString>

namespace learnid::cli {

/// The paper's Table 1 as text: row k is the estimate after k learning steps with the figures
/// of the trial run with it (tracking error, conditioning of the fit made from that trial), the
/// relative change from the previous row and, for a simulated robot, the error against the truth.
QString resultTable(const CommissioningSession &session);

/// One line about a finished trial for the progress stream.
QString trialSummary(const TrialResult &result);

} // namespace learnid::cli
