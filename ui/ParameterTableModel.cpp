#include "ui/ParameterTableModel.h"

#include <QBrush>
#include <QFont>
#include <cmath>

namespace learnid {

namespace {

constexpr int kLeading = 3; ///< group, parameter, unit

} // namespace

ParameterTableModel::ParameterTableModel(QObject *parent)
    : QAbstractTableModel(parent)
{}

void ParameterTableModel::setParameters(const QList<ParameterInfo> &parameters,
                                        const std::optional<Eigen::VectorXd> &truth)
{
    beginResetModel();
    m_parameters = parameters;
    m_truth = truth;
    m_estimates.clear();
    m_newest.reset();
    m_figures = {};
    m_accepted.reset();
    endResetModel();
}

void ParameterTableModel::setEstimates(const QVector<Eigen::VectorXd> &estimates,
                                       const QVector<TrialResult> &history,
                                       const EstimateFigures &figures)
{
    beginResetModel();
    m_estimates = estimates;
    m_figures = figures;
    m_newest.reset();
    for (auto it = history.crbegin(); it != history.crend(); ++it) {
        if (it->update) {
            m_newest = it->update;
            break;
        }
    }
    endResetModel();
}

void ParameterTableModel::setAccepted(std::optional<int> estimateIndex)
{
    m_accepted = estimateIndex;
    if (rowCount() > 0)
        emit dataChanged(index(0, 0), index(rowCount() - 1, columnCount() - 1));
}

ParameterTableModel::Column ParameterTableModel::columnKind(int c, int *estimate) const
{
    const int e = int(m_estimates.size());
    if (estimate)
        *estimate = c >= kLeading && c < kLeading + e ? c - kLeading : 0;
    if (c < kLeading)
        return Column(c);
    if (c < kLeading + e)
        return Column::Estimate;
    return Column(int(Column::RelativeStd) + c - kLeading - e);
}

int ParameterTableModel::columnOf(Column kind, int estimate) const
{
    for (int c = 0; c < columnCount(); ++c) {
        int k = 0;
        if (columnKind(c, &k) == kind && k == estimate)
            return c;
    }
    return -1;
}

int ParameterTableModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : int(m_parameters.size());
}

int ParameterTableModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : kLeading + int(m_estimates.size()) + 3 + (m_truth ? 1 : 0);
}

QVariant ParameterTableModel::number(int i, Column kind, int k) const
{
    switch (kind) {
    case Column::Estimate:
        return i < m_estimates.at(k).size() ? QVariant(m_estimates.at(k)[i]) : QVariant();
    case Column::RelativeStd: {
        if (!m_newest || i >= m_newest->phiStd.size() || m_estimates.isEmpty())
            return {};
        const double phi = std::abs(m_estimates.constLast()[i]);
        const double std = m_newest->phiStd[i];
        if (!std::isfinite(std) || !(phi > 0.0))
            return {};
        return 100.0 * std / phi;
    }
    case Column::Truth:
        return m_truth && i < m_truth->size() ? QVariant((*m_truth)[i]) : QVariant();
    default:
        return {};
    }
}

QString ParameterTableModel::text(int i, Column kind, int k) const
{
    const ParameterInfo &p = m_parameters.at(i);
    switch (kind) {
    case Column::Group: // the group once, on its first row
        return i > 0 && m_parameters.at(i - 1).group == p.group ? QString() : p.group;
    case Column::Parameter:
        return p.name;
    case Column::Unit:
        return p.unit;
    case Column::Estimate:
    case Column::Truth: {
        const QVariant v = number(i, kind, k);
        return v.isValid() ? QString::number(v.toDouble(), 'g', 6) : QString();
    }
    case Column::RelativeStd: {
        const QVariant v = number(i, kind, k);
        if (v.isValid())
            return QString::number(v.toDouble(), 'f', 2);
        return m_newest && i < m_newest->phiStd.size() && !std::isfinite(m_newest->phiStd[i])
                   ? tr("kept")
                   : QStringLiteral("\u2013");
    }
    case Column::Observable:
        if (!m_newest || i >= int(m_newest->observable.size()))
            return QStringLiteral("\u2013");
        return m_newest->observable[size_t(i)] ? tr("yes") : tr("\u26a0 kept");
    case Column::Consistent:
        if (!m_figures.consistencyChecked || p.group.isEmpty())
            return QStringLiteral("\u2013");
        if (m_figures.inconsistentGroups.contains(p.group))
            return tr("\u2717 no");
        return m_figures.implausibleGroups.contains(p.group) ? tr("\u26a0 not plausible")
                                                             : tr("\u2713");
    }
    return {};
}

QVariant ParameterTableModel::data(const QModelIndex &index, int role) const
{
    if (!index.isValid() || index.row() >= m_parameters.size())
        return {};
    int k = 0;
    const int i = index.row();
    const Column kind = columnKind(index.column(), &k);
    switch (role) {
    case Qt::DisplayRole:
        return text(i, kind, k);
    case Qt::UserRole:
        return number(i, kind, k);
    case Qt::ToolTipRole:
        return kind == Column::Parameter || kind == Column::Group ? m_parameters.at(i).description
                                                                  : QVariant();
    case Qt::TextAlignmentRole:
        return int((kind == Column::Estimate || kind == Column::RelativeStd || kind == Column::Truth
                        ? Qt::AlignRight
                        : Qt::AlignLeft) |
                   Qt::AlignVCenter);
    case Qt::ForegroundRole: {
        const QString t = text(i, kind, k);
        if (t.startsWith(QChar(0x26a0)))
            return QBrush(QColor(0xb0, 0x60, 0x00));
        if (t.startsWith(QChar(0x2717)))
            return QBrush(QColor(0x8c, 0x1d, 0x18));
        return {};
    }
    case Qt::BackgroundRole:
        if (kind == Column::Estimate && m_accepted && *m_accepted == k)
            return QBrush(QColor(0xe3, 0xf1, 0xe3));
        return {};
    case Qt::FontRole:
        if (kind == Column::Estimate && m_accepted && *m_accepted == k) {
            QFont bold;
            bold.setBold(true);
            return bold;
        }
        return {};
    default:
        return {};
    }
}

QVariant ParameterTableModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation == Qt::Vertical || role != Qt::DisplayRole)
        return QAbstractTableModel::headerData(section, orientation, role);
    int k = 0;
    switch (columnKind(section, &k)) {
    case Column::Group:
        return tr("Link / joint");
    case Column::Parameter:
        return tr("Parameter");
    case Column::Unit:
        return tr("Unit");
    case Column::Estimate:
        return tr("Estimate %1").arg(k);
    case Column::RelativeStd:
        return tr("\u03c3 / |\u03c6| [%]");
    case Column::Observable:
        return tr("Observed");
    case Column::Consistent:
        return tr("Real body");
    case Column::Truth:
        return tr("Truth");
    }
    return {};
}

} // namespace learnid
