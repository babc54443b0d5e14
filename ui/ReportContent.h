#pragma once

#include "ui/ReportWriter.h"

namespace learnid {

class ConvergenceChart;
class ConvergenceTableModel;
class ParameterTableModel;
class SessionController;
class TrackingErrorPlot;

/// The views a report copies its tables and plots from.
struct ReportViews
{
    const ConvergenceTableModel *table = nullptr;
    const ParameterTableModel *parameters = nullptr;
    TrackingErrorPlot *plot = nullptr;
    ConvergenceChart *chart = nullptr;
};

/// What the commissioning report of the session shows: the scenario in words, the
/// convergence table as the window shows it, the plots, what the robot holds; and for an arm
/// with more parameters than the table has columns, the Parameters table on pages of its own.
ReportContent sessionReportContent(const SessionController &session, const ReportViews &views);

} // namespace learnid
