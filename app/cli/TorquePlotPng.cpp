#include "cli/TorquePlotPng.h"

#include <QBuffer>
#include <QCoreApplication>
#include <QImage>
#include <QPainter>
#include <QPainterPath>
#include <algorithm>
#include <cmath>
#include <cstring>

namespace learnid::cli {

namespace {

constexpr int width = 1200;
constexpr int panelHeight = 170;
constexpr int top = 56;    ///< title and legend
constexpr int bottom = 40; ///< time axis labels
constexpr int left = 90;   ///< torque labels
constexpr int right = 20;
constexpr int gap = 14; ///< between panels

// A "nice" step for about `ticks` ticks over span: 1, 2 or 5 times a power of ten.
double niceStep(double span, int ticks)
{
    const double raw = span / std::max(ticks, 1);
    const double power = std::pow(10.0, std::floor(std::log10(raw)));
    for (const double m : {1.0, 2.0, 5.0, 10.0}) {
        if (m * power >= raw)
            return m * power;
    }
    return 10.0 * power;
}

// The smallest step of 1, 2 or 5 times a power of ten that puts at most `ticks` ticks on
// [low, high] widened to whole steps.
double torqueTick(double low, double high, int ticks)
{
    const double span = std::max(high - low, 1e-12);
    double step = std::pow(10.0, std::floor(std::log10(span / ticks)) - 1.0);
    const auto count = [&](double s) {
        return std::ceil(high / s - 1e-9) - std::floor(low / s + 1e-9) + 1.0;
    };
    for (int i = 0; count(step) > ticks && i < 12; ++i)
        step *= i % 3 == 1 ? 2.5 : 2.0; // 1, 2, 5, 10, 20, 50, ...
    return step;
}

// A tick's label with the digits that tell it from its neighbours `tick` apart (0.6, 0.61,
// 0.62, not 0.6, 0.61, 0.62 from 'g' with 3 digits only up to 0.615).
QString tickLabel(double v, double tick, double largest)
{
    if (std::abs(v) < 1e-9 * tick)
        v = 0.0; // not "-0.00"
    const int decimals = std::max(0, int(-std::floor(std::log10(tick) + 1e-9)));
    if (decimals <= 4)
        return QString::number(v, 'f', decimals);
    const int digits = int(std::floor(std::log10(std::max(largest, tick)) + 1e-9)) -
                       int(std::floor(std::log10(tick) + 1e-9)) + 1;
    return QString::number(v, 'g', std::max(digits, 1));
}

void drawSeries(QPainter &p, const QRectF &r, const Eigen::VectorXd &t, const Eigen::RowVectorXd &y,
                double lo, double hi, const QPen &pen)
{
    if (t.size() < 2)
        return;
    const double t0 = t[0];
    const double span = std::max(t[t.size() - 1] - t0, 1e-12);
    QPainterPath path;
    // At most a few points per pixel: the image shows no more.
    const Eigen::Index step = std::max<Eigen::Index>(1, t.size() / (4 * Eigen::Index(r.width())));
    for (Eigen::Index k = 0; k < t.size(); k += step) {
        const QPointF point(r.left() + (t[k] - t0) / span * r.width(),
                            r.bottom() - (y[k] - lo) / (hi - lo) * r.height());
        if (k == 0)
            path.moveTo(point);
        else
            path.lineTo(point);
    }
    p.setPen(pen);
    p.drawPath(path);
}

void drawPanel(QPainter &p, const QRectF &r, const TorquePlotData &d, int joint, bool last)
{
    const Eigen::RowVectorXd m = d.measured.row(joint);
    const Eigen::RowVectorXd g = d.given.row(joint);
    const Eigen::RowVectorXd i = d.identified.row(joint);
    double lo = std::min({m.minCoeff(), g.minCoeff(), i.minCoeff()});
    double hi = std::max({m.maxCoeff(), g.maxCoeff(), i.maxCoeff()});
    const double margin = std::max(0.05 * (hi - lo), 1e-6);
    // The range widened to whole ticks, as many as fit (7 in a panel): every panel has 3 labels
    // at least. A step chosen from the span alone could leave one inside the range ("0").
    const double tick = torqueTick(lo - margin, hi + margin, 7);
    lo = std::floor((lo - margin) / tick + 1e-9) * tick;
    hi = std::ceil((hi + margin) / tick - 1e-9) * tick;
    p.setPen(QPen(QColor(200, 200, 200), 1));
    p.drawRect(r);
    p.setFont(QFont(p.font().family(), 9));
    for (double v = lo; v <= hi + 1e-9 * tick; v += tick) {
        const double y = r.bottom() - (v - lo) / (hi - lo) * r.height();
        p.setPen(QPen(QColor(225, 225, 225), 1));
        p.drawLine(QPointF(r.left(), y), QPointF(r.right(), y));
        p.setPen(Qt::black);
        p.drawText(QRectF(0, y - 8, left - 6, 16), Qt::AlignRight | Qt::AlignVCenter,
                   tickLabel(v, tick, std::max(std::abs(lo), std::abs(hi))));
    }
    const double t0 = d.t[0];
    const double span = std::max(d.t[d.t.size() - 1] - t0, 1e-12);
    const double ttick = niceStep(span, 10);
    for (double v = std::ceil(t0 / ttick) * ttick; v <= t0 + span; v += ttick) {
        const double x = r.left() + (v - t0) / span * r.width();
        p.setPen(QPen(QColor(225, 225, 225), 1));
        p.drawLine(QPointF(x, r.top()), QPointF(x, r.bottom()));
        if (last) {
            p.setPen(Qt::black);
            p.drawText(QRectF(x - 30, r.bottom() + 4, 60, 16), Qt::AlignCenter,
                       QString::number(v, 'g', 4));
        }
    }
    p.setRenderHint(QPainter::Antialiasing, true);
    drawSeries(p, r, d.t, g, lo, hi, QPen(QColor(150, 150, 150), 1.4, Qt::DashLine));
    drawSeries(p, r, d.t, m, lo, hi, QPen(Qt::black, 1.4));
    drawSeries(p, r, d.t, i, lo, hi, QPen(QColor(30, 90, 200), 1.6));
    p.setRenderHint(QPainter::Antialiasing, false);
    p.setPen(Qt::black);
    p.drawText(QRectF(r.left() + 6, r.top() + 2, r.width() - 12, 16), Qt::AlignLeft,
               QCoreApplication::translate("learnid-cli", "joint %1 (%2) [N m]")
                   .arg(joint + 1)
                   .arg(d.jointNames.value(joint)));
}

} // namespace

QByteArray torquePlotPng(const TorquePlotData &d)
{
    const int n = int(d.measured.rows());
    const int height = top + n * panelHeight + (n - 1) * gap + bottom;
    QImage image(width, height, QImage::Format_RGB32);
    image.fill(Qt::white);
    {
        QPainter p(&image);
        p.setFont(QFont(p.font().family(), 11, QFont::Bold));
        p.drawText(QRectF(left, 6, width - left - right, 20), Qt::AlignLeft, d.title);
        p.setFont(QFont(p.font().family(), 9));
        const struct
        {
            QString name;
            QPen pen;
        } legend[] = {
            {QCoreApplication::translate("learnid-cli", "measured"), QPen(Qt::black, 2)},
            {QCoreApplication::translate("learnid-cli", "URDF as given"),
             QPen(QColor(150, 150, 150), 2, Qt::DashLine)},
            {QCoreApplication::translate("learnid-cli", "identified"),
             QPen(QColor(30, 90, 200), 2)},
        };
        int x = left;
        for (const auto &item : legend) {
            p.setPen(item.pen);
            p.drawLine(x, 38, x + 30, 38);
            p.setPen(Qt::black);
            p.drawText(QRect(x + 36, 30, 200, 16), Qt::AlignLeft | Qt::AlignVCenter, item.name);
            x += 60 + p.fontMetrics().horizontalAdvance(item.name);
        }
        for (int j = 0; j < n; ++j) {
            const QRectF r(left, top + j * (panelHeight + gap), width - left - right, panelHeight);
            drawPanel(p, r, d, j, j == n - 1);
        }
        p.drawText(QRectF(left, height - 18, width - left - right, 16), Qt::AlignCenter,
                   QCoreApplication::translate("learnid-cli", "t [s]"));
    }
    QByteArray png;
    QBuffer buffer(&png);
    buffer.open(QIODevice::WriteOnly);
    image.save(&buffer, "PNG");
    return png;
}

bool imagesWanted(int argc, char **argv)
{
    bool identify = false;
    bool images = false;
    for (int i = 1; i < argc; ++i) {
        identify = identify || std::strcmp(argv[i], "identify") == 0;
        images = images || std::strncmp(argv[i], "--plots", 7) == 0 ||
                 std::strncmp(argv[i], "--report", 8) == 0;
    }
    if (!(identify && images))
        return false;
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM") && qEnvironmentVariableIsEmpty("DISPLAY") &&
        qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    return true;
}

} // namespace learnid::cli
