#include "ui/LogValidationTableModel.h"

#include <QBrush>
#include <QColor>
#include <QFont>
#include <cmath>
#include <limits>

namespace learnid {

namespace {
constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
} // namespace

LogValidationTableModel::LogValidationTableModel(QObject *parent)
    : QAbstractTableModel(parent)
{}

void LogValidationTableModel::setFigures(const QStringList &jointNames, const TorqueFigures &given,
                                         const TorqueFigures &identified)
{
    beginResetModel();
    m_joints = jointNames;
    m_given = given;
    m_identified = identified;
    endResetModel();
}

void LogValidationTableModel::clear()
{
    beginResetModel();
    m_joints.clear();
    m_given = {};
    m_identified = {};
    endResetModel();
}

LogValidationTableModel::Row LogValidationTableModel::rowKind(int row) const
{
    if (row < m_joints.size())
        return Row::Joint;
    return row == overallRow() ? Row::Overall : Row::MeanRatio;
}

int LogValidationTableModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() || m_joints.isEmpty() ? 0 : int(m_joints.size()) + 2;
}

int LogValidationTableModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : IdentifiedRatio + 1;
}

double LogValidationTableModel::number(int row, int column, int *decimals) const
{
    const Row kind = rowKind(row);
    if (kind == Row::Overall) {
        *decimals = 3; // as learnid-cli prints it
        return column == GivenRatio        ? 100.0 * m_given.overall
               : column == IdentifiedRatio ? 100.0 * m_identified.overall
                                           : kNone;
    }
    *decimals = 1;
    if (kind == Row::MeanRatio) {
        return column == GivenRatio        ? 100.0 * m_given.meanRatio
               : column == IdentifiedRatio ? 100.0 * m_identified.meanRatio
                                           : kNone;
    }
    if (column != GivenRatio && column != IdentifiedRatio)
        *decimals = 4;
    switch (column) {
    case RmsMeasured:
        return m_given.rmsMeasured[row];
    case GivenError:
        return m_given.rmsError[row];
    case GivenRatio:
        return 100.0 * m_given.ratio(row);
    case IdentifiedError:
        return m_identified.rmsError[row];
    case IdentifiedRatio:
        return 100.0 * m_identified.ratio(row);
    default:
        return kNone;
    }
}

QVariant LogValidationTableModel::data(const QModelIndex &index, int role) const
{
    if (!index.isValid())
        return {};
    const int row = index.row(), column = index.column();
    const Row kind = rowKind(row);
    if (role == Qt::FontRole) {
        QFont f;
        f.setBold(kind == Row::Overall || (column == Joint && kind != Row::Joint));
        return f;
    }
    if (column == Joint) {
        if (role == Qt::ToolTipRole && kind == Row::Overall)
            return tr("sqrt(sum e^2 / sum tau^2) over the joints and samples, in %");
        if (role == Qt::ToolTipRole && kind == Row::MeanRatio)
            return tr("The mean over the joints of RMS error / RMS measured, in %");
        if (role != Qt::DisplayRole)
            return {};
        if (kind == Row::Overall)
            return tr("overall %");
        if (kind == Row::MeanRatio)
            return tr("mean ratio %");
        return QStringLiteral("%1 %2").arg(row + 1).arg(m_joints.at(row));
    }
    int decimals = 0;
    const double v = number(row, column, &decimals);
    switch (role) {
    case Qt::DisplayRole:
        return std::isnan(v) ? QString() : QString::number(v, 'f', decimals);
    case Qt::UserRole:
        return std::isnan(v) ? QVariant() : QVariant(v);
    case Qt::TextAlignmentRole:
        return int(Qt::AlignRight | Qt::AlignVCenter);
    case Qt::ForegroundRole: {
        // The identified ratio in green where it predicts better than the URDF as given.
        if (column != IdentifiedRatio || std::isnan(v))
            return {};
        const double given = number(row, GivenRatio, &decimals);
        return QBrush(v < given ? QColor(0x1e, 0x7b, 0x34) : QColor(0xb0, 0x3a, 0x2e));
    }
    default:
        return {};
    }
}

QVariant LogValidationTableModel::headerData(int section, Qt::Orientation orientation,
                                             int role) const
{
    if (orientation == Qt::Vertical || role != Qt::DisplayRole)
        return QAbstractTableModel::headerData(section, orientation, role);
    switch (section) {
    case Joint:
        return tr("Joint");
    case RmsMeasured:
        return tr("RMS measured\n[N m]");
    case GivenError:
        return tr("URDF as given\nRMS error [N m]");
    case GivenRatio:
        return tr("URDF as given\nratio %");
    case IdentifiedError:
        return tr("Identified\nRMS error [N m]");
    case IdentifiedRatio:
        return tr("Identified\nratio %");
    default:
        return {};
    }
}

} // namespace learnid
