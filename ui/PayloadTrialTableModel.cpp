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
    case ComX:
    case ComY:
    case ComZ:
        *decimals = 1;
        return 1000.0 * r.com[column - ComX];
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
        return r.baseline && r.usable ? tr("kept: taken out of every payload trial") : r.message;
    QStringList names;
    const QStringList all = PayloadEstimate::bodyNames();
    for (int i = 0; i < 10; ++i)
        if (r.identified[size_t(i)])
            names << all.at(i);
    if (names.size() == 10)
        return tr("all");
    return names.isEmpty() ? tr("none (the prior)") : names.join(QStringLiteral(", "));
}

QVariant PayloadTrialTableModel::data(const QModelIndex &index, int role) const
{
    if (!index.isValid() || index.row() >= rowCount())
        return {};
    const PayloadTrialRow &r = m_rows[size_t(index.row())];
    const int column = index.column();
    if (column == Kind && role == Qt::DisplayRole)
        return r.baseline ? tr("baseline (no payload)") : tr("payload");
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
    if (role == Qt::DisplayRole)
        return std::isfinite(v) ? QString::number(v, 'f', decimals) : QStringLiteral("\u2013");
    return {};
}

QVariant PayloadTrialTableModel::headerData(int section, Qt::Orientation orientation,
                                            int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case Trial:
        return tr("Trial");
    case Kind:
        return tr("Kind");
    case MaxError:
        return tr("Max error [deg]");
    case RmsError:
        return tr("RMS error [deg]");
    case Mass:
        return tr("Mass [kg]");
    case ComX:
        return tr("CoM x [mm]");
    case ComY:
        return tr("CoM y [mm]");
    case ComZ:
        return tr("CoM z [mm]");
    case Update:
        return tr("Update [ms]");
    case Identified:
        return tr("Identified so far");
    }
    return {};
}

} // namespace learnid
