#include "ui/PayloadEstimateTableModel.h"

#include <QColor>
#include <cmath>
#include <limits>

namespace learnid {

namespace {

// The body's values in bodyValue's order: mass, c x y z, I_c xx xy yy xz yz zz.
double displayScale(int row)
{
    return row >= 1 && row <= 3 ? 1000.0 : 1.0; // the centre of mass in mm
}

} // namespace

PayloadEstimateTableModel::PayloadEstimateTableModel(QObject *parent)
    : QAbstractTableModel(parent)
{}

void PayloadEstimateTableModel::setEstimate(const PayloadEstimate &e)
{
    beginResetModel();
    const PayloadBody prior = payloadBody(e.prior);
    const Eigen::Matrix3d &i = prior.inertiaAtCom;
    m_prior = {prior.mass, prior.com.x(), prior.com.y(), prior.com.z(), i(0, 0),
               i(0, 1),    i(1, 1),       i(0, 2),       i(1, 2),       i(2, 2)};
    m_value = e.bodyValue;
    m_error = e.bodyStandardError;
    m_identified = e.bodyIdentified;
    m_shown = true;
    endResetModel();
}

void PayloadEstimateTableModel::clear()
{
    beginResetModel();
    m_shown = false;
    endResetModel();
}

int PayloadEstimateTableModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() || !m_shown ? 0 : 10;
}

int PayloadEstimateTableModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : Source + 1;
}

double PayloadEstimateTableModel::number(int row, int column) const
{
    const size_t k = size_t(row);
    const double scale = displayScale(row);
    switch (column) {
    case Estimate:
        return scale * m_value[k];
    case StandardError:
        return m_identified[k] && std::isfinite(m_error[k])
                   ? scale * m_error[k]
                   : std::numeric_limits<double>::quiet_NaN();
    case Prior:
        return scale * m_prior[k];
    default:
        return std::numeric_limits<double>::quiet_NaN();
    }
}

QVariant PayloadEstimateTableModel::data(const QModelIndex &index, int role) const
{
    if (!index.isValid() || index.row() >= rowCount())
        return {};
    const int row = index.row();
    const int column = index.column();
    const bool seen = m_identified[size_t(row)];
    if (column == Value && role == Qt::DisplayRole)
        return PayloadEstimate::bodyNames().at(row);
    if (column == Unit && role == Qt::DisplayRole)
        return row == 0 ? QStringLiteral("kg")
                        : (row < 4 ? QStringLiteral("mm") : QStringLiteral("kg m\u00b2"));
    if (column == Source) {
        if (role == Qt::DisplayRole)
            return seen ? tr("data (the trials)") : tr("prior (not identified)");
        if (role == Qt::ForegroundRole && !seen)
            return QColor(0x8a, 0x5a, 0x00);
        return {};
    }
    if (column == Value || column == Unit)
        return {};
    const double v = number(row, column);
    if (role == Qt::UserRole)
        return v;
    if (role == Qt::TextAlignmentRole)
        return int(Qt::AlignRight | Qt::AlignVCenter);
    if (role == Qt::DisplayRole) {
        if (!std::isfinite(v))
            return QStringLiteral("\u2013");
        return QString::number(std::abs(v) < 1e-12 ? 0.0 : v, 'g', column == StandardError ? 2 : 5);
    }
    return {};
}

QVariant PayloadEstimateTableModel::headerData(int section, Qt::Orientation orientation,
                                               int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case Value:
        return tr("Value");
    case Unit:
        return tr("Unit");
    case Estimate:
        return tr("Estimate");
    case StandardError:
        return tr("Std. error");
    case Prior:
        return tr("Prior");
    case Source:
        return tr("From");
    }
    return {};
}

} // namespace learnid
