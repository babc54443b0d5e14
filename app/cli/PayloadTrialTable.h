#pragma once

#include "session/PayloadSession.h"

#include <QString>

namespace learnid::cli {

/// The two header lines of the payload session's trial table (`run` and `learn` with a payload
/// section, docs/cli.md), each ended by a newline.
QString payloadTrialHeader();

/// One trial's row: index, max and RMS tracking error over the joints, then the mass, centre of
/// mass, update CPU and the body values the trials identified, or why it was not learned from.
QString payloadTrialRow(const PayloadTrial &t);

/// The last learned trial's estimate as `identify --payload` prints it, headed by its trial and
/// the bound; empty when no trial was learned from.
QString payloadResult(const PayloadSession &session);

} // namespace learnid::cli
