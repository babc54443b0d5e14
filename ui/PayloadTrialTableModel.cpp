#include "ui/PayloadTrialTableModel.h"

#include "identify/PayloadEstimate.h"

#include <QColor>
#include <cmath>
#include <limits>

namespace learnid {

PayloadTrialTableModel::PayloadTrialTableModel(QObject *parent)
    : QAbstractTableModel(parent)
{}

void PayloadTrialTableModel::addRow(const PayloadTrialRow &row)
{
    const int at = int(m_rows.size());
    beginInsertRows({}, at, at);
    m_rows.push_back(row);
    endInsertRows();
}

void PayloadTrialTableModel::clear()
{
    beginResetModel();
    m_rows.clear();
    endResetModel();
}

int PayloadTrialTableModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : int(m_rows.size());
}

int PayloadTrialTableModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : Identified + 1;
}

double PayloadTrialTableModel::number(const PayloadTrialRow &r, int column, int *decimals) const
{
    *decimals = 3;
    switch (column) {
    case Trial:
        *decimals = 0;
        return r.index;
    case MaxError:
        return r.maxTrackingErrorDeg;
    case RmsError:
        return r.rmsTrackingErrorDeg;
    case Mass:
        *decimals = 4;
        return r.mass;
    case Com:
        *decimals = 1;
        return 1000.0 * r.com.norm();
    case Update:
        *decimals = 1;
        return r.learned ? r.updateMs : std::numeric_limits<double>::quiet_NaN();
    default:
        return std::numeric_limits<double>::quiet_NaN();
    }
}

QString PayloadTrialTableModel::identifiedText(const PayloadTrialRow &r) const
{
    if (!r.learned)
        return r.baseline && r.usable ? tr("kept for the payload trials") : r.message;
    QStringList seen, kept;
    const QStringList all = PayloadEstimate::bodyNames();
    for (int i = 0; i < 10; ++i)
        (r.identified[size_t(i)] ? seen : kept) << all.at(i);
    if (kept.isEmpty())
        return tr("all");
    if (seen.isEmpty())
        return tr("none (the prior)");
    // The shorter list: a path that misses one inertia entry says so in a few words.
    return seen.size() > kept.size() ? tr("all but %1").arg(kept.join(QStringLiteral(", ")))
                                     : seen.join(QStringLiteral(", "));
}

QVariant PayloadTrialTableModel::data(const QModelIndex &index, int role) const
{
    if (!index.isValid() || index.row() >= rowCount())
        return {};
    const PayloadTrialRow &r = m_rows[size_t(index.row())];
    const int column = index.column();
    if (column == Kind) {
        if (role == Qt::ToolTipRole && r.partial)
            return r.message;
        return role == Qt::DisplayRole ? QVariant(r.baseline  ? tr("baseline")
                                                  : r.partial ? tr("payload, stopped")
                                                              : tr("payload"))
                                       : QVariant();
    }
    if (column == Identified) {
        if (role == Qt::DisplayRole || role == Qt::ToolTipRole)
            return identifiedText(r);
        if (role == Qt::ForegroundRole && !r.usable)
            return QColor(0xb3, 0x26, 0x1e);
        return {};
    }
    int decimals = 0;
    const double v = number(r, column, &decimals);
    if (role == Qt::UserRole)
        return v;
    if (role == Qt::TextAlignmentRole)
        return int(Qt::AlignRight | Qt::AlignVCenter);
    if (role == Qt::DisplayRole && column == Com && std::isfinite(v)) {
        // Rounded to 0.1 mm first, so that a rounding of zero shows no sign.
        const Eigen::Vector3d mm = (10000.0 * r.com).array().round() / 10.0 + 0.0;
        return QStringLiteral("(%1, %2, %3)")
            .arg(mm.x(), 0, 'f', 1)
            .arg(mm.y(), 0, 'f', 1)
            .arg(mm.z(), 0, 'f', 1);
    }
    if (role == Qt::DisplayRole)
        return std::isfinite(v) ? QString::number(v, 'f', decimals) : QStringLiteral("\u2013");
    return {};
}

QVariant PayloadTrialTableModel::headerData(int section, Qt::Orientation orientation,
                                            int role) const
{
    if (orientation != Qt::Horizontal)
        return {};
    if (role == Qt::ToolTipRole) {
        switch (section) {
        case Kind:
            return tr("A baseline trial runs the same timed path without the payload");
        case MaxError:
            return tr("The worst joint's maximum tracking error");
        case RmsError:
            return tr("The worst joint's RMS tracking error");
        case Mass:
        case Com:
            return tr("The payload fitted to the trials so far");
        case Update:
            return tr("CPU time of the payload's update");
        case Identified:
            return tr("The payload's values the trials so far identified; the others keep the "
                      "prior");
        }
        return {};
    }
    if (role != Qt::DisplayRole)
        return {};
    switch (section) {
    case Trial:
        return tr("Trial");
    case Kind:
        return tr("Kind");
    case MaxError:
        return tr("Max [deg]");
    case RmsError:
        return tr("RMS [deg]");
    case Mass:
        return tr("Mass [kg]");
    case Com:
        return tr("CoM [mm]");
    case Update:
        return tr("Update [ms]");
    case Identified:
        return tr("Identified");
    }
    return {};
}

} // namespace learnid
