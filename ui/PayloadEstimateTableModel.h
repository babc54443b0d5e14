#pragma once

#include "identify/PayloadEstimate.h"

#include <QAbstractTableModel>
#include <array>

namespace learnid {

/// The payload's estimate, one row per value of its body (mass, centre of mass, inertia about
/// it): the estimate, its standard error (empty for a value kept at the prior), the prior, and
/// where the value comes from: the trials' data or the prior (not identified). The centre of mass
/// in mm, the mass in kg, the inertia in kg m^2. Qt::UserRole gives the raw number of a numeric
/// cell in the unit shown (NaN for an empty one).
class PayloadEstimateTableModel : public QAbstractTableModel
{
    Q_OBJECT

public:
    enum Column { Value, Unit, Estimate, StandardError, Prior, Source };

    explicit PayloadEstimateTableModel(QObject *parent = nullptr);

    void setEstimate(const PayloadEstimate &estimate);
    void clear();
    bool isEmpty() const { return !m_shown; }

    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;

private:
    double number(int row, int column) const;

    bool m_shown = false;
    std::array<double, 10> m_value{};
    std::array<double, 10> m_error{};
    std::array<double, 10> m_prior{};
    std::array<bool, 10> m_identified{};
};

} // namespace learnid
