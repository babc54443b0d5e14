// BoundingVolume and Plausibility against bodies known in closed form (solid boxes, cylinders,
// ellipsoids, rods, plates, point masses) and against sampled point clouds, whose integrals
// over the mass are plain sums.
#include "../support/NumericAssert.h"
#include "InertiaSamples.h"
#include "model/BoundingVolume.h"
#include "model/Error.h"
#include "model/Plausibility.h"

#include <Eigen/Dense>
#include <QTest>
#include <cmath>
#include <limits>
#include <random>

using namespace learnid;
using namespace learnid::test;

namespace {

// A solid cylinder of mass m, radius r and length h along the link's z axis, centred at c:
// I_zz = m r^2 / 2, I_xx = I_yy = m (3 r^2 + h^2) / 12.
Vector10d cylinderInertial(double m, double r, double h, const Eigen::Vector3d &c)
{
    const double side = m * (3.0 * r * r + h * h) / 12.0;
    return inertialOf(m, Eigen::Vector3d(side, side, 0.5 * m * r * r).asDiagonal(), c);
}

// A solid ellipsoid of semi-axes a (along `axes`' columns) centred at c:
// I_c = m / 5 diag(b^2 + c^2, a^2 + c^2, a^2 + b^2) in its own axes.
Vector10d ellipsoidInertial(double m, const Eigen::Vector3d &a, const Eigen::Matrix3d &axes,
                            const Eigen::Vector3d &c)
{
    const Eigen::Vector3d s = a.cwiseAbs2();
    const Eigen::Vector3d d(s.y() + s.z(), s.x() + s.z(), s.x() + s.y());
    return inertialOf(m, axes * (m / 5.0 * d).asDiagonal() * axes.transpose(), c);
}

// Point masses: the pseudo-inertia is their plain sum of m [x; 1][x; 1]^T.
struct Cloud
{
    std::vector<Eigen::Vector3d> points;
    std::vector<double> masses;

    Vector10d inertial() const
    {
        Eigen::Matrix4d j = Eigen::Matrix4d::Zero();
        for (size_t k = 0; k < points.size(); ++k) {
            const Eigen::Vector4d x = points[k].homogeneous();
            j += masses[k] * x * x.transpose();
        }
        return inertialFromPseudoInertia(j);
    }
};

// n random points uniform in the box [lower, upper] with random masses in [0.1, 1].
Cloud randomCloud(int n, const Eigen::Vector3d &lower, const Eigen::Vector3d &upper, unsigned seed)
{
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    Cloud cloud;
    for (int k = 0; k < n; ++k) {
        const Eigen::Vector3d u(unit(random), unit(random), unit(random));
        cloud.points.push_back(lower + u.cwiseProduct(upper - lower));
        cloud.masses.push_back(0.1 + 0.9 * unit(random));
    }
    return cloud;
}

Eigen::Matrix3d rotation()
{
    return Eigen::AngleAxisd(0.9, Eigen::Vector3d(0.3, 1.0, -0.4).normalized()).toRotationMatrix();
}

// One link's verdict with the default rule against a CAD link.
LinkPlausibility verdictOf(const Vector10d &pi, const Vector10d &cad,
                           const std::optional<BoundingEllipsoid> &volume = std::nullopt)
{
    return checkPlausibility(pi, cad, 1, {volume}).front();
}

} // namespace

class TestPlausibility : public QObject
{
    Q_OBJECT

private slots:
    void ellipsoidAroundBox_passesThroughTheCornersAndHoldsTheBox();
    void ellipsoidAroundBox_flatBoxGetsAThicknessAndInvertedBoxThrows();
    void constraintMatrix_quadraticFormIsOneMinusTheNormalisedDistance();
    void fitShare_equalsTheMeanOverASampledCloud();
    void fitShare_solidBodyInsideIsPositiveOutsideNegative();
    void ellipsoidFromInertia_ofSolidEllipsoidAndBox_givesTheirAxesTimesTheMargin();
    void ellipsoidFromInertia_pointMassGetsTheMinimumAxisAndBadInputThrows();
    void principalMoments_ofSolidCylinder_areTheTextbookOnes();
    void triangle_rodAndPlateFailCubeAndCloudsPass();
    void moments_shareOfTheCadSmallestDecides();
    void pointMass_isNotPlausible();
    void volume_centreOfMassOutsideFails();
    void linkVolumes_geometryWhenItHoldsTheCadBodyElseCadInertia();
    void tinyJointTerms_listsValuesBetweenZeroAndTheFloor();
    void badInput_throws();
};

void TestPlausibility::ellipsoidAroundBox_passesThroughTheCornersAndHoldsTheBox()
{
    const Eigen::Vector3d lower(-0.1, 0.2, -0.3), upper(0.3, 0.25, 0.1);
    const BoundingEllipsoid e = ellipsoidAroundBox(lower, upper);
    LEARNID_COMPARE_MATRIX(e.centre, Eigen::Vector3d(0.1, 0.225, -0.1), 1e-15);
    QCOMPARE(e.source, VolumeSource::Geometry);
    // Each corner lies on the surface; the face centres lie inside at 1/3.
    for (int corner = 0; corner < 8; ++corner) {
        const Eigen::Vector3d x((corner & 1) ? upper.x() : lower.x(),
                                (corner & 2) ? upper.y() : lower.y(),
                                (corner & 4) ? upper.z() : lower.z());
        LEARNID_COMPARE_NEAR(e.normalisedDistance(x), 1.0, 1e-12);
    }
    LEARNID_COMPARE_NEAR(e.normalisedDistance(Eigen::Vector3d(upper.x(), 0.225, -0.1)), 1.0 / 3.0,
                         1e-12);
    // The smallest such ellipsoid: any other axis-aligned one through the corners, with a
    // semi-axis ratio changed, is larger (volume prop. to the product of the semi-axes).
    const Eigen::Vector3d h = 0.5 * (upper - lower);
    const double volume = e.axes.determinant();
    LEARNID_COMPARE_NEAR(volume, std::pow(3.0, 1.5) * h.prod(), 1e-15);
    const Eigen::Vector3d stretched = h.cwiseProduct(Eigen::Vector3d(1.2, 1.0, 1.0));
    // Through the corners: sum (h_i / a_i)^2 = 1 with a_1 = sqrt(3) 1.2 h_1 leaves the others.
    const double rest = std::sqrt(2.0 / (1.0 - 1.0 / (3.0 * 1.44)));
    QVERIFY(std::sqrt(3.0) * stretched.x() * rest * h.y() * rest * h.z() > volume);
}

void TestPlausibility::ellipsoidAroundBox_flatBoxGetsAThicknessAndInvertedBoxThrows()
{
    const BoundingEllipsoid flat =
        ellipsoidAroundBox(Eigen::Vector3d(0.0, 0.0, 0.0), Eigen::Vector3d(0.4, 0.2, 0.0));
    // Thickness 1e-3 of the largest side: half 0.2e-3, semi-axis sqrt(3) of it.
    LEARNID_COMPARE_NEAR(flat.axes(2, 2), std::sqrt(3.0) * 0.2e-3, 1e-15);
    QVERIFY(std::isfinite(flat.normalisedDistance(Eigen::Vector3d(0.2, 0.1, 0.0))));
    QVERIFY_THROWS_EXCEPTION(
        Error, ellipsoidAroundBox(Eigen::Vector3d(0.0, 0.0, 0.0), Eigen::Vector3d(0.4, -0.1, 0.1)));
    QVERIFY_THROWS_EXCEPTION(Error,
                             ellipsoidAroundBox(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()));
    QVERIFY_THROWS_EXCEPTION(
        Error, ellipsoidAroundBox(Eigen::Vector3d::Zero(), Eigen::Vector3d(NAN, 1.0, 1.0)));
}

void TestPlausibility::constraintMatrix_quadraticFormIsOneMinusTheNormalisedDistance()
{
    BoundingEllipsoid e;
    e.centre = Eigen::Vector3d(0.1, -0.2, 0.3);
    e.axes = rotation() * Eigen::Vector3d(0.3, 0.1, 0.05).asDiagonal();
    const Eigen::Matrix4d q = e.constraintMatrix();
    LEARNID_COMPARE_MATRIX(q, q.transpose(), 0.0);
    const Cloud cloud =
        randomCloud(50, Eigen::Vector3d::Constant(-0.5), Eigen::Vector3d::Constant(0.5), 7);
    for (const Eigen::Vector3d &x : cloud.points) {
        // |A (x - c)|^2 with A = axes^-1, computed here by solving axes u = x - c.
        const Eigen::Vector3d u = e.axes.colPivHouseholderQr().solve(x - e.centre);
        LEARNID_COMPARE_NEAR(e.normalisedDistance(x), u.squaredNorm(), 1e-9);
        LEARNID_COMPARE_NEAR(x.homogeneous().dot(q * x.homogeneous()), 1.0 - u.squaredNorm(), 1e-9);
    }
    LEARNID_COMPARE_NEAR(e.normalisedDistance(e.centre + e.axes.col(1)), 1.0, 1e-12);
}

void TestPlausibility::fitShare_equalsTheMeanOverASampledCloud()
{
    BoundingEllipsoid e;
    e.centre = Eigen::Vector3d(0.05, 0.0, 0.1);
    e.axes = rotation() * Eigen::Vector3d(0.25, 0.2, 0.15).asDiagonal();
    const Cloud cloud =
        randomCloud(2000, Eigen::Vector3d(-0.2, -0.2, -0.1), Eigen::Vector3d(0.3, 0.2, 0.3), 11);
    // tr(Q J) / m = sum m_k (1 - |A (x_k - c)|^2) / sum m_k: linear in the mass distribution.
    double weighted = 0.0, total = 0.0;
    int outside = 0;
    for (size_t k = 0; k < cloud.points.size(); ++k) {
        const double d = e.normalisedDistance(cloud.points[k]);
        weighted += cloud.masses[k] * (1.0 - d);
        total += cloud.masses[k];
        outside += d > 1.0;
    }
    QVERIFY(outside > 0); // a cloud partly outside: the share is a mean, not a verdict per point
    LEARNID_COMPARE_NEAR(e.fitShare(cloud.inertial()), weighted / total, 1e-12);
}

void TestPlausibility::fitShare_solidBodyInsideIsPositiveOutsideNegative()
{
    // A cylinder r = 0.05, h = 0.3 along z in the box around its geometry: inside.
    const Vector10d cylinder = cylinderInertial(2.0, 0.05, 0.3, Eigen::Vector3d(0.0, 0.0, 0.15));
    const BoundingEllipsoid around =
        ellipsoidAroundBox(Eigen::Vector3d(-0.05, -0.05, 0.0), Eigen::Vector3d(0.05, 0.05, 0.3));
    // In closed form: 1 - (E x^2 + E y^2) / (3 h_r^2) - E (z - c)^2 / (3 h_z^2) with
    // E x^2 = r^2 / 4 for a disc, E (z - c)^2 = h^2 / 12: 1 - 2 (1/4) / 3 - (1/3)(1/3) = 0.7222.
    LEARNID_COMPARE_NEAR(around.fitShare(cylinder), 1.0 - 0.5 / 3.0 - 1.0 / 9.0, 1e-12);
    // The same cylinder twice as long sticks out of the ellipsoid: tr(Q J) < 0.
    const Vector10d longer = cylinderInertial(2.0, 0.05, 1.2, Eigen::Vector3d(0.0, 0.0, 0.15));
    QVERIFY(around.fitShare(longer) < 0.0);
}

void TestPlausibility::ellipsoidFromInertia_ofSolidEllipsoidAndBox_givesTheirAxesTimesTheMargin()
{
    const Eigen::Vector3d semi(0.3, 0.12, 0.05);
    const Eigen::Vector3d c(0.1, -0.05, 0.2);
    const BoundingEllipsoid e =
        ellipsoidFromInertia(ellipsoidInertial(4.0, semi, rotation(), c), 1.5, 0.0);
    QCOMPARE(e.source, VolumeSource::CadInertia);
    LEARNID_COMPARE_MATRIX(e.centre, c, 1e-14);
    // The same ellipsoid scaled by 1.5: its semi-axis end points lie on the surface.
    for (int i = 0; i < 3; ++i) {
        LEARNID_COMPARE_NEAR(e.normalisedDistance(c + 1.5 * semi[i] * rotation().col(i)), 1.0,
                             1e-9);
    }
    LEARNID_COMPARE_NEAR(std::abs(e.axes.determinant()), std::pow(1.5, 3) * semi.prod(), 1e-12);

    // A box of edges s has the second moments of the ellipsoid with semi-axes sqrt(5/12) s.
    const Box box = sampleBox();
    const BoundingEllipsoid b = ellipsoidFromInertia(boxInertial(box), 2.0, 0.0);
    for (int i = 0; i < 3; ++i) {
        const Eigen::Vector3d end =
            box.centre + 2.0 * std::sqrt(5.0 / 12.0) * box.size[i] * box.axes.col(i);
        LEARNID_COMPARE_NEAR(b.normalisedDistance(end), 1.0, 1e-9);
    }
    // With the margin 2 the box's corners are inside: |u|^2 = 3 (1/2)^2 / (4 5/12) = 0.45.
    const Eigen::Vector3d corner = box.centre + box.axes * (0.5 * box.size);
    LEARNID_COMPARE_NEAR(b.normalisedDistance(corner), 0.45, 1e-9);
}

void TestPlausibility::ellipsoidFromInertia_pointMassGetsTheMinimumAxisAndBadInputThrows()
{
    const Eigen::Vector3d c(0.2, 0.0, -0.1);
    const Vector10d point = inertialOf(1.5, Eigen::Matrix3d::Zero(), c);
    const BoundingEllipsoid e = ellipsoidFromInertia(point, cadVolumeMargin, 0.02);
    LEARNID_COMPARE_MATRIX(e.centre, c, 1e-14);
    LEARNID_COMPARE_NEAR(std::abs(e.axes.determinant()), 0.02 * 0.02 * 0.02, 1e-15);
    LEARNID_COMPARE_NEAR(e.normalisedDistance(c + Eigen::Vector3d(0.0, 0.02, 0.0)), 1.0, 1e-9);

    Vector10d massless = point;
    massless[0] = 0.0;
    QVERIFY_THROWS_EXCEPTION(Error, ellipsoidFromInertia(massless, 2.0, 0.02));
    QVERIFY_THROWS_EXCEPTION(Error, ellipsoidFromInertia(point, 1.0, 0.02));
    QVERIFY_THROWS_EXCEPTION(Error, ellipsoidFromInertia(point, 2.0, -1.0));
    QVERIFY_THROWS_EXCEPTION(Error, ellipsoidFromInertia(Eigen::VectorXd::Ones(9), 2.0, 0.02));
}

void TestPlausibility::principalMoments_ofSolidCylinder_areTheTextbookOnes()
{
    // Off the origin and turned, so the parallel-axis theorem and the rotation are undone.
    const double m = 3.0, r = 0.06, h = 0.4;
    const Eigen::Vector3d c(0.3, -0.2, 0.1);
    const Vector10d along = cylinderInertial(m, r, h, Eigen::Vector3d::Zero());
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity(); // the link frame in the body's
    pose.linear() = rotation().transpose();
    pose.translation() = -rotation().transpose() * c;
    const InertialParameters turned = transformedInertial(along, pose);
    const LinkPlausibility v = verdictOf(turned, along);
    LEARNID_COMPARE_NEAR(v.mass, m, 1e-14);
    const double side = m * (3.0 * r * r + h * h) / 12.0;
    LEARNID_COMPARE_MATRIX(v.moments, Eigen::Vector3d(0.5 * m * r * r, side, side), 1e-12);
    LEARNID_COMPARE_NEAR(v.cadSmallestMoment, 0.5 * m * r * r, 1e-14);
    LEARNID_COMPARE_NEAR(v.triangleRatio, (0.5 * m * r * r + side) / side, 1e-10);
    QVERIFY(v.momentsOk);
    QVERIFY(v.triangleOk);
    QVERIFY(v.plausible);
}

void TestPlausibility::triangle_rodAndPlateFailCubeAndCloudsPass()
{
    // A rod of radius 2 mm and length 0.5 m: (I1 + I2) / I3 = 1 + 6 r^2 / (3 r^2 + h^2) - tiny.
    const double r = 0.002, h = 0.5;
    const Vector10d rod = cylinderInertial(1.0, r, h, Eigen::Vector3d(0.0, 0.0, 0.25));
    const LinkPlausibility rv = verdictOf(rod, rod);
    LEARNID_COMPARE_NEAR(rv.triangleRatio, 1.0 + 6.0 * r * r / (3.0 * r * r + h * h), 1e-9);
    QVERIFY(!rv.triangleOk);
    QVERIFY(!rv.plausible);
    // A square plate 0.4 x 0.4 x 0.0004: ratio 1 + (t/a)^2 exactly for a box.
    const Box plate{2.0, {0.4, 0.4, 0.0004}, rotation(), {0.1, 0.1, 0.0}};
    const LinkPlausibility pv = verdictOf(boxInertial(plate), boxInertial(plate));
    LEARNID_COMPARE_NEAR(pv.triangleRatio, 1.0 + 1e-6, 1e-9);
    QVERIFY(!pv.triangleOk);
    // A cube: I1 = I2 = I3, ratio 2.
    const Box cube{1.0, {0.2, 0.2, 0.2}, rotation(), {0.0, 0.0, 0.1}};
    const LinkPlausibility cv = verdictOf(boxInertial(cube), boxInertial(cube));
    LEARNID_COMPARE_NEAR(cv.triangleRatio, 2.0, 1e-9);
    QVERIFY(cv.triangleOk);
    QVERIFY(cv.plausible);
    // Any real mass distribution meets I1 + I2 >= I3; the rule's margin 2 % lets plate-like
    // clouds fail. A cloud in a thick box passes; one squeezed to 1 mm does not.
    const Cloud thick =
        randomCloud(500, Eigen::Vector3d(-0.1, -0.1, -0.1), Eigen::Vector3d(0.2, 0.1, 0.05), 3);
    const LinkPlausibility tv = verdictOf(thick.inertial(), thick.inertial());
    QVERIFY(tv.triangleRatio >= 1.0);
    QVERIFY(tv.triangleOk);
    const Cloud flat =
        randomCloud(500, Eigen::Vector3d(-0.1, -0.1, 0.0), Eigen::Vector3d(0.2, 0.1, 0.001), 5);
    const LinkPlausibility fv = verdictOf(flat.inertial(), thick.inertial());
    QVERIFY(fv.triangleRatio >= 1.0);
    QVERIFY(fv.triangleRatio < 1.02);
    QVERIFY(!fv.triangleOk);
}

void TestPlausibility::moments_shareOfTheCadSmallestDecides()
{
    // The same box shape at 4 % and 6 % of the CAD mass: its moments scale with the mass.
    const Box cadBox = sampleBox();
    Box light = cadBox;
    light.mass = 0.04 * cadBox.mass;
    Box lighter = cadBox;
    lighter.mass = 0.06 * cadBox.mass;
    const Vector10d cad = boxInertial(cadBox);
    const LinkPlausibility a = verdictOf(boxInertial(light), cad);
    const LinkPlausibility b = verdictOf(boxInertial(lighter), cad);
    LEARNID_COMPARE_NEAR(a.moments[0] / a.cadSmallestMoment, 0.04, 1e-12);
    QVERIFY(!a.momentsOk);
    QVERIFY(a.triangleOk);
    QVERIFY(!a.plausible);
    QVERIFY(b.momentsOk);
    QVERIFY(b.plausible);
    PlausibilityRule strict;
    strict.minMomentShare = 0.1;
    QVERIFY(!checkPlausibility(boxInertial(lighter), cad, 1, {}, strict).front().momentsOk);
}

void TestPlausibility::pointMass_isNotPlausible()
{
    const Vector10d point =
        inertialOf(2.0, Eigen::Matrix3d::Zero(), Eigen::Vector3d(0.1, 0.2, 0.3));
    const LinkPlausibility v = verdictOf(point, boxInertial(sampleBox()));
    LEARNID_COMPARE_MATRIX(v.moments, Eigen::Vector3d::Zero(), 1e-14);
    QVERIFY(!v.momentsOk);
    QVERIFY(!v.plausible);
    // Even against a CAD point mass: a link has size.
    QVERIFY(!verdictOf(point, point).plausible);
    // No mass at all: nothing holds.
    const LinkPlausibility none = verdictOf(Vector10d::Zero(), boxInertial(sampleBox()));
    QVERIFY(!none.momentsOk);
    QVERIFY(!none.triangleOk);
    QVERIFY(!none.plausible);
}

void TestPlausibility::volume_centreOfMassOutsideFails()
{
    const Box cadBox = sampleBox();
    const BoundingEllipsoid volume = ellipsoidFromInertia(boxInertial(cadBox), 2.0, 0.0);
    const LinkPlausibility inside = verdictOf(boxInertial(cadBox), boxInertial(cadBox), volume);
    QVERIFY(inside.hasVolume);
    LEARNID_COMPARE_NEAR(inside.comDistance, 0.0, 1e-12);
    QVERIFY(inside.volumeOk);
    QVERIFY(inside.fitShare > 0.0);
    QVERIFY(inside.plausible);
    // The same body moved 1.1 semi-axes along the box's long axis: its centre lies outside.
    Box moved = cadBox;
    moved.centre += 1.1 * volume.axes.col(2).norm() * volume.axes.col(2).normalized();
    const LinkPlausibility outside = verdictOf(boxInertial(moved), boxInertial(cadBox), volume);
    LEARNID_COMPARE_NEAR(outside.comDistance, 1.21, 1e-9);
    QVERIFY(!outside.volumeOk);
    QVERIFY(outside.momentsOk);
    QVERIFY(!outside.plausible);
    // Without a volume the centre of mass is not judged.
    const LinkPlausibility free = verdictOf(boxInertial(moved), boxInertial(cadBox));
    QVERIFY(!free.hasVolume);
    QVERIFY(free.volumeOk);
}

void TestPlausibility::linkVolumes_geometryWhenItHoldsTheCadBodyElseCadInertia()
{
    SerialChain chain;
    chain.joints.resize(3);
    const Vector10d cylinder = cylinderInertial(2.0, 0.05, 0.3, Eigen::Vector3d(0.0, 0.0, 0.15));
    Eigen::VectorXd cad(30);
    cad << cylinder, cylinder, Vector10d::Zero();
    // Link 0: its geometry holds it. Link 1: a box at the far end only. Link 2: no mass.
    chain.joints[0].geometryBox =
        Eigen::AlignedBox3d(Eigen::Vector3d(-0.05, -0.05, 0.0), Eigen::Vector3d(0.05, 0.05, 0.3));
    chain.joints[0].geometryDescription = QStringLiteral("1 cylinder");
    chain.joints[1].geometryBox =
        Eigen::AlignedBox3d(Eigen::Vector3d(-0.05, -0.05, 0.6), Eigen::Vector3d(0.05, 0.05, 0.7));
    chain.joints[2].geometryBox = chain.joints[0].geometryBox;
    const auto volumes = linkVolumes(chain, cad);
    QCOMPARE(volumes.size(), size_t(3));
    QVERIFY(volumes[0].has_value());
    QCOMPARE(volumes[0]->source, VolumeSource::Geometry);
    QCOMPARE(volumes[0]->description, QStringLiteral("1 cylinder"));
    LEARNID_COMPARE_MATRIX(volumes[0]->centre, Eigen::Vector3d(0.0, 0.0, 0.15), 1e-15);
    QVERIFY(volumes[1].has_value());
    QCOMPARE(volumes[1]->source, VolumeSource::CadInertia);
    LEARNID_COMPARE_MATRIX(volumes[1]->centre, Eigen::Vector3d(0.0, 0.0, 0.15), 1e-14);
    QVERIFY(!volumes[2].has_value());
    QVERIFY_THROWS_EXCEPTION(Error, linkVolumes(chain, cad.head(20)));
}

void TestPlausibility::tinyJointTerms_listsValuesBetweenZeroAndTheFloor()
{
    Eigen::VectorXd standard(14);
    standard << Vector10d::Zero(), 6e-169, 0.0, 1e-6, 0.3;
    QCOMPARE(tinyJointTerms(standard, {10, 11, 12, 13}), std::vector<int>({10}));
    PlausibilityRule rule;
    rule.termFloor = 1e-5;
    QCOMPARE(tinyJointTerms(standard, {10, 11, 12, 13}, rule), std::vector<int>({10, 12}));
    QVERIFY_THROWS_EXCEPTION(Error, tinyJointTerms(standard, {14}));
    QVERIFY_THROWS_EXCEPTION(Error, tinyJointTerms(standard, {-1}));
}

void TestPlausibility::badInput_throws()
{
    const Vector10d box = boxInertial(sampleBox());
    QVERIFY_THROWS_EXCEPTION(Error, checkPlausibility(box, box, 2, {}));
    QVERIFY_THROWS_EXCEPTION(Error, checkPlausibility(box, box, 1, {std::nullopt, std::nullopt}));
    Vector10d broken = box;
    broken[4] = std::numeric_limits<double>::quiet_NaN();
    QVERIFY_THROWS_EXCEPTION(Error, checkPlausibility(broken, box, 1, {}));
    QVERIFY_THROWS_EXCEPTION(Error, checkPlausibility(box, broken, 1, {}));
    QVERIFY_THROWS_EXCEPTION(Error, checkPlausibility(box, box, -1, {}));
}

QTEST_GUILESS_MAIN(TestPlausibility)
#include "tst_plausibility.moc"
