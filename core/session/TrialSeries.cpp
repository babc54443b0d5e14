#include "session/TrialSeries.h"

#include <QCoreApplication>
#include <algorithm>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(TrialSeries)
};

double maxErrorDeg(const TrialResult &t)
{
    return t.maxTrackingErrorDeg.size() > 0 ? t.maxTrackingErrorDeg.maxCoeff() : 0.0;
}

// Where on the path a trial stopped [s]: the time of its last recorded sample.
double stopTime(const TrialResult &t)
{
    return std::max(t.record.samples() - 1, 0) * t.record.samplePeriod;
}

bool isAbort(const TrialResult &t)
{
    return t.record.stoppedAtTrackingLimit();
}

bool tracksWorse(const TrialResult &t, const TrialResult &than)
{
    return maxErrorDeg(t) > (1.0 + worseTrackingMargin) * maxErrorDeg(than);
}

bool progressOver(const TrialResult &later, const TrialResult &earlier)
{
    return later.record.samples() > earlier.record.samples() ||
           maxErrorDeg(later) < maxErrorDeg(earlier);
}

} // namespace

TrialPlan planUpTo(const TrialPlan &plan, int samples)
{
    TrialPlan out = plan;
    samples = std::clamp(samples, 0, plan.samples());
    out.desired.q = plan.desired.q.leftCols(samples);
    out.desired.qd = plan.desired.qd.leftCols(samples);
    out.desired.qdd = plan.desired.qdd.leftCols(samples);
    out.feedforward =
        plan.feedforward.leftCols(std::min<Eigen::Index>(samples, plan.feedforward.cols()));
    return out;
}

QString seriesStopAfterAbort(const QVector<TrialResult> &earlier, const TrialResult &latest)
{
    if (!isAbort(latest))
        return {};
    QVector<const TrialResult *> inARow{&latest};
    for (qsizetype i = earlier.size() - 1; i >= 0 && isAbort(earlier.at(i)); --i)
        inARow.prepend(&earlier.at(i));
    if (inARow.size() < maxAbortsInARow)
        return {};
    for (qsizetype i = 1; i < inARow.size(); ++i) {
        const TrialResult &a = *inARow.at(i - 1);
        const TrialResult &b = *inARow.at(i);
        if (progressOver(b, a))
            continue;
        return Text::tr("Run all stops: %1 trials in a row stopped at the tracking limit, and "
                        "trial %2 was no progress over trial %3 (stopped at t = %4 s with %5 "
                        "deg, against t = %6 s with %7 deg)")
            .arg(inARow.size())
            .arg(b.index)
            .arg(a.index)
            .arg(stopTime(b), 0, 'f', 3)
            .arg(maxErrorDeg(b), 0, 'g', 4)
            .arg(stopTime(a), 0, 'f', 3)
            .arg(maxErrorDeg(a), 0, 'g', 4);
    }
    return {};
}

QVector<int> estimateIndices(const QVector<TrialResult> &history)
{
    QVector<int> out;
    int estimate = 0;
    for (const TrialResult &t : history) {
        out << estimate;
        if (t.learned())
            ++estimate;
    }
    return out;
}

std::optional<int> bestTrackingEstimate(const QVector<TrialResult> &history)
{
    const QVector<int> estimate = estimateIndices(history);
    std::optional<int> best;
    double bestError = 0.0;
    for (qsizetype i = 0; i < history.size(); ++i) {
        const TrialResult &t = history.at(i);
        if (!t.record.completed() || estimate.at(i) < 1)
            continue;
        if (!best || maxErrorDeg(t) < bestError) {
            best = estimate.at(i);
            bestError = maxErrorDeg(t);
        }
    }
    return best;
}

int proposedEstimate(const QVector<TrialResult> &history, int estimateCount)
{
    const int newest = estimateCount - 1;
    if (newest < 1)
        return 0;
    const std::optional<int> best = bestTrackingEstimate(history);
    const QVector<int> estimate = estimateIndices(history);
    for (qsizetype i = history.size() - 1; i >= 0; --i) {
        const TrialResult &t = history.at(i);
        if (!t.record.completed())
            continue;
        // The latest completed trial: if a learned estimate tracked better, propose that one.
        if (best && *best != estimate.at(i)) {
            for (qsizetype k = 0; k < history.size(); ++k)
                if (estimate.at(k) == *best && history.at(k).record.completed() &&
                    tracksWorse(t, history.at(k)))
                    return *best;
        }
        break;
    }
    return newest;
}

QString worseTrackingNote(const QVector<TrialResult> &earlier, const TrialResult &latest)
{
    if (!latest.record.completed() || latest.maxTrackingErrorDeg.size() == 0)
        return {};
    for (qsizetype i = earlier.size() - 1; i >= 0; --i) {
        const TrialResult &before = earlier.at(i);
        if (!before.record.completed())
            continue;
        if (!tracksWorse(latest, before))
            return {};
        QVector<TrialResult> all = earlier;
        all.append(latest);
        // What Accept will propose: an earlier learned estimate, or the newest (one past the
        // latest trial's), which the note does not name.
        const int newest = estimateIndices(all).constLast() + 1;
        const int proposal = proposedEstimate(all, newest + 1);
        const QString worse = Text::tr("trial %1 tracked worse than trial %2 (max %3 deg against "
                                       "%4 deg)")
                                  .arg(latest.index)
                                  .arg(before.index)
                                  .arg(maxErrorDeg(latest), 0, 'g', 4)
                                  .arg(maxErrorDeg(before), 0, 'g', 4);
        return proposal != newest ? Text::tr("%1; Accept proposes estimate %2, which tracked best")
                                        .arg(worse)
                                        .arg(proposal)
                                  : worse;
    }
    return {};
}

} // namespace learnid
