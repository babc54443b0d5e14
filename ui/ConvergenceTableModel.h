#pragma once

#include "model/RobotModel.h"
#include "session/ConvergenceFigures.h"
#include "session/TrialResult.h"

#include <QAbstractTableModel>
#include <QVector>
#include <optional>

namespace learnid {

/// Parameter convergence like the paper's Table 1: one row per estimate (row 0 = phi_0), a column
/// per parameter with its unit, the relative change from the previous estimate, the max tracking
/// error of the trial run with the estimate, the conditioning of the fit that produced it, a mark
/// when unobservable directions were kept, for a simulated robot the error against the truth,
/// and the trials run with it. Qt::UserRole gives the raw number of numeric cells. A model with
/// more than maxParameterColumns parameters (an n-joint arm) shows no column per parameter
/// (ParameterTableModel lists them as rows) but, for a simulated robot, the path-torque error
/// against the truth.
class ConvergenceTableModel : public QAbstractTableModel
{
    Q_OBJECT

public:
    enum class Column {
        Estimate,
        Parameter,
        RelativeChange,
        MaxError,
        Condition,
        Observable,
        TruthError,
        PathTorque,
        Trials,
        State
    };

    /// Up to this many parameters each has its columns (the paper's Table 1), as in the CLI.
    static constexpr int maxParameterColumns = 4;

    explicit ConvergenceTableModel(QObject *parent = nullptr);

    void setParameters(const QList<ParameterInfo> &parameters,
                       const std::optional<Eigen::VectorXd> &truth);
    void setHistory(const QVector<TrialResult> &history, const QVector<Eigen::VectorXd> &estimates);
    /// The path-torque figures of every estimate (EstimateFigures::vsTruth is shown).
    void setFigures(const EstimateFigures &figures);
    void setAccepted(std::optional<int> estimateIndex);
    /// The estimate the robot holds, -1 for none.
    void setApplied(int estimateIndex);

    /// Which column kind column c is, and for Parameter/TruthError which parameter.
    Column columnKind(int column, int *parameter = nullptr) const;
    int columnOf(Column kind, int parameter = 0) const;
    /// The trial that produced estimate k (k >= 1), or nullptr.
    const TrialResult *producer(int estimateIndex) const;

    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;

private:
    int shownParameters() const;
    QVariant number(int row, Column kind, int parameter) const;
    QString text(int row, Column kind, int parameter) const;

    QList<ParameterInfo> m_parameters;
    std::optional<Eigen::VectorXd> m_truth;
    EstimateFigures m_figures;
    QVector<TrialResult> m_history; ///< the trials shown (the window gives them without samples)
    QVector<Eigen::VectorXd> m_estimates;
    QVector<QVector<int>> m_trialsWith; ///< history indices of the trials run with estimate k
    QVector<int> m_producer;            ///< history index of the trial that produced k, or -1
    std::optional<int> m_accepted;
    int m_applied = -1;
};

} // namespace learnid
