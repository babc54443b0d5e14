#pragma once

#include <QColor>
#include <QString>
#include <QStringList>

class QFontMetricsF;
class QValueAxis;

namespace learnid {

/// How the tracking-error plot tells joints and trials apart: each joint a colour of a fixed
/// qualitative palette (ten colours; from joint 11 on they repeat with a dashed, then a dotted
/// line), each trial of a joint a shade of that colour (later = darker, as later errors are
/// smaller).
QColor jointColor(int joint); ///< joint: 0-based
Qt::PenStyle jointPenStyle(int joint);
/// The shade of `base` for the order-th of `count` trials drawn (0 = the earliest, lightest).
QColor trialShade(const QColor &base, int order, int count);
/// "Joint 3" or, with a name, "Joint 3 (panda_joint3)" (joint: 0-based).
QString jointLabel(int joint, const QStringList &names);
/// The legend's labels of joints (0-based) side by side in width [px], each at most its share
/// less the marker (metrics: the legend's font): the longest form that fits them all, of
/// "Joint 3 (panda_joint3)", the names alone ("panda_joint3", when every joint has one),
/// "Joint 3", "3". QtCharts elides what does not fit ("Joint 1 (panda_join...").
QStringList fittedJointLabels(const QList<int> &joints, const QStringList &names,
                              const QFontMetricsF &metrics, qreal width);
/// The error axis's title in a plot height [px] high (metrics: the title's font): "Tracking
/// error [deg]", else "Error [deg]", else "[deg]".
QString fittedErrorAxisTitle(const QFontMetricsF &metrics, qreal height);

/// The time axis [s] over [0, tMax] with ticks at round steps.
void setTimeAxis(QValueAxis *axis, double tMax);
/// The error axis [deg]: symmetric on the paper's 0.02 deg grid for errors up to maxAbsDeg
/// (errorAxisRange), or auto-scaled: fitted to [yMin, yMax] with nice numbers.
/// maxTicks: at most this many grid intervals (fewer on a low plot, where more labels would not
/// fit and QtCharts would elide them all).
void setErrorAxis(QValueAxis *axis, bool autoScale, double maxAbsDeg, double yMin, double yMax,
                  int maxTicks = 12);

} // namespace learnid
