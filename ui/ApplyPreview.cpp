#include "ui/ApplyPreview.h"

#include "ui/ConvergenceTableModel.h"

#include <QCoreApplication>
#include <QStringList>
#include <cmath>

namespace learnid {

std::optional<double> ApplyPreview::relativeChange(int i) const
{
    if (i < 0 || i >= oldValues.size() || i >= newValues.size() || oldValues[i] == 0.0)
        return std::nullopt;
    return (newValues[i] - oldValues[i]) / std::abs(oldValues[i]);
}

QString parameterSetText(const Eigen::VectorXd &values)
{
    if (values.size() > ConvergenceTableModel::maxParameterColumns)
        return QCoreApplication::translate("learnid::SessionPresenter", "%n parameter(s)", nullptr,
                                           int(values.size()));
    QStringList parts;
    for (Eigen::Index i = 0; i < values.size(); ++i)
        parts << QString::number(values[i], 'g', 6);
    return parts.join(QStringLiteral(", "));
}

} // namespace learnid
