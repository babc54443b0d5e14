// Fuzz target: the robot log reader and the resampling behind it (core/io RobotLogCsv,
// core/identify UniformLog). The first byte chooses how the rest is read:
//   bits 0-1  joints - 1 (1 to 4)            bit 4  maxGap unbounded (+inf)
//   bit 2     all joints revolute (unit check) bit 5  period 1 ms instead of the median step
//   bit 3     useNominalTimes                  bit 6  the first line is a --columns spec
//                                              bit 7  the fit's filter at 200 rad/s, not 50
// The seeds start with a letter, so each has a --columns line: 'A' (0x41) two joints, 'E' the
// same with the unit check, 'I' with nominal times, 'Q' with no gap limit, 'a' at 1 ms. Bad input
// must end in a learnid::Error. An accepted log has consistent sizes, at least 4 samples, finite
// values, strictly increasing times and increasing line numbers, and its stale rows' lines
// increase, lie after the first sample and are none of the samples'; resampling it either throws
// Error or gives finite values on a grid within the log.

#include "FuzzSupport.h"

#include "identify/UniformLog.h"
#include "io/RobotLogCsv.h"
#include "model/Error.h"

#include <algorithm>
#include <cmath>
#include <limits>

using namespace learnid;

namespace {

void checkLog(const RobotLog &log, int joints)
{
    const Eigen::Index n = joints, samples = log.samples();
    if (log.q.rows() != n || log.q.cols() != samples || log.tau.rows() != n ||
        log.tau.cols() != samples || Eigen::Index(log.rows.size()) != samples ||
        (log.dq.size() != 0 && (log.dq.rows() != n || log.dq.cols() != samples)))
        fuzz::fuzzFailure("an accepted log has inconsistent sizes");
    if (samples < 4)
        fuzz::fuzzFailure("an accepted log has fewer than 4 samples");
    if (!log.t.allFinite() || !log.q.allFinite() || !log.dq.allFinite() || !log.tau.allFinite())
        fuzz::fuzzFailure("an accepted log holds a value that is not finite");
    for (Eigen::Index k = 1; k < samples; ++k) {
        if (!(log.t[k] > log.t[k - 1]))
            fuzz::fuzzFailure("the times of an accepted log do not increase",
                              QString::number(log.t[k], 'g', 17));
        if (log.rows[size_t(k)] <= log.rows[size_t(k) - 1])
            fuzz::fuzzFailure("the line numbers of an accepted log do not increase");
    }
    for (size_t i = 0; i < log.staleRows.size(); ++i) {
        const int line = log.staleRows[i];
        if ((i > 0 && line <= log.staleRows[i - 1]) || line <= log.rows.front() ||
            std::binary_search(log.rows.begin(), log.rows.end(), line))
            fuzz::fuzzFailure("the stale rows of an accepted log are not lines between samples",
                              QString::number(line));
    }
}

void checkUniform(const UniformLog &uniform, const RobotLog &log)
{
    if (!(uniform.period > 0.0) || !std::isfinite(uniform.period) || uniform.samples() < 2)
        fuzz::fuzzFailure("a resampled log has no period or fewer than 2 samples");
    if (uniform.dof() != log.dof() || uniform.tau.cols() != uniform.samples() ||
        uniform.dq.size() != (log.dq.size() == 0 ? 0 : log.dof() * uniform.samples()))
        fuzz::fuzzFailure("a resampled log has inconsistent sizes");
    if (!uniform.q.allFinite() || !uniform.dq.allFinite() || !uniform.tau.allFinite())
        fuzz::fuzzFailure("a resampled log holds a value that is not finite");
    const double last = uniform.time(uniform.samples() - 1);
    const double end = log.t[log.samples() - 1];
    const double rounding = 1e-6 * uniform.period + 1e-14 * (std::abs(log.t[0]) + std::abs(end));
    if (uniform.t0 != log.t[0] || last > end + rounding)
        fuzz::fuzzFailure("a resampled log reaches beyond the log",
                          QString::number(last, 'g', 17) + QStringLiteral(" > ") +
                              QString::number(end, 'g', 17));
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz::quietMessages();
    if (size == 0)
        return 0;
    const uint8_t control = data[0];
    QByteArray csv = fuzz::bytes(data + 1, size - 1);
    const int joints = 1 + (control & 0x03);
    const QList<bool> angular = (control & 0x04) ? QList<bool>(joints, true) : QList<bool>();
    ResampleOptions options;
    options.useNominalTimes = (control & 0x08) != 0;
    if (control & 0x10)
        options.maxGap = std::numeric_limits<double>::infinity();
    if (control & 0x20)
        options.period = 1e-3;
    if (control & 0x80)
        options.fitBandwidth = 200.0;

    LogColumns columns;
    if (control & 0x40) {
        const qsizetype end = csv.indexOf('\n');
        const QByteArray spec = end < 0 ? csv : csv.left(end);
        csv = end < 0 ? QByteArray() : csv.mid(end + 1);
        try {
            columns = parseLogColumns(QString::fromUtf8(spec));
        } catch (const Error &) {
            return 0;
        }
    }

    RobotLog log;
    try {
        log = readRobotLog(csv, QStringLiteral("fuzz.csv"), joints, columns, angular);
    } catch (const Error &) {
        return 0;
    }
    checkLog(log, joints);
    try {
        checkUniform(resampleUniform(log, options), log);
    } catch (const Error &) {
    }
    return 0;
}
