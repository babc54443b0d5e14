#include "ui/TrackingErrorStyle.h"

#include "service/TrackingErrorData.h"

#include <QCoreApplication>
#include <QFontMetricsF>
#include <QtCharts/QValueAxis>
#include <algorithm>
#include <functional>

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

QStringList fittedJointLabels(const QList<int> &joints, const QStringList &names,
                              const QFontMetricsF &metrics, qreal width)
{
    bool allNamed = true;
    for (const int j : joints)
        allNamed = allNamed && j >= 0 && j < names.size() && !names.at(j).isEmpty();
    QList<std::function<QString(int)>> forms{[&names](int j) {
        return jointLabel(j, names);
    }};
    if (allNamed)
        forms.append([&names](int j) { return names.at(j); });
    forms.append([](int j) {
        return QCoreApplication::translate("learnid::TrackingErrorPlot", "Joint %1").arg(j + 1);
    });
    forms.append([](int j) { return QString::number(j + 1); });
    // Each entry: its marker (a square of the font's height) and spacing around it and the text.
    const qreal share = width / qreal(std::max<qsizetype>(1, joints.size()));
    const qreal textWidth = share - 2.0 * metrics.height() - 8.0;
    QStringList labels;
    for (const auto &form : std::as_const(forms)) {
        labels.clear();
        bool fits = true;
        for (const int j : joints) {
            labels.append(form(j));
            fits = fits && metrics.horizontalAdvance(labels.constLast()) <= textWidth;
        }
        if (fits)
            break;
    }
    return labels; // the shortest form when none fits
}

QString fittedErrorAxisTitle(const QFontMetricsF &metrics, qreal height)
{
    const QString titles[] = {
        QCoreApplication::translate("learnid::TrackingErrorPlot", "Tracking error [deg]"),
        QCoreApplication::translate("learnid::TrackingErrorPlot", "Error [deg]")};
    for (const QString &title : titles)
        if (metrics.horizontalAdvance(title) + metrics.height() <= height)
            return title;
    return QCoreApplication::translate("learnid::TrackingErrorPlot", "[deg]");
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
