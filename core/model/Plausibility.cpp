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

QStringList plausibilityProblems(const LinkPlausibility &v,
                                 const std::optional<BoundingEllipsoid> &volume,
                                 const PlausibilityRule &rule)
{
    const auto number = [](double x) {
        return QString::number(x, 'g', 3);
    };
    QStringList out;
    if (v.plausible)
        return out;
    if (!(v.mass > 0.0))
        return {Text::tr("its mass is %1 kg: not a real body").arg(number(v.mass))};
    if (!v.momentsOk) {
        out << Text::tr("its smallest principal moment of inertia about the centre of mass, "
                        "%1 kg m^2, is below %2 % of the CAD link's smallest (%3 kg m^2): a point "
                        "mass or a needle, not a link")
                   .arg(number(v.moments[0]), number(100.0 * rule.minMomentShare),
                        number(v.cadSmallestMoment));
    }
    if (!v.triangleOk) {
        out << Text::tr("its principal moments %1, %2 and %3 kg m^2 give I1 + I2 = %4 I3, "
                        "below %5 I3 (a flat plate at best)")
                   .arg(number(v.moments[0]), number(v.moments[1]), number(v.moments[2]),
                        QString::number(v.triangleRatio, 'f', 3),
                        QString::number(1.0 + rule.triangleMargin, 'f', 3));
    }
    if (!v.volumeOk) {
        out << (volume ? Text::tr("its centre of mass lies outside its bounding volume (%1)")
                             .arg(volume->source == VolumeSource::Geometry
                                      ? Text::tr("the URDF's geometry: %1").arg(volume->description)
                                      : Text::tr("the CAD body's inertia ellipsoid, enlarged "
                                                 "%1 times")
                                            .arg(cadVolumeMargin))
                       : Text::tr("its centre of mass lies outside its bounding volume"));
    }
    return out;
}

QString plausibilityProblem(const LinkPlausibility &v, const PlausibilityRule &rule)
{
    return plausibilityProblems(v, std::nullopt, rule).join(QStringLiteral("; "));
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
