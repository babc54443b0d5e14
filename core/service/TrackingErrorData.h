#pragma once

#include "session/TrialResult.h"

#include <QList>
#include <QPointF>
#include <QVector>

namespace learnid {

/// One curve of a tracking-error plot: e_j(t) = q_d - q of one joint of one trial [deg] over
/// t [s], possibly decimated for display.
struct TrackingErrorCurve
{
    int trial = 0;
    int joint = 0; ///< 0-based
    TrialStatus status = TrialStatus::Completed;
    QList<QPointF> points;  ///< (t [s], e [deg])
    double maxAbsDeg = 0.0; ///< over all recorded samples, not only the displayed ones
};

/// The curves of one trial, one per joint, each with at most maxPoints points: min/max
/// decimation keeps every bucket's extremes, so peaks survive (maxPoints >= 4; 0 = all). The
/// default, 400 buckets, is about the width of the plot in pixels: more points draw no more.
QList<TrackingErrorCurve> trackingErrorCurves(const TrialResult &trial, int maxPoints = 800);
/// The same for trial `index` of any session: its plan's desired path against its record.
QList<TrackingErrorCurve> trackingErrorCurves(int index, const TrialPlan &plan,
                                              const TrialRecord &record, int maxPoints = 800);

/// Min/max decimation of a sampled curve to at most maxPoints points, in time order.
QList<QPointF> decimateMinMax(const QList<QPointF> &points, int maxPoints);

/// The axis of a tracking-error plot [deg]: symmetric about 0, a multiple of `grid`, with at
/// most maxTicks grid intervals (the interval becomes a multiple of grid when needed).
struct ErrorAxisRange
{
    double limit = 0.02;    ///< the axis spans [-limit, limit]
    double interval = 0.02; ///< grid spacing
};
ErrorAxisRange errorAxisRange(double maxAbsDeg, double grid = 0.02, int maxTicks = 12);

} // namespace learnid
