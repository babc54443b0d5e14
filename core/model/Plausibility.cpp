#include "model/Plausibility.h"

#include "model/Error.h"

#include <Eigen/Eigenvalues>
#include <QCoreApplication>
#include <QStringList>
#include <algorithm>
#include <cmath>
#include <limits>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(Plausibility)
};

// Principal moments of inertia about the centre of mass, ascending; zero for a link without
// positive mass.
Eigen::Vector3d principalMoments(const Eigen::Ref<const Eigen::VectorXd> &pi10)
{
    const double m = pi10[0];
    if (!(m > 0.0))
        return Eigen::Vector3d::Zero();
    const Eigen::Vector3d c = pi10.segment<3>(1) / m;
    const InertialParameters pi = pi10;
    // I_c = I - m (|c|^2 E - c c^T), the parallel axis theorem backwards.
    const Eigen::Matrix3d atCom =
        rotationalInertia(pi) -
        m * (c.squaredNorm() * Eigen::Matrix3d::Identity() - c * c.transpose());
    return Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(atCom, Eigen::EigenvaluesOnly)
        .eigenvalues();
}

} // namespace

std::vector<std::optional<BoundingEllipsoid>> linkVolumes(const SerialChain &chain,
                                                          const Eigen::VectorXd &cadPrior)
{
    const int n = chain.dof();
    if (cadPrior.size() < 10 * Eigen::Index(n))
        throw Error(Text::tr("The CAD vector has %1 entries, too few for %2 links.")
                        .arg(cadPrior.size())
                        .arg(n));
    std::vector<std::optional<BoundingEllipsoid>> volumes(static_cast<size_t>(n));
    for (int l = 0; l < n; ++l) {
        const Eigen::VectorXd cad = cadPrior.segment<10>(10 * l);
        if (!(cad[0] > 0.0))
            continue;
        const ChainJoint &joint = chain.joints[size_t(l)];
        if (!joint.geometryBox.isEmpty()) {
            BoundingEllipsoid e =
                ellipsoidAroundBox(joint.geometryBox.min(), joint.geometryBox.max());
            e.description = joint.geometryDescription;
            // Geometry that does not hold the CAD body (a visual mesh offset, a collision shape
            // for one end only) would make the CAD prior itself implausible: the CAD body's
            // ellipsoid serves instead.
            if (e.fitShare(cad) > 0.0) {
                volumes[size_t(l)] = e;
                continue;
            }
        }
        volumes[size_t(l)] = ellipsoidFromInertia(cad, cadVolumeMargin, cadVolumeMinimumAxis);
    }
    return volumes;
}

std::vector<LinkPlausibility>
checkPlausibility(const Eigen::VectorXd &standard, const Eigen::VectorXd &cadPrior, int links,
                  const std::vector<std::optional<BoundingEllipsoid>> &volumes,
                  const PlausibilityRule &rule)
{
    if (links < 0 || standard.size() < 10 * Eigen::Index(links) ||
        cadPrior.size() < 10 * Eigen::Index(links) ||
        (!volumes.empty() && volumes.size() != size_t(links)))
        throw Error(Text::tr("The plausibility check needs 10 parameters and a volume per link "
                             "(%1 links, %2 and %3 parameters, %4 volumes).")
                        .arg(links)
                        .arg(standard.size())
                        .arg(cadPrior.size())
                        .arg(volumes.size()));
    if (!standard.head(10 * links).allFinite() || !cadPrior.head(10 * links).allFinite())
        throw Error(Text::tr("The parameters to check are not finite."));
    std::vector<LinkPlausibility> out;
    for (int l = 0; l < links; ++l) {
        const Eigen::VectorXd pi = standard.segment<10>(10 * l);
        LinkPlausibility v;
        v.link = l;
        v.mass = pi[0];
        v.moments = principalMoments(pi);
        v.cadSmallestMoment = principalMoments(cadPrior.segment<10>(10 * l))[0];
        v.triangleRatio = v.moments[2] > 0.0 ? (v.moments[0] + v.moments[1]) / v.moments[2]
                                             : std::numeric_limits<double>::infinity();
        v.momentsOk = v.mass > 0.0 && v.moments[0] >= rule.minMomentShare * v.cadSmallestMoment &&
                      v.moments[0] > 0.0;
        v.triangleOk = v.mass > 0.0 && v.triangleRatio >= 1.0 + rule.triangleMargin;
        if (!volumes.empty() && volumes[size_t(l)] && v.mass > 0.0) {
            const BoundingEllipsoid &e = *volumes[size_t(l)];
            v.hasVolume = true;
            v.comDistance = e.normalisedDistance(pi.segment<3>(1) / v.mass);
            v.fitShare = e.fitShare(pi);
            v.volumeOk = v.comDistance <= 1.0;
        }
        v.plausible = v.mass > 0.0 && v.momentsOk && v.triangleOk && v.volumeOk;
        out.push_back(v);
    }
    return out;
}

QString plausibilityProblem(const LinkPlausibility &v, const PlausibilityRule &rule)
{
    if (v.plausible)
        return {};
    if (!(v.mass > 0.0))
        return Text::tr("mass %1 kg").arg(v.mass, 0, 'g', 3);
    QStringList problems;
    if (!v.momentsOk) {
        problems << Text::tr("smallest principal moment %1 kg m², below %2 % of the CAD link's "
                             "smallest (%3 kg m²)")
                        .arg(v.moments[0], 0, 'g', 2)
                        .arg(100.0 * rule.minMomentShare, 0, 'g', 3)
                        .arg(v.cadSmallestMoment, 0, 'g', 2);
    }
    if (!v.triangleOk) {
        problems << Text::tr("(I1 + I2) / I3 = %1, below %2: a needle or a plate")
                        .arg(v.triangleRatio, 0, 'f', 3)
                        .arg(1.0 + rule.triangleMargin, 0, 'f', 2);
    }
    if (!v.volumeOk) {
        problems << Text::tr("centre of mass outside the link's bounding volume (%1 times its "
                             "size)")
                        .arg(std::sqrt(v.comDistance), 0, 'f', 2);
    }
    return problems.join(QStringLiteral("; "));
}

std::vector<int> tinyJointTerms(const Eigen::VectorXd &standard,
                                const std::vector<int> &nonnegativeIndices,
                                const PlausibilityRule &rule)
{
    std::vector<int> out;
    for (const int i : nonnegativeIndices) {
        if (i < 0 || i >= standard.size())
            throw Error(Text::tr("Index %1 is outside the %2 standard parameters.")
                            .arg(i)
                            .arg(standard.size()));
        if (standard[i] > 0.0 && standard[i] < rule.termFloor)
            out.push_back(i);
    }
    return out;
}

} // namespace learnid
