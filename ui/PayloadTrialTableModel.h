#pragma once

#include "service/PayloadRun.h"

#include <QAbstractTableModel>
#include <vector>

namespace learnid {

/// The trials of a payload run, one row each as they finish: the trial, what it was (a baseline
/// trial without the payload, or a payload trial), the worst joint's maximum and RMS tracking
/// error, the payload fitted after it (mass, centre of mass in mm), the update's CPU time, and
/// which of the payload's values the trials identified so far (or why it was not learned from).
/// Qt::UserRole gives the raw number of a numeric cell (NaN for an empty one; the centre of mass:
/// its distance from the link frame's origin [mm]).
class PayloadTrialTableModel : public QAbstractTableModel
{
    Q_OBJECT

public:
    enum Column { Trial, Kind, MaxError, RmsError, Mass, Com, Update, Identified };

    explicit PayloadTrialTableModel(QObject *parent = nullptr);

    void addRow(const PayloadTrialRow &row);
    void clear();
    const PayloadTrialRow &row(int i) const { return m_rows.at(size_t(i)); }

    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;

private:
    double number(const PayloadTrialRow &r, int column, int *decimals) const;
    QString identifiedText(const PayloadTrialRow &r) const;

    std::vector<PayloadTrialRow> m_rows;
};

} // namespace learnid
