#pragma once

#include <Eigen/Core>
#include <QByteArray>
#include <QString>
#include <QStringList>

namespace learnid::cli {

/// What one validation log's plot shows: per joint (rows) the measured torque and the torques
/// two models predict, at the times t [s] (columns), all filtered alike (docs/identify.md).
struct TorquePlotData
{
    QString title;            ///< e.g. the validation log's file name
    QStringList jointNames;   ///< one per joint
    Eigen::VectorXd t;        ///< [s]
    Eigen::MatrixXd measured; ///< [N m] n x N
    Eigen::MatrixXd given;    ///< the URDF as given
    Eigen::MatrixXd identified;
};

/// The plot as PNG file content: one panel per joint on a shared time axis (measured black,
/// URDF as given grey, identified blue), each panel scaled to its own torques. Drawn with
/// QPainter on a QImage: learnid-cli has no windows, and a chart library would need widgets.
/// Text needs a QGuiApplication (imagesWanted()).
QByteArray torquePlotPng(const TorquePlotData &data);

/// Whether the command line asks for images (identify --plots or --report), so that main() makes a
/// QGuiApplication instead of a QCoreApplication; then, when no window system is named
/// (QT_QPA_PLATFORM, DISPLAY, WAYLAND_DISPLAY unset), it selects Qt's "offscreen" platform.
bool imagesWanted(int argc, char **argv);

} // namespace learnid::cli
