#include "service/TrackingErrorData.h"

#include <algorithm>
#include <cmath>

namespace learnid {

namespace {
constexpr double kRadToDeg = 180.0 / M_PI;
}

QList<QPointF> decimateMinMax(const QList<QPointF> &points, int maxPoints)
{
    if (maxPoints <= 0 || points.size() <= maxPoints)
        return points;
    const int buckets = std::max(2, maxPoints / 2);
    const qsizetype n = points.size();
    QList<QPointF> out;
    out.reserve(2 * buckets);
    for (int b = 0; b < buckets; ++b) {
        const qsizetype begin = n * b / buckets;
        const qsizetype end = n * (b + 1) / buckets;
        if (begin >= end)
            continue;
        qsizetype lo = begin, hi = begin;
        for (qsizetype i = begin + 1; i < end; ++i) {
            if (points[i].y() < points[lo].y())
                lo = i;
            if (points[i].y() > points[hi].y())
                hi = i;
        }
        out.append(points[std::min(lo, hi)]);
        if (lo != hi)
            out.append(points[std::max(lo, hi)]);
    }
    return out;
}

QList<TrackingErrorCurve> trackingErrorCurves(const TrialResult &trial, int maxPoints)
{
    return trackingErrorCurves(trial.index, trial.plan(), trial.record, maxPoints);
}

QList<TrackingErrorCurve> trackingErrorCurves(int index, const TrialPlan &plan,
                                              const TrialRecord &record, int maxPoints)
{
    QList<TrackingErrorCurve> curves;
    const Eigen::MatrixXd &desired = plan.desired.q;
    const int samples = std::min<int>(record.samples(), int(desired.cols()));
    const int n = std::min<int>(int(record.q.rows()), int(desired.rows()));
    const double ts = record.samplePeriod > 0 ? record.samplePeriod : plan.desired.samplePeriod;
    for (int j = 0; j < n; ++j) {
        TrackingErrorCurve curve;
        curve.trial = index;
        curve.joint = j;
        curve.status = record.status;
        QList<QPointF> all;
        all.reserve(samples);
        for (int k = 0; k < samples; ++k) {
            const double e = (desired(j, k) - record.q(j, k)) * kRadToDeg;
            if (!std::isfinite(e))
                continue;
            all.append(QPointF(k * ts, e));
            curve.maxAbsDeg = std::max(curve.maxAbsDeg, std::abs(e));
        }
        curve.points = decimateMinMax(all, maxPoints);
        curves.append(curve);
    }
    return curves;
}

ErrorAxisRange errorAxisRange(double maxAbsDeg, double grid, int maxTicks)
{
    ErrorAxisRange r;
    const double steps = std::max(1.0, std::ceil(maxAbsDeg / grid - 1e-9));
    r.limit = steps * grid;
    // 2 * steps intervals across the axis; widen the interval by whole grid multiples.
    const double factor = std::max(1.0, std::ceil(2.0 * steps / maxTicks));
    r.interval = grid * factor;
    r.limit = std::ceil(r.limit / r.interval - 1e-9) * r.interval;
    return r;
}

} // namespace learnid
