// The per-link verdict (LinkVerdictTable, EstimateConsistency::describe()) on a two-link arm whose
// verdicts follow from the equations of a box: link 2 identified as a flat plate of the CAD
// box's outline (I1 + I2 = I3 exactly, a ratio of 1 below the rule's 1.02), link 1 as the CAD's
// solid box, then a link without mass and a Coulomb friction that is an underflow.
#include "../support/NumericAssert.h"
#include "model/ChainModel.h"
#include "model/ModelCheck.h"
#include "model/UrdfChain.h"
#include "session/EstimateConsistency.h"
#include "session/LinkVerdictTable.h"

#include <QRegularExpression>
#include <QTest>

using namespace learnid;

namespace {

// Link 1: a solid box 0.1 x 0.1 x 0.4 m of 2 kg; link 2: 0.3 x 0.2 x 0.05 m of 1 kg, each
// centred on its link frame, with a collision box of the same size.
const QByteArray urdf = R"(<robot name="boxes">
  <link name="base"/>
  <link name="link1">
    <inertial><mass value="2"/><origin xyz="0 0 0"/>
      <inertia ixx="0.028333333333333333" ixy="0" ixz="0" iyy="0.028333333333333333" iyz="0"
               izz="0.0033333333333333335"/></inertial>
    <collision><geometry><box size="0.1 0.1 0.4"/></geometry></collision>
  </link>
  <link name="link2">
    <inertial><mass value="1"/><origin xyz="0 0 0"/>
      <inertia ixx="0.0035416666666666665" ixy="0" ixz="0" iyy="0.0077083333333333335" iyz="0"
               izz="0.010833333333333334"/></inertial>
    <collision><geometry><box size="0.3 0.2 0.05"/></geometry></collision>
  </link>
  <joint name="j1" type="revolute"><parent link="base"/><child link="link1"/>
    <axis xyz="0 0 1"/><limit lower="-3" upper="3" effort="50" velocity="2"/></joint>
  <joint name="j2" type="revolute"><parent link="link1"/><child link="link2"/>
    <origin xyz="0 0 0.4"/><axis xyz="0 1 0"/>
    <limit lower="-3" upper="3" effort="50" velocity="2"/></joint>
</robot>)";

// Box moments about its centre, ascending: m (b^2 + c^2) / 12 and so on.
Eigen::Vector3d boxMoments(double m, double a, double b, double c)
{
    Eigen::Vector3d i(m * (b * b + c * c) / 12, m * (a * a + c * c) / 12, m * (a * a + b * b) / 12);
    std::sort(i.data(), i.data() + 3);
    return i;
}

QStringList cells(const QString &line)
{
    return line.split(QRegularExpression(QStringLiteral("\\s{2,}")), Qt::SkipEmptyParts);
}

} // namespace

class TestLinkVerdictTable : public QObject
{
    Q_OBJECT

private slots:
    void flatPlate_failsTheTriangleRule_andTheTableSaysWhy();
    void noMassAndUnderflow_areNotConsistentOrNotPlausible();
};

void TestLinkVerdictTable::flatPlate_failsTheTriangleRule_andTheTableSaysWhy()
{
    const ChainModel model(parseUrdfChain(urdf, QStringLiteral("boxes.urdf")),
                           JointTerms{false, true, true, false}, QStringLiteral("urdf"));
    Eigen::VectorXd pi = model.cadStandard();
    // Link 2 as a plate 0.3 x 0.2 m without thickness: Ixx = m b^2/12, Iyy = m a^2/12, Izz their
    // sum, so (I1 + I2) / I3 = 1.
    pi.segment<6>(14) << 0.04 / 12, 0, 0.09 / 12, 0, 0, 0.13 / 12;
    const EstimateConsistency verdict = checkStandardConsistency(model, pi);
    QVERIFY(verdict.consistent);
    QVERIFY(!verdict.plausible);

    const LinkVerdictTable table = linkVerdictTable(model, verdict);
    QCOMPARE(table.header.size(), 7);
    QCOMPARE(table.rows.size(), 2);
    const Eigen::Vector3d solid1 = boxMoments(2, 0.1, 0.1, 0.4);
    const Eigen::Vector3d solid2 = boxMoments(1, 0.3, 0.2, 0.05);
    QCOMPARE(table.rows[0],
             (QStringList{QStringLiteral("1 link1"), QString::number(solid1[0], 'g', 3),
                          QString::number(solid1[0], 'g', 3),
                          QString::number((solid1[0] + solid1[1]) / solid1[2], 'f', 3),
                          QStringLiteral("yes"), QStringLiteral("yes"), QStringLiteral("yes")}));
    QCOMPARE(table.rows[1],
             (QStringList{QStringLiteral("2 link2"), QString::number(0.04 / 12, 'g', 3),
                          QString::number(solid2[0], 'g', 3), QStringLiteral("1.000"),
                          QStringLiteral("yes"), QStringLiteral("yes"), QStringLiteral("no")}));
    QCOMPARE(table.plausible, (QList<bool>{true, false}));

    // As text: the header, then each row's cells in their columns.
    const QStringList lines = linkVerdictText(table).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    QCOMPARE(lines.size(), 3);
    QCOMPARE(cells(lines[0]), table.header);
    QCOMPARE(cells(lines[2]), table.rows[1]);
    for (const QString &line : lines) // right-aligned under the header's last column
        QCOMPARE(line.size(), lines[0].size());

    // describe(): the verdict first, then why, in modelProblems()' words.
    const QStringList described = verdict.describe(model);
    QCOMPARE(described.size(), 2);
    QCOMPARE(described[0],
             QStringLiteral("physically consistent (every link a real body) but not plausible"));
    QCOMPARE(described[1], QStringLiteral("link 2 (link2): its principal moments 0.00333, 0.0075 "
                                          "and 0.0108 kg m^2 give I1 + I2 = 1.000 I3, below "
                                          "1.020 I3 (a flat plate at best)"));
    // The CAD model itself: plausible, and said so.
    const EstimateConsistency cad = checkStandardConsistency(model, model.cadStandard());
    QVERIFY(cad.plausible);
    QCOMPARE(cad.describe(model),
             QStringList{QStringLiteral("physically consistent and plausible: every link a real "
                                        "body that a robot's link could be")});
}

void TestLinkVerdictTable::noMassAndUnderflow_areNotConsistentOrNotPlausible()
{
    const ChainModel model(parseUrdfChain(urdf, QStringLiteral("boxes.urdf")),
                           JointTerms{false, true, true, false}, QStringLiteral("urdf"));
    Eigen::VectorXd pi = model.cadStandard();
    pi.segment<10>(0).setZero(); // link 1 without mass
    const int fc2 = 20 + 2 + 1;  // joint 2's terms after 20 inertia entries: fv, fc
    pi[fc2] = 1e-9;
    const EstimateConsistency verdict = checkStandardConsistency(model, pi);
    QVERIFY(!verdict.consistent);
    QCOMPARE(verdict.tinyTerms, std::vector<int>{fc2});

    const LinkVerdictTable table = linkVerdictTable(model, verdict);
    QCOMPARE(
        table.rows[0].mid(1),
        (QStringList{QStringLiteral("-"), QString::number(boxMoments(2, 0.1, 0.1, 0.4)[0], 'g', 3),
                     QStringLiteral("-"), QStringLiteral("-"), QStringLiteral("no"),
                     QStringLiteral("no")}));
    QCOMPARE(table.rows[1].mid(4),
             (QStringList{QStringLiteral("yes"), QStringLiteral("yes"), QStringLiteral("yes")}));

    const QStringList described = verdict.describe(model);
    QCOMPARE(described,
             (QStringList{QStringLiteral("not physically consistent"),
                          QStringLiteral("link 1 (link1): its mass is 0 kg: not a real body"),
                          QStringLiteral("joint 2 (j2): %1 is 1e-09, between 0 and 1e-06: the "
                                         "underflow of a positive parametrisation where 0 is meant")
                              .arg(model.standardParameters()[fc2].name)}));
}

QTEST_GUILESS_MAIN(TestLinkVerdictTable)
#include "tst_linkverdicttable.moc"
