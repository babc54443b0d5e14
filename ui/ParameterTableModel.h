#pragma once

#include "model/RobotModel.h"
#include "session/ConvergenceFigures.h"
#include "session/TrialResult.h"

#include <QAbstractTableModel>
#include <QVector>
#include <optional>

namespace learnid {

/// The parameters of any arm as rows, grouped by the link or joint they belong to (the
/// combination each base parameter stands for as its name), the estimates as columns; then,
/// for the newest learned estimate, the relative standard deviation, whether the path observes
/// the parameter or the trials kept it, whether its link is a real body, and for a simulated
/// robot the truth. Qt::UserRole gives the raw number of numeric cells.
class ParameterTableModel : public QAbstractTableModel
{
    Q_OBJECT

public:
    enum class Column {
        Group,
        Parameter,
        Unit,
        Estimate,
        RelativeStd,
        Observable,
        Consistent,
        Truth
    };

    explicit ParameterTableModel(QObject *parent = nullptr);

    void setParameters(const QList<ParameterInfo> &parameters,
                       const std::optional<Eigen::VectorXd> &truth);
    /// history: the trials (their updates give the standard deviations and observability).
    void setEstimates(const QVector<Eigen::VectorXd> &estimates,
                      const QVector<TrialResult> &history, const EstimateFigures &figures);
    void setAccepted(std::optional<int> estimateIndex);

    /// Which column kind column c is, and for Estimate which estimate.
    Column columnKind(int column, int *estimate = nullptr) const;
    int columnOf(Column kind, int estimate = 0) const;

    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;

private:
    QVariant number(int row, Column kind, int estimate) const;
    QString text(int row, Column kind, int estimate) const;

    QList<ParameterInfo> m_parameters;
    std::optional<Eigen::VectorXd> m_truth;
    QVector<Eigen::VectorXd> m_estimates;
    std::optional<ParameterUpdate> m_newest; ///< the update that made the newest estimate
    EstimateFigures m_figures;
    std::optional<int> m_accepted;
};

} // namespace learnid
