#include "ui/TrackingErrorStyle.h"

#include "service/TrackingErrorData.h"

#include <QCoreApplication>
#include <QtCharts/QValueAxis>
#include <algorithm>

namespace learnid {

namespace {

// Matplotlib's "tab10", a qualitative palette made to tell up to ten lines apart (and readable
// on white: no pale yellow among the first seven, the joints of a 7-axis arm).
const QColor kPalette[] = {QColor(0x1f, 0x77, 0xb4), QColor(0xff, 0x7f, 0x0e),
                           QColor(0x2c, 0xa0, 0x2c), QColor(0xd6, 0x27, 0x28),
                           QColor(0x94, 0x67, 0xbd), QColor(0x8c, 0x56, 0x4b),
                           QColor(0xe3, 0x77, 0xc2), QColor(0x7f, 0x7f, 0x7f),
                           QColor(0xbc, 0xbd, 0x22), QColor(0x17, 0xbe, 0xcf)};
constexpr int kPaletteSize = int(sizeof(kPalette) / sizeof(kPalette[0]));

} // namespace

QColor jointColor(int joint)
{
    return kPalette[std::max(0, joint) % kPaletteSize];
}

Qt::PenStyle jointPenStyle(int joint)
{
    static const Qt::PenStyle styles[] = {Qt::SolidLine, Qt::DashLine, Qt::DotLine};
    return styles[(std::max(0, joint) / kPaletteSize) % 3];
}

QColor trialShade(const QColor &base, int order, int count)
{
    // f = 0 for the earliest trial (blended 65 % towards white), 1 for the latest (the colour
    // darkened by a third).
    const double f = count > 1 ? double(order) / (count - 1) : 1.0;
    const double white = 0.65 * (1.0 - f);
    const QColor blended = QColor::fromRgbF(float(base.redF() + white * (1.0 - base.redF())),
                                            float(base.greenF() + white * (1.0 - base.greenF())),
                                            float(base.blueF() + white * (1.0 - base.blueF())));
    return blended.darker(100 + int(50 * f));
}

QString jointLabel(int joint, const QStringList &names)
{
    const QString name = joint >= 0 && joint < names.size() ? names.at(joint) : QString();
    if (name.isEmpty())
        return QCoreApplication::translate("learnid::TrackingErrorPlot", "Joint %1").arg(joint + 1);
    return QCoreApplication::translate("learnid::TrackingErrorPlot", "Joint %1 (%2)")
        .arg(joint + 1)
        .arg(name);
}

void setTimeAxis(QValueAxis *axis, double tMax)
{
    const double span = tMax > 0 ? tMax : 1.0;
    axis->setRange(0.0, span);
    axis->setTickType(QValueAxis::TicksDynamic);
    axis->setTickAnchor(0.0);
    axis->setTickInterval(span > 8 ? 2.0 : span > 3 ? 0.5 : 0.25);
    axis->setLabelFormat(span > 3 ? QStringLiteral("%.1f") : QStringLiteral("%.2f"));
}

void setErrorAxis(QValueAxis *axis, bool autoScale, double maxAbsDeg, double yMin, double yMax,
                  int maxTicks)
{
    if (autoScale) {
        axis->setTickType(QValueAxis::TicksFixed);
        const double pad = std::max(1e-6, 0.05 * (yMax - yMin));
        axis->setRange(yMin - pad, yMax + pad);
        axis->applyNiceNumbers();
        axis->setLabelFormat(QStringLiteral("%.3g"));
    } else {
        const ErrorAxisRange r = errorAxisRange(maxAbsDeg, 0.02, maxTicks);
        axis->setRange(-r.limit, r.limit);
        axis->setTickType(QValueAxis::TicksDynamic);
        axis->setTickAnchor(0.0);
        axis->setTickInterval(r.interval);
        axis->setLabelFormat(QStringLiteral("%.2f"));
    }
}

} // namespace learnid
