#include "ui/ConvergenceTableModel.h"

#include "session/ConvergenceFigures.h"

#include <QBrush>
#include <QFont>
#include <cmath>

namespace learnid {

ConvergenceTableModel::ConvergenceTableModel(QObject *parent)
    : QAbstractTableModel(parent)
{}

void ConvergenceTableModel::setParameters(const QList<ParameterInfo> &parameters,
                                          const std::optional<Eigen::VectorXd> &truth)
{
    beginResetModel();
    m_parameters = parameters;
    m_truth = truth;
    endResetModel();
}

void ConvergenceTableModel::setHistory(const QVector<TrialResult> &history,
                                       const QVector<Eigen::VectorXd> &estimates)
{
    beginResetModel();
    // Shared with the caller: the window's history holds no samples (trialSummary), so the
    // copy its next append makes is of figures only.
    m_history = history;
    m_estimates = estimates;
    m_trialsWith = QVector<QVector<int>>(estimates.size());
    m_producer = QVector<int>(estimates.size(), -1);
    int k = 0;
    for (int i = 0; i < history.size(); ++i) {
        if (k < m_trialsWith.size())
            m_trialsWith[k].append(i);
        if (history.at(i).learned() && k + 1 < m_producer.size())
            m_producer[++k] = i;
    }
    endResetModel();
}

void ConvergenceTableModel::setFigures(const EstimateFigures &figures)
{
    // The same rows and columns: a change of cells, not of the table (no second reset after
    // setHistory's, which would size the view's columns again).
    m_figures = figures;
    const int column = columnOf(Column::PathTorque);
    if (column >= 0 && rowCount() > 0)
        emit dataChanged(index(0, column), index(rowCount() - 1, column));
}

int ConvergenceTableModel::shownParameters() const
{
    return m_parameters.size() <= maxParameterColumns ? int(m_parameters.size()) : 0;
}

void ConvergenceTableModel::setAccepted(std::optional<int> estimateIndex)
{
    m_accepted = estimateIndex;
    if (rowCount() > 0)
        emit dataChanged(index(0, 0), index(rowCount() - 1, columnCount() - 1));
}

void ConvergenceTableModel::setApplied(int estimateIndex)
{
    m_applied = estimateIndex;
    if (rowCount() > 0)
        emit dataChanged(index(0, 0), index(rowCount() - 1, columnCount() - 1));
}

const TrialResult *ConvergenceTableModel::producer(int k) const
{
    if (k < 1 || k >= m_producer.size() || m_producer.at(k) < 0)
        return nullptr;
    return &m_history.at(m_producer.at(k));
}

ConvergenceTableModel::Column ConvergenceTableModel::columnKind(int c, int *parameter) const
{
    const int m = shownParameters();
    const int truth = m_truth ? m : 0;
    const int path = m_truth && m == 0 ? 1 : 0; // the path-torque error instead
    int p = 0;
    Column kind;
    if (c == 0)
        kind = Column::Estimate;
    else if (c <= m)
        kind = Column::Parameter, p = c - 1;
    else if (c == m + 1)
        kind = Column::RelativeChange;
    else if (c == m + 2)
        kind = Column::MaxError;
    else if (c == m + 3)
        kind = Column::Condition;
    else if (c == m + 4)
        kind = Column::Observable;
    else if (c < m + 5 + truth)
        kind = Column::TruthError, p = c - m - 5;
    else if (c < m + 5 + truth + path)
        kind = Column::PathTorque;
    else if (c == m + 5 + truth + path)
        kind = Column::Trials;
    else
        kind = Column::State;
    if (parameter)
        *parameter = p;
    return kind;
}

int ConvergenceTableModel::columnOf(Column kind, int parameter) const
{
    for (int c = 0; c < columnCount(); ++c) {
        int p = 0;
        if (columnKind(c, &p) == kind && p == parameter)
            return c;
    }
    return -1;
}

int ConvergenceTableModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : int(m_estimates.size());
}

int ConvergenceTableModel::columnCount(const QModelIndex &parent) const
{
    if (parent.isValid())
        return 0;
    const int m = shownParameters();
    return 1 + m + 4 + (m_truth ? std::max(m, 1) : 0) + 2;
}

QVariant ConvergenceTableModel::number(int k, Column kind, int p) const
{
    const Eigen::VectorXd &phi = m_estimates.at(k);
    const TrialResult *made = producer(k);
    switch (kind) {
    case Column::Estimate:
        return k;
    case Column::Parameter:
        return p < phi.size() ? QVariant(phi[p]) : QVariant();
    case Column::RelativeChange:
        if (k == 0)
            return {};
        return largestRelativeDifferencePercent(phi, m_estimates.at(k - 1));
    case Column::MaxError:
        for (auto it = m_trialsWith.at(k).crbegin(); it != m_trialsWith.at(k).crend(); ++it) {
            const TrialResult &t = m_history.at(*it);
            if (t.maxTrackingErrorDeg.size() > 0)
                return t.maxTrackingErrorDeg.maxCoeff();
        }
        return {};
    case Column::Condition:
        return made && made->update ? QVariant(made->update->condition) : QVariant();
    case Column::TruthError:
        if (!m_truth || p >= m_truth->size() || (*m_truth)[p] == 0.0)
            return {};
        return 100.0 * (phi[p] - (*m_truth)[p]) / (*m_truth)[p];
    case Column::PathTorque:
        return k < m_figures.vsTruth.size() ? QVariant(m_figures.vsTruth.at(k)) : QVariant();
    default:
        return {};
    }
}

QString ConvergenceTableModel::text(int k, Column kind, int p) const
{
    const QVariant v = number(k, kind, p);
    const TrialResult *made = producer(k);
    switch (kind) {
    case Column::Estimate:
        return QString::number(k);
    case Column::Parameter:
        return v.isValid() ? QString::number(v.toDouble(), 'f', 4) : QString();
    case Column::RelativeChange:
        return v.isValid() ? QString::number(v.toDouble(), 'f', 2) : QStringLiteral("\u2013");
    case Column::MaxError:
        return v.isValid() ? QString::number(v.toDouble(), 'f', 4) : QStringLiteral("\u2013");
    case Column::Condition:
        if (!v.isValid())
            return QStringLiteral("\u2013");
        return std::isfinite(v.toDouble()) ? QString::number(v.toDouble(), 'f', 1)
                                           : QStringLiteral("\u221e");
    case Column::Observable: {
        if (!made || !made->update)
            return QStringLiteral("\u2013");
        QStringList kept;
        const std::vector<bool> &obs = made->update->observable;
        for (int i = 0; i < int(obs.size()) && i < m_parameters.size(); ++i)
            if (!obs[i])
                kept << m_parameters.at(i).name;
        if (kept.isEmpty())
            return tr("all (rank %1)").arg(made->update->rank);
        if (kept.size() > maxParameterColumns) // the Parameters table marks which
            return tr("\u26a0 kept %1 of %2").arg(kept.size()).arg(m_parameters.size());
        return tr("\u26a0 kept: %1").arg(kept.join(QStringLiteral(", ")));
    }
    case Column::TruthError:
        return v.isValid() ? QString::asprintf("%+.3f", v.toDouble()) : QString();
    case Column::PathTorque:
        return v.isValid() ? QString::number(v.toDouble(), 'f', 3) : QStringLiteral("\u2013");
    case Column::Trials: {
        QStringList trials;
        for (int i : m_trialsWith.at(k)) {
            const TrialResult &t = m_history.at(i);
            trials << (t.status() == TrialStatus::Completed ? QString::number(t.index)
                       : t.learnedFromPartial()
                           ? tr("%1 (learned from a partial trial)").arg(t.index)
                           : tr("%1 (%2)").arg(t.index).arg(trialStatusName(t.status())));
        }
        return trials.join(QStringLiteral(", "));
    }
    case Column::State: {
        QStringList state;
        if (m_accepted && *m_accepted == k)
            state << tr("accepted");
        if (m_applied == k)
            state << tr("on robot");
        return state.join(QStringLiteral(", "));
    }
    }
    return {};
}

QVariant ConvergenceTableModel::data(const QModelIndex &index, int role) const
{
    if (!index.isValid() || index.row() >= m_estimates.size())
        return {};
    int p = 0;
    const int k = index.row();
    const Column kind = columnKind(index.column(), &p);
    switch (role) {
    case Qt::DisplayRole:
        return text(k, kind, p);
    case Qt::UserRole:
        return number(k, kind, p);
    case Qt::TextAlignmentRole:
        return int((kind == Column::Observable || kind == Column::Trials || kind == Column::State
                        ? Qt::AlignLeft
                        : Qt::AlignRight) |
                   Qt::AlignVCenter);
    case Qt::ForegroundRole:
        if (kind == Column::Observable && text(k, kind, p).startsWith(QChar(0x26a0)))
            return QBrush(QColor(0xb0, 0x60, 0x00));
        if (kind == Column::Trials && text(k, kind, p).contains(QLatin1Char('(')))
            return QBrush(QColor(0x8c, 0x1d, 0x18));
        return {};
    case Qt::BackgroundRole:
        if (m_accepted && *m_accepted == k)
            return QBrush(QColor(0xe3, 0xf1, 0xe3));
        return {};
    case Qt::FontRole:
        if (m_accepted && *m_accepted == k) {
            QFont bold;
            bold.setBold(true);
            return bold;
        }
        return {};
    case Qt::ToolTipRole: {
        const TrialResult *made = producer(k);
        if (kind == Column::Parameter && made && made->update && p < made->update->phiStd.size())
            return tr("%1 = %2 \u00b1 %3 (1 sigma)")
                .arg(m_parameters.at(p).name)
                .arg(m_estimates.at(k)[p], 0, 'g', 8)
                .arg(made->update->phiStd[p], 0, 'g', 3);
        if (kind == Column::Trials && !m_trialsWith.at(k).isEmpty())
            return m_history.at(m_trialsWith.at(k).constLast()).message;
        return {};
    }
    default:
        return {};
    }
}

QVariant ConvergenceTableModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation == Qt::Vertical || role != Qt::DisplayRole)
        return QAbstractTableModel::headerData(section, orientation, role);
    int p = 0;
    auto withUnit = [](const ParameterInfo &info) {
        return info.unit.isEmpty() ? info.name
                                   : QStringLiteral("%1 [%2]").arg(info.name, info.unit);
    };
    switch (columnKind(section, &p)) {
    case Column::Estimate:
        return tr("Estimate");
    case Column::Parameter:
        return withUnit(m_parameters.at(p));
    case Column::RelativeChange:
        return tr("Rel. change [%]");
    case Column::MaxError:
        return tr("Max |e| [deg]");
    case Column::Condition:
        return tr("cond(W\u1d40W)");
    case Column::Observable:
        return tr("Observable");
    case Column::TruthError:
        return tr("%1 vs truth [%]").arg(m_parameters.at(p).name);
    case Column::PathTorque:
        return tr("Path torque vs truth [%]");
    case Column::Trials:
        return tr("Trials run");
    case Column::State:
        return tr("State");
    }
    return {};
}

} // namespace learnid
