#pragma once

#include "identify/LogFit.h"

#include <QAbstractTableModel>
#include <QStringList>

namespace learnid {

/// The figures of one validation log, as `learnid-cli identify` prints them: per joint the RMS
/// of the measured torque, and for the URDF as given and for the identified parameters the RMS
/// error and its ratio to the measured RMS; then a row with the overall
/// sqrt(sum e^2 / sum tau^2) and one with the mean of the joint ratios. Ratios in %;
/// Qt::UserRole gives the raw number of a numeric cell (ratios and figures in %).
class LogValidationTableModel : public QAbstractTableModel
{
    Q_OBJECT

public:
    enum Column { Joint, RmsMeasured, GivenError, GivenRatio, IdentifiedError, IdentifiedRatio };
    enum class Row { Joint, Overall, MeanRatio };

    explicit LogValidationTableModel(QObject *parent = nullptr);

    /// jointNames: the URDF's moving joints in chain order; both figures of the same log.
    void setFigures(const QStringList &jointNames, const TorqueFigures &given,
                    const TorqueFigures &identified);
    void clear();

    Row rowKind(int row) const;
    /// The row of the overall figure.
    int overallRow() const { return int(m_joints.size()); }

    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;

private:
    /// The cell's value (NaN: empty cell) and its decimals.
    double number(int row, int column, int *decimals) const;

    QStringList m_joints;
    TorqueFigures m_given;
    TorqueFigures m_identified;
};

} // namespace learnid
