#include "model/ChainPerturbation.h"

#include <Eigen/Eigenvalues>
#include <random>

namespace learnid {

namespace {

bool triangle(const Eigen::Vector3d &moments)
{
    const double sum = moments.sum();
    return (moments.array() >= 0.0).all() && (2.0 * moments.array() <= sum).all();
}

} // namespace

Eigen::VectorXd perturbedStandard(const ChainModel &model, double fraction, quint64 seed)
{
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    const auto factor = [&] {
        return 1.0 + fraction * unit(random);
    };
    Eigen::VectorXd pi = model.cadStandard();
    for (int k = 0; k < model.dof(); ++k) {
        const InertialParameters cad = pi.segment<10>(10 * k);
        const double m = cad[0];
        if (!(m > 0.0))
            continue; // a massless link stays massless
        const Eigen::Vector3d c = cad.segment<3>(1) / m;
        const Eigen::Matrix3d atCom =
            rotationalInertia(cad) -
            m * (c.squaredNorm() * Eigen::Matrix3d::Identity() - c * c.transpose());
        const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> principal(atCom);
        const double mass = m * factor();
        Eigen::Vector3d centre = c;
        for (double &x : centre)
            x *= factor();
        Eigen::Vector3d moments = principal.eigenvalues();
        for (int attempt = 0; attempt < 100; ++attempt) {
            const Eigen::Vector3d drawn(moments[0] * factor(), moments[1] * factor(),
                                        moments[2] * factor());
            if (triangle(drawn)) {
                moments = drawn;
                break;
            }
        }
        const Eigen::Matrix3d axes = principal.eigenvectors();
        pi.segment<10>(10 * k) =
            inertialParameters(mass, centre, axes * moments.asDiagonal() * axes.transpose());
    }
    for (Eigen::Index i = 10 * model.dof(); i < pi.size(); ++i)
        pi[i] *= factor();
    return pi;
}

} // namespace learnid
