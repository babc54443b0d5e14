// The geometry box of each moving body (UrdfChain, UrdfGeometry, MeshBounds) against boxes worked
// out by hand and against sampled surfaces; mesh files written here (STL, OBJ, COLLADA) found by
// relative name, through ROS_PACKAGE_PATH and from the URDF's package; unreadable meshes skipped;
// learnid's URDF extension element read back.

#include "../support/NumericAssert.h"
#include "../support/SharedData.h"
#include "model/CadPrior.h"
#include "model/ChainModel.h"
#include "model/Error.h"
#include "model/MeshBounds.h"
#include "model/Plausibility.h"
#include "model/UrdfChain.h"
#include "model/UrdfGeometry.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>
#include <QTest>
#include <cmath>
#include <random>

using namespace learnid;

namespace {

void writeText(const QString &path, const QByteArray &text)
{
    QDir().mkpath(QFileInfo(path).absolutePath());
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(text);
}

// Vertices span [-0.5, 0, 0] .. [1, 2, 3].
const QByteArray stlText = "solid part\n"
                           "facet normal 0 0 1\n"
                           " outer loop\n"
                           "  vertex 0 0 0\n"
                           "  vertex 1 0 0\n"
                           "  vertex 0 2 0\n"
                           " endloop\n"
                           "endfacet\n"
                           "facet normal 1 0 0\n"
                           " outer loop\n"
                           "  vertex 0 0 0\n"
                           "  vertex 0 2 0\n"
                           "  vertex -0.5 0 3\n"
                           " endloop\n"
                           "endfacet\n"
                           "endsolid part\n";

// Vertices span [0, 0, 0] .. [0.2, 0.3, 0.1].
const QByteArray objText = "v 0 0 0\nv 0.2 0 0\nv 0 0.3 0.1\nf 1 2 3\n";

// In millimetres, Z up: [0, 0, 0] .. [100, 200, 300] mm, i.e. [0 .. 0.1, 0.2, 0.3] m unturned.
const QByteArray daeText =
    "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n"
    "<COLLADA xmlns=\"http://www.collada.org/2005/11/COLLADASchema\" version=\"1.4.1\">\n"
    "  <asset><unit name=\"millimeter\" meter=\"0.001\"/><up_axis>Z_UP</up_axis></asset>\n"
    "  <library_geometries>\n"
    "    <geometry id=\"g\" name=\"g\"><mesh>\n"
    "      <source id=\"g-pos\">\n"
    "        <float_array id=\"g-pos-array\" count=\"9\">0 0 0 100 0 0 0 200 300</float_array>\n"
    "        <technique_common><accessor source=\"#g-pos-array\" count=\"3\" stride=\"3\">\n"
    "          <param name=\"X\" type=\"float\"/><param name=\"Y\" type=\"float\"/><param "
    "name=\"Z\" type=\"float\"/>\n"
    "        </accessor></technique_common>\n"
    "      </source>\n"
    "      <vertices id=\"g-vtx\"><input semantic=\"POSITION\" source=\"#g-pos\"/></vertices>\n"
    "      <triangles count=\"1\"><input semantic=\"VERTEX\" source=\"#g-vtx\" offset=\"0\"/><p>0 "
    "1 2</p></triangles>\n"
    "    </mesh></geometry>\n"
    "  </library_geometries>\n"
    "  <library_visual_scenes>\n"
    "    <visual_scene id=\"s\"><node id=\"n\"><instance_geometry "
    "url=\"#g\"/></node></visual_scene>\n"
    "  </library_visual_scenes>\n"
    "  <scene><instance_visual_scene url=\"#s\"/></scene>\n"
    "</COLLADA>\n";

const char *limit = "<limit effort=\"10\" velocity=\"1\" lower=\"-1\" upper=\"1\"/>";

// Two moving bodies: l1 (a turned box, a cylinder along x, and the fixed "tool" with only a
// visual sphere) and l2 (meshes: found, missing, broken).
QByteArray shapesUrdf(const QByteArray &l1Extra = {})
{
    return QByteArray("<robot name=\"shapes\">\n"
                      "  <link name=\"base\"/>\n"
                      "  <joint name=\"j1\" type=\"revolute\"><parent link=\"base\"/><child "
                      "link=\"l1\"/><axis xyz=\"0 0 1\"/>") +
           limit + l1Extra +
           "</joint>\n"
           "  <link name=\"l1\">\n"
           "    <inertial><mass value=\"1\"/><inertia ixx=\"0.01\" iyy=\"0.01\" izz=\"0.01\" "
           "ixy=\"0\" ixz=\"0\" iyz=\"0\"/></inertial>\n"
           "    <collision><origin xyz=\"0.1 0 0\" rpy=\"0 0 1.5707963267948966\"/><geometry><box "
           "size=\"0.4 0.2 0.1\"/></geometry></collision>\n"
           "    <collision><origin xyz=\"0 0 0.5\" rpy=\"0 1.5707963267948966 "
           "0\"/><geometry><cylinder radius=\"0.05\" length=\"0.6\"/></geometry></collision>\n"
           "    <visual><geometry><sphere radius=\"5\"/></geometry></visual>\n"
           "  </link>\n"
           "  <joint name=\"tool_joint\" type=\"fixed\"><parent link=\"l1\"/><child "
           "link=\"tool\"/><origin xyz=\"0 0 1\"/></joint>\n"
           "  <link name=\"tool\"><visual><origin xyz=\"0 0.1 0\"/><geometry><sphere "
           "radius=\"0.02\"/></geometry></visual></link>\n"
           "  <joint name=\"j2\" type=\"revolute\"><parent link=\"tool\"/><child "
           "link=\"l2\"/><origin xyz=\"0 0 0.2\"/><axis xyz=\"0 1 0\"/>" +
           limit +
           "</joint>\n"
           "  <link name=\"l2\">\n"
           "    <inertial><mass value=\"1\"/><inertia ixx=\"0.01\" iyy=\"0.01\" izz=\"0.01\" "
           "ixy=\"0\" ixz=\"0\" iyz=\"0\"/></inertial>\n"
           "    <collision><geometry><mesh filename=\"meshes/part.stl\" scale=\"0.1 0.1 "
           "-0.1\"/></geometry></collision>\n"
           "    <collision><geometry><mesh "
           "filename=\"package://mypkg/meshes/part.obj\"/></geometry></collision>\n"
           "    <collision><geometry><mesh "
           "filename=\"meshes/missing.stl\"/></geometry></collision>\n"
           "    <collision><geometry><mesh "
           "filename=\"meshes/broken.stl\"/></geometry></collision>\n"
           "    <collision><origin xyz=\"0 0 1\"/><geometry><mesh "
           "filename=\"meshes/part.dae\"/></geometry></collision>\n"
           "  </link>\n"
           "</robot>";
}

Eigen::AlignedBox3d box(double x0, double y0, double z0, double x1, double y1, double z1)
{
    return {Eigen::Vector3d(x0, y0, z0), Eigen::Vector3d(x1, y1, z1)};
}

void compareBox(const Eigen::AlignedBox3d &actual, const Eigen::AlignedBox3d &expected,
                double tolerance)
{
    QVERIFY(!actual.isEmpty());
    LEARNID_COMPARE_MATRIX(actual.min(), expected.min(), tolerance);
    LEARNID_COMPARE_MATRIX(actual.max(), expected.max(), tolerance);
}

} // namespace

class TestUrdfGeometry : public QObject
{
    Q_OBJECT

private slots:
    void placedCylinder_equalsTheBoxOfItsSampledRims();
    void primitives_turnedAndMergedWithFixedLinks();
    void meshes_foundReadScaledAndUnreadableOnesSkipped();
    void locateMesh_packageFromTheUrdfsFolderAndNoDevices();
    void kukaLwr4_collisionSpheresAndCylinders();
    void badShapes_areRefusedNamingLinkAndShape();
    void extension_armatureAndOffsetReadIntoTheModel();
    void extension_badValues_nameLineAndColumn();
};

void TestUrdfGeometry::placedCylinder_equalsTheBoxOfItsSampledRims()
{
    std::mt19937 random(5);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (int trial = 0; trial < 5; ++trial) {
        Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
        pose.linear() = Eigen::AngleAxisd(
                            3.0 * unit(random),
                            Eigen::Vector3d(unit(random), unit(random), unit(random)).normalized())
                            .toRotationMatrix();
        pose.translation() = Eigen::Vector3d(unit(random), unit(random), unit(random));
        const double r = 0.05 + 0.1 * std::abs(unit(random)), l = 0.3;
        // The solid's box is the box of its two end circles.
        Eigen::AlignedBox3d sampled;
        for (int k = 0; k < 20000; ++k) {
            const double a = 2.0 * M_PI * k / 20000.0;
            for (const double z : {-0.5 * l, 0.5 * l})
                sampled.extend(pose * Eigen::Vector3d(r * std::cos(a), r * std::sin(a), z));
        }
        compareBox(placedCylinder(r, l, pose), sampled, 1e-7);
        // The sphere does not depend on the turn; the box is the box of its corners.
        compareBox(placedSphere(r, pose),
                   Eigen::AlignedBox3d(pose.translation() - Eigen::Vector3d::Constant(r),
                                       pose.translation() + Eigen::Vector3d::Constant(r)),
                   0.0);
        const Eigen::AlignedBox3d own(Eigen::Vector3d(-0.1, -0.2, 0.0),
                                      Eigen::Vector3d(0.3, 0.2, 0.1));
        Eigen::AlignedBox3d corners;
        for (int c = 0; c < 8; ++c)
            corners.extend(pose * own.corner(Eigen::AlignedBox3d::CornerType(c)));
        QVERIFY(placedBox(own, pose).isApprox(corners));
    }
}

void TestUrdfGeometry::primitives_turnedAndMergedWithFixedLinks()
{
    const SerialChain chain = parseUrdfChain(shapesUrdf(), QStringLiteral("shapes.urdf"));
    QCOMPARE(chain.dof(), 2);
    // Box turned 90 deg about z at (0.1, 0, 0): [0, -0.2, -0.05]..[0.2, 0.2, 0.05]; cylinder
    // along x at z 0.5: [-0.3, -0.05, 0.45]..[0.3, 0.05, 0.55]; the tool's visual sphere at
    // (0, 0.1, 1): [-0.02, 0.08, 0.98]..[0.02, 0.12, 1.02]. The link's own visual sphere of 5 m
    // is not used: it has collision shapes.
    compareBox(chain.joints[0].geometryBox, box(-0.3, -0.2, -0.05, 0.3, 0.2, 1.02), 1e-12);
    QCOMPARE(chain.joints[0].geometryDescription,
             QStringLiteral("1 box, 1 cylinder, 1 sphere; visual shapes of tool (no collision "
                            "shape)"));
    // Without a folder to look in, the relative meshes are skipped, the package one too.
    QVERIFY(chain.joints[1].geometryBox.isEmpty());
    QVERIFY(chain.joints[1].geometryDescription.contains(
        QLatin1String("mesh \"meshes/part.stl\" of link \"l2\" skipped")));
}

void TestUrdfGeometry::meshes_foundReadScaledAndUnreadableOnesSkipped()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    writeText(dir.filePath(QStringLiteral("robot/meshes/part.stl")), stlText);
    writeText(dir.filePath(QStringLiteral("robot/meshes/broken.stl")), "solid x\nnot a facet\n");
    writeText(dir.filePath(QStringLiteral("robot/meshes/part.dae")), daeText);
    writeText(dir.filePath(QStringLiteral("ws/mypkg/meshes/part.obj")), objText);
    const QString urdf = dir.filePath(QStringLiteral("robot/shapes.urdf"));
    writeText(urdf, shapesUrdf());
    qputenv("ROS_PACKAGE_PATH", (dir.filePath(QStringLiteral("nowhere")) + QLatin1Char(':') +
                                 dir.filePath(QStringLiteral("ws")))
                                    .toLocal8Bit());
    const SerialChain chain = readUrdfChain(urdf);
    qunsetenv("ROS_PACKAGE_PATH");
    // STL scaled (0.1, 0.1, -0.1): [-0.05, 0, -0.3]..[0.1, 0.2, 0]; OBJ: [0, 0, 0]..[0.2, 0.3,
    // 0.1]; COLLADA in mm, Z up as written, at z + 1: [0, 0, 1]..[0.1, 0.2, 1.3].
    compareBox(chain.joints[1].geometryBox, box(-0.05, 0.0, -0.3, 0.2, 0.3, 1.3), 1e-6);
    const QString d = chain.joints[1].geometryDescription;
    QVERIFY2(d.startsWith(QLatin1String("3 meshes; ")), qPrintable(d));
    QVERIFY2(d.contains(QLatin1String("mesh \"meshes/missing.stl\" of link \"l2\" skipped: no "
                                      "such file")),
             qPrintable(d));
    QVERIFY2(d.contains(QLatin1String("mesh \"meshes/broken.stl\" of link \"l2\" skipped: has "
                                      "no vertices")),
             qPrintable(d));
    // The same file read again comes from the cache with the same box.
    QString problem;
    const auto again = meshBounds(dir.filePath(QStringLiteral("robot/meshes/part.stl")), &problem);
    QVERIFY(again.has_value());
    compareBox(*again, box(-0.5, 0.0, 0.0, 1.0, 2.0, 3.0), 1e-6);
    QVERIFY(problem.isEmpty());
}

void TestUrdfGeometry::locateMesh_packageFromTheUrdfsFolderAndNoDevices()
{
    QTemporaryDir dir;
    writeText(dir.filePath(QStringLiteral("pkg2/meshes/part.stl")), stlText);
    const QString urdfDir = dir.filePath(QStringLiteral("pkg2/urdf"));
    QDir().mkpath(urdfDir);
    const MeshLocation found =
        locateMesh(QStringLiteral("package://pkg2/meshes/part.stl"), urdfDir, {});
    QCOMPARE(QFileInfo(found.path).canonicalFilePath(),
             QFileInfo(dir.filePath(QStringLiteral("pkg2/meshes/part.stl"))).canonicalFilePath());
    QVERIFY(found.problem.isEmpty());
    const MeshLocation absolute = locateMesh(
        QStringLiteral("file://") + dir.filePath(QStringLiteral("pkg2/meshes/part.stl")), {}, {});
    QVERIFY(!absolute.path.isEmpty());
    QVERIFY(locateMesh(QStringLiteral("package://other/part.stl"), urdfDir, {}).path.isEmpty());
    QVERIFY(locateMesh(QStringLiteral("package://"), urdfDir, {}).path.isEmpty());
    // A device is not a mesh: never opened.
    const MeshLocation device = locateMesh(QStringLiteral("/dev/zero"), {}, {});
    QVERIFY(device.path.isEmpty());
    QCOMPARE(device.problem, QStringLiteral("no such file"));
}

void TestUrdfGeometry::kukaLwr4_collisionSpheresAndCylinders()
{
    const QString urdf = test::sharedDataFile(QStringLiteral("kuka-lwr4/kuka_lwr4.urdf"));
    if (urdf.isEmpty())
        QSKIP(qPrintable(test::sharedDataMissing()));
    const SerialChain chain = readUrdfChain(urdf);
    QCOMPARE(chain.dof(), 7);
    // lwr_1_link: spheres r 0.07 at (0, 0, 0) and (0, 0.06, 0.2); a cylinder r 0.07, length
    // 0.208 at (0, 0.03, 0.1) turned -0.291 rad about x, inside the spheres' box:
    // its y reach 0.104 sin 0.291 + 0.07 cos 0.291 = 0.0969, z reach 0.1197.
    compareBox(chain.joints[0].geometryBox, box(-0.07, -0.07, -0.07, 0.07, 0.13, 0.27), 1e-12);
    QCOMPARE(chain.joints[0].geometryDescription, QStringLiteral("1 cylinder, 2 spheres"));
    // lwr_6_link has meshes only, from a package that is not here: skipped, and said so.
    for (int j = 0; j < 7; ++j)
        QVERIFY2(chain.joints[size_t(j)].geometryBox.isEmpty() == (j == 5),
                 qPrintable(chain.joints[size_t(j)].link));
    QCOMPARE(chain.joints[5].geometryDescription,
             QStringLiteral("mesh \"package://lwr_description/meshes/kuka/convex/"
                            "arm_wrist_convex.stl\" of link \"lwr_6_link\" skipped: package "
                            "\"lwr_description\" not found (ROS_PACKAGE_PATH, the URDF's folder); "
                            "mesh \"package://lwr_description/meshes/kuka/link_6.STL\" of link "
                            "\"lwr_6_link\" skipped: package \"lwr_description\" not found "
                            "(ROS_PACKAGE_PATH, the URDF's folder)"));
    // The CAD bodies fit their geometry: their ellipsoids are the geometry's, and each CAD
    // link is plausible in it.
    const ChainModel model(chain, JointTerms{}, QStringLiteral("urdf"));
    const Eigen::VectorXd prior = realBodyPrior(model.cadStandard(), 7);
    const auto volumes = linkVolumes(chain, prior);
    int fromGeometry = 0;
    for (const auto &v : volumes)
        fromGeometry += v && v->source == VolumeSource::Geometry;
    QVERIFY2(fromGeometry >= 5, qPrintable(QString::number(fromGeometry)));
    QVERIFY(volumes[5] && volumes[5]->source == VolumeSource::CadInertia);
    for (const LinkPlausibility &v : checkPlausibility(prior, prior, 7, volumes))
        QVERIFY2(v.volumeOk, qPrintable(QString::number(v.link)));
}

void TestUrdfGeometry::badShapes_areRefusedNamingLinkAndShape()
{
    QByteArray urdf = shapesUrdf();
    urdf.replace("<cylinder radius=\"0.05\" length=\"0.6\"/>",
                 "<cylinder radius=\"-0.05\" length=\"0.6\"/>");
    try {
        parseUrdfChain(urdf, QStringLiteral("bad.urdf"));
        QFAIL("a cylinder of negative radius was accepted");
    } catch (const Error &e) {
        QCOMPARE(e.message(), QStringLiteral("bad.urdf: link \"l1\", <collision> 2: the "
                                             "cylinder's radius or length is negative or not a "
                                             "number"));
    }
}

void TestUrdfGeometry::extension_armatureAndOffsetReadIntoTheModel()
{
    const SerialChain chain =
        parseUrdfChain(shapesUrdf("<learnid:dynamics armature=\"0.02\" offset=\"-0.35\"/>"),
                       QStringLiteral("shapes.urdf"));
    QCOMPARE(chain.joints[0].armature, 0.02);
    QCOMPARE(chain.joints[0].offset, -0.35);
    QCOMPARE(chain.joints[1].armature, 0.0);
    QCOMPARE(chain.joints[1].offset, 0.0);
    JointTerms all;
    all.armature = all.offset = true;
    const ChainModel model(chain, all, QStringLiteral("urdf"));
    // Joint 1's terms: armature, viscous, Coulomb, offset after the 20 inertia entries.
    QCOMPARE(model.cadStandard()[20], 0.02);
    QCOMPARE(model.cadStandard()[23], -0.35);
    // Torque: the offset adds -0.35 at rest, the armature 0.02 qdd.
    Eigen::Vector2d tauRest, tauAccelerated;
    const Eigen::Vector2d zero = Eigen::Vector2d::Zero();
    const Eigen::VectorXd phi = model.baseFromStandard(model.cadStandard());
    model.inverseDynamics(zero, zero, zero, phi, tauRest);
    model.inverseDynamics(zero, zero, Eigen::Vector2d(1.0, 0.0), phi, tauAccelerated);
    JointTerms none;
    none.viscous = none.coulomb = false;
    const ChainModel bare(chain, none, QStringLiteral("urdf"));
    Eigen::Vector2d bareAccelerated;
    bare.inverseDynamics(zero, zero, Eigen::Vector2d(1.0, 0.0),
                         bare.baseFromStandard(bare.cadStandard()), bareAccelerated);
    LEARNID_COMPARE_NEAR(tauRest[0], -0.35, 1e-12);
    LEARNID_COMPARE_NEAR(tauAccelerated[0] - tauRest[0], bareAccelerated[0] + 0.02, 1e-12);
}

void TestUrdfGeometry::extension_badValues_nameLineAndColumn()
{
    const auto messageOf = [](const QByteArray &extra) {
        try {
            parseUrdfChain(shapesUrdf(extra), QStringLiteral("ext.urdf"));
        } catch (const Error &e) {
            return e.message();
        }
        return QString();
    };
    const QString nan = messageOf("<learnid:dynamics offset=\"nan\"/>");
    QVERIFY2(nan.startsWith(QLatin1String("ext.urdf: line 3, column ")) &&
                 nan.contains(QLatin1String("offset must be a finite number, got \"nan\"")),
             qPrintable(nan));
    const QString twice =
        messageOf("<learnid:dynamics offset=\"1\"/><learnid:dynamics offset=\"2\"/>");
    QVERIFY2(twice.contains(QLatin1String("given twice in joint \"j1\"")), qPrintable(twice));
    const QString unknown = messageOf("<learnid:dynamics stiffness=\"3\"/>");
    QVERIFY2(unknown.contains(QLatin1String("unknown attribute \"stiffness\"")),
             qPrintable(unknown));
}

QTEST_GUILESS_MAIN(TestUrdfGeometry)
#include "tst_urdfgeometry.moc"
