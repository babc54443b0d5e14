#include "identify/RotorTorque.h"

#include "control/PidController.h"
#include "identify/FilteringEstimator.h"

#include <algorithm>

namespace learnid {

Eigen::MatrixXd driveCommand(const TrialPlan &plan, const TrialRecord &record)
{
    const Eigen::Index n = record.q.rows();
    const int samples = record.samples();
    Eigen::MatrixXd command(n, samples);
    PidController pid(plan.controller);
    Eigen::VectorXd e(n), u(n);
    for (int k = 0; k < samples; ++k) {
        e = plan.desired.q.col(k) - record.q.col(k);
        pid.step(e, u);
        command.col(k) =
            (plan.feedforward.col(k) + u).cwiseMax(-plan.torqueLimit).cwiseMin(plan.torqueLimit);
    }
    return command;
}

Eigen::MatrixXd rotorTorque(const FilteringEstimator &filter, const TrialPlan &plan,
                            const TrialRecord &record, const Eigen::MatrixXd &measured,
                            const Eigen::MatrixXd &qddHat, Eigen::Index used,
                            Eigen::VectorXd *inertia)
{
    const Eigen::Index n = record.q.rows();
    const Eigen::Index rows = std::max<Eigen::Index>(record.samples() - 1, 0);
    used = std::clamp<Eigen::Index>(used, 0, rows);
    // Row k pairs torque sample k, held over [t_k, t_k+1), with the mid-sample state (as the
    // law's rows: ImprovedLaw.cpp, step 2).
    const Eigen::MatrixXd command = driveCommand(plan, record);
    Eigen::MatrixXd acceleration(rows, n), rotor(rows, n);
    for (Eigen::Index k = 0; k < rows; ++k)
        acceleration.row(k) = 0.5 * (qddHat.col(k) + qddHat.col(k + 1)).transpose();
    Eigen::MatrixXd difference =
        (command.leftCols(rows) - measured.leftCols(rows)).transpose().eval();
    Eigen::MatrixXd filtered = acceleration;
    filter.zeroPhaseLowPassColumnsInPlace(difference);
    filter.zeroPhaseLowPassColumnsInPlace(filtered);
    if (inertia)
        inertia->setZero(n);
    for (Eigen::Index j = 0; j < n; ++j) {
        const auto a = filtered.col(j).head(used);
        const double energy = a.squaredNorm();
        // A joint that did not accelerate shows no rotor: nothing to fit.
        const double ia = energy > 0.0 ? a.dot(difference.col(j).head(used)) / energy : 0.0;
        rotor.col(j) = ia * acceleration.col(j);
        if (inertia)
            (*inertia)[j] = ia;
    }
    return rotor;
}

} // namespace learnid
