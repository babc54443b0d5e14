#include "../model/InertiaSamples.h"
#include "../support/ErrorOf.h"
#include "../support/SharedData.h"
#include "io/UrdfExport.h"
#include "model/UrdfChain.h"

#include <QDomDocument>
#include <QFile>
#include <QTest>
#include <random>
#include <urdf_parser/urdf_parser.h>

using namespace learnid;
using learnid::test::errorOf;

namespace {

// A two-joint arm on a base fixed to the world: a housing fixed in the middle of the chain
// (merged into j1's body), a tool at the tip and a camera off the chain (both merged into j2's),
// and a moving link without <inertial> of its own (fore).
const char twoJointArm[] = R"(<?xml version="1.0"?>
<robot name="two-joint">
  <material name="grey"><color rgba="0.5 0.5 0.5 1"/></material>
  <link name="world"/>
  <joint name="mount" type="fixed">
    <origin xyz="0 0 0.5"/><parent link="world"/><child link="base"/>
  </joint>
  <link name="base">
    <inertial><mass value="4"/><inertia ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.1"/></inertial>
    <visual><geometry><cylinder radius="0.1" length="0.2"/></geometry><material name="grey"/></visual>
  </link>
  <joint name="j1" type="revolute">
    <origin xyz="0 0 0.1" rpy="0 0 0.3"/><parent link="base"/><child link="upper"/>
    <axis xyz="0 0 1"/><limit lower="-2" upper="2" effort="50" velocity="2"/>
    <dynamics damping="0.5" friction="0.1"/>
  </joint>
  <link name="upper">
    <inertial><origin xyz="0 0 0.2"/><mass value="2"/><inertia ixx="0.02" ixy="0" ixz="0" iyy="0.02" iyz="0" izz="0.004"/></inertial>
    <visual><origin xyz="0 0 0.2"/><geometry><box size="0.05 0.05 0.4"/></geometry></visual>
    <collision><origin xyz="0 0 0.2"/><geometry><box size="0.05 0.05 0.4"/></geometry></collision>
  </link>
  <joint name="elbow_mount" type="fixed">
    <origin xyz="0 0 0.4" rpy="0.2 0 0"/><parent link="upper"/><child link="housing"/>
  </joint>
  <link name="housing">
    <inertial><origin xyz="0 0.01 0"/><mass value="0.8"/><inertia ixx="0.001" ixy="0" ixz="0" iyy="0.002" iyz="0" izz="0.001"/></inertial>
    <visual><geometry><sphere radius="0.05"/></geometry></visual>
  </link>
  <joint name="j2" type="revolute">
    <origin xyz="0 0 0.05"/><parent link="housing"/><child link="fore"/>
    <axis xyz="0 1 0"/><limit lower="-1.5" upper="1.5" effort="20" velocity="3"/>
  </joint>
  <link name="fore">
    <visual><origin xyz="0 0 0.15"/><geometry><box size="0.04 0.04 0.3"/></geometry></visual>
  </link>
  <joint name="tool_mount" type="fixed">
    <origin xyz="0 0 0.3" rpy="0 1.5707963267948966 0"/><parent link="fore"/><child link="tool"/>
  </joint>
  <link name="tool">
    <inertial><origin xyz="0.02 0 0"/><mass value="0.5"/><inertia ixx="0.0005" ixy="0" ixz="0" iyy="0.001" iyz="0" izz="0.001"/></inertial>
    <visual><geometry><cylinder radius="0.02" length="0.08"/></geometry></visual>
    <collision><geometry><cylinder radius="0.02" length="0.08"/></geometry></collision>
  </link>
  <joint name="camera_mount" type="fixed">
    <origin xyz="0.05 0 0.1"/><parent link="fore"/><child link="camera"/>
  </joint>
  <link name="camera">
    <inertial><mass value="0.1"/><inertia ixx="0.0001" ixy="0" ixz="0" iyy="0.0001" iyz="0" izz="0.0001"/></inertial>
    <visual><geometry><box size="0.03 0.03 0.03"/></geometry></visual>
  </link>
  <transmission name="j1_trans">
    <type>transmission_interface/SimpleTransmission</type>
    <joint name="j1"><hardwareInterface>EffortJointInterface</hardwareInterface></joint>
  </transmission>
  <gazebo reference="tool"><material>Gazebo/Red</material></gazebo>
</robot>
)";

QByteArray kukaUrdf()
{
    QFile file(test::sharedDataFile(QStringLiteral("kuka-lwr4/kuka_lwr4.urdf")));
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

// Random solid boxes: physically consistent bodies of every orientation and offset.
std::vector<InertialParameters> randomBodies(int n, std::mt19937 &rng)
{
    std::uniform_real_distribution<double> mass(0.3, 5.0), edge(0.02, 0.4), offset(-0.2, 0.2),
        angle(-3.0, 3.0);
    std::vector<InertialParameters> bodies;
    for (int j = 0; j < n; ++j) {
        const Eigen::Vector3d axis = Eigen::Vector3d(offset(rng), offset(rng), 0.1).normalized();
        const test::Box box{mass(rng),
                            {edge(rng), edge(rng), edge(rng)},
                            Eigen::AngleAxisd(angle(rng), axis).toRotationMatrix(),
                            {offset(rng), offset(rng), offset(rng)}};
        bodies.push_back(test::boxInertial(box));
    }
    return bodies;
}

std::vector<IdentifiedJoint> randomFriction(int n, std::mt19937 &rng)
{
    std::uniform_real_distribution<double> viscous(0.0, 3.0), coulomb(0.0, 1.5);
    std::vector<IdentifiedJoint> friction;
    for (int j = 0; j < n; ++j)
        friction.push_back({viscous(rng), coulomb(rng)});
    return friction;
}

std::vector<InertialParameters> bodiesOf(const SerialChain &chain)
{
    std::vector<InertialParameters> bodies;
    for (const ChainJoint &joint : chain.joints)
        bodies.push_back(joint.inertial);
    return bodies;
}

// Every body to 1e-12 of its largest entry, and the written friction exactly.
void compareDynamics(const SerialChain &read, const std::vector<InertialParameters> &bodies,
                     const std::vector<IdentifiedJoint> &friction)
{
    QCOMPARE(size_t(read.dof()), bodies.size());
    for (int j = 0; j < read.dof(); ++j) {
        const double scale = bodies[j].cwiseAbs().maxCoeff();
        const double difference = (read.joints[j].inertial - bodies[j]).cwiseAbs().maxCoeff();
        QVERIFY2(difference <= 1e-12 * scale,
                 qPrintable(QStringLiteral("link %1: difference %2 of scale %3")
                                .arg(read.joints[j].link)
                                .arg(difference)
                                .arg(scale)));
        QCOMPARE(read.joints[j].damping, friction[j].viscous);
        QCOMPARE(read.joints[j].friction, friction[j].coulomb);
    }
}

QDomDocument dom(const QByteArray &xml)
{
    QDomDocument doc;
    doc.setContent(xml);
    return doc;
}

QDomElement linkElement(const QDomDocument &doc, const QString &name)
{
    const QDomElement robot = doc.documentElement();
    for (QDomElement e = robot.firstChildElement(QStringLiteral("link")); !e.isNull();
         e = e.nextSiblingElement(QStringLiteral("link"))) {
        if (e.attribute(QStringLiteral("name")) == name)
            return e;
    }
    return {};
}

int countOf(const QDomElement &parent, const char *tag)
{
    return parent.elementsByTagName(QLatin1String(tag)).count();
}

// The direct children of <robot> as "tag name", in order.
QStringList outline(const QDomDocument &doc)
{
    QStringList names;
    for (QDomElement e = doc.documentElement().firstChildElement(); !e.isNull();
         e = e.nextSiblingElement())
        names << e.tagName() + QLatin1Char(' ') + e.attribute(QStringLiteral("name"));
    return names;
}

} // namespace

class TestUrdfExport : public QObject
{
    Q_OBJECT

private slots:
    void kukaRandomBodies_readBackWithTheSameKinematics();
    void kukaCadBodies_readBackUnchanged();
    void fixedLinks_loseTheirInertialAndKeepTheirVisuals();
    void nonPhysicalBody_isRefusedNamingTheLink();
    void otherChainOrBadFriction_isRefused();
    void armatureAndOffsets_inTheExtensionThatUrdfdomSkips();
};

void TestUrdfExport::kukaRandomBodies_readBackWithTheSameKinematics()
{
    const QByteArray original = kukaUrdf();
    if (original.isEmpty())
        QSKIP(qPrintable(test::sharedDataMissing()));
    const SerialChain chain = parseUrdfChain(original, QStringLiteral("kuka_lwr4.urdf"));
    std::mt19937 rng(20240611);
    const std::vector<InertialParameters> bodies = randomBodies(chain.dof(), rng);
    const std::vector<IdentifiedJoint> friction = randomFriction(chain.dof(), rng);
    const QString note = QStringLiteral("learnid test, 2024-06-11");
    const QByteArray xml =
        identifiedUrdf(original, QStringLiteral("kuka_lwr4.urdf"), chain, bodies, friction, note);

    const SerialChain read =
        parseUrdfChain(xml, QStringLiteral("written"), chain.baseLink, chain.tipLink);
    QCOMPARE(read.name, chain.name);
    QCOMPARE(read.baseLink, chain.baseLink);
    QCOMPARE(read.tipLink, chain.tipLink);
    QCOMPARE(read.dof(), chain.dof());
    for (int j = 0; j < chain.dof(); ++j) {
        const ChainJoint &a = read.joints[j];
        const ChainJoint &b = chain.joints[j];
        QCOMPARE(a.name, b.name);
        QCOMPARE(a.link, b.link);
        QVERIFY(a.type == b.type);
        QVERIFY(a.origin.matrix() == b.origin.matrix());
        QVERIFY(a.axis == b.axis);
        QCOMPARE(a.lower, b.lower);
        QCOMPARE(a.upper, b.upper);
        QCOMPARE(a.velocityLimit, b.velocityLimit);
        QCOMPARE(a.effortLimit, b.effortLimit);
    }
    compareDynamics(read, bodies, friction);

    // Everything but inertia and friction as it was, in the same order, and the note on top.
    const QDomDocument before = dom(original);
    const QDomDocument after = dom(xml);
    QCOMPARE(outline(after), outline(before));
    for (const char *tag : {"visual", "collision", "material", "mesh", "transmission", "limit",
                            "rotor_inertia", "inertial"}) {
        QCOMPARE(countOf(after.documentElement(), tag), countOf(before.documentElement(), tag));
    }
    // lwr_base_link is fixed to the base: not part of the chain, its CAD mass stays.
    QCOMPARE(linkElement(after, QStringLiteral("lwr_base_link"))
                 .firstChildElement(QStringLiteral("inertial"))
                 .firstChildElement(QStringLiteral("mass"))
                 .attribute(QStringLiteral("value")),
             QStringLiteral("1.6"));
    QVERIFY(after.firstChild().isComment() || after.firstChild().nextSibling().isComment());
    QVERIFY(xml.left(xml.indexOf("<robot")).contains(note.toUtf8()));
    // Attributes in name order: the same text every time.
    QCOMPARE(
        identifiedUrdf(original, QStringLiteral("kuka_lwr4.urdf"), chain, bodies, friction, note),
        xml);
}

void TestUrdfExport::kukaCadBodies_readBackUnchanged()
{
    const QByteArray original = kukaUrdf();
    if (original.isEmpty())
        QSKIP(qPrintable(test::sharedDataMissing()));
    const SerialChain chain = parseUrdfChain(original, QStringLiteral("kuka_lwr4.urdf"));
    std::vector<IdentifiedJoint> friction;
    for (const ChainJoint &joint : chain.joints)
        friction.push_back({joint.damping, joint.friction});
    const QByteArray xml = identifiedUrdf(original, QStringLiteral("kuka_lwr4.urdf"), chain,
                                          bodiesOf(chain), friction, QString());
    compareDynamics(parseUrdfChain(xml, QStringLiteral("written")), bodiesOf(chain), friction);
}

void TestUrdfExport::fixedLinks_loseTheirInertialAndKeepTheirVisuals()
{
    const QByteArray original(twoJointArm);
    const QString source = QStringLiteral("two-joint.urdf");
    const SerialChain chain = parseUrdfChain(original, source, {}, QStringLiteral("tool"));
    QCOMPARE(chain.dof(), 2);
    std::mt19937 rng(7);
    const std::vector<InertialParameters> bodies = randomBodies(2, rng);
    const std::vector<IdentifiedJoint> friction = {{0.7, 0.25}, {0.3, 0.125}};
    const QByteArray xml = identifiedUrdf(original, source, chain, bodies, friction,
                                          QStringLiteral("identified -- on the bench"));

    compareDynamics(parseUrdfChain(xml, QStringLiteral("written"), {}, QStringLiteral("tool")),
                    bodies, friction);
    const QDomDocument before = dom(original);
    const QDomDocument after = dom(xml);
    QCOMPARE(outline(after), outline(before));
    for (const char *link : {"housing", "tool", "camera"})
        QCOMPARE(countOf(linkElement(after, QLatin1String(link)), "inertial"), 0);
    for (const char *link : {"base", "upper", "fore"}) // fore had none before
        QCOMPARE(countOf(linkElement(after, QLatin1String(link)), "inertial"), 1);
    QCOMPARE(linkElement(after, QStringLiteral("base"))
                 .firstChildElement(QStringLiteral("inertial"))
                 .firstChildElement(QStringLiteral("mass"))
                 .attribute(QStringLiteral("value")),
             QStringLiteral("4"));
    for (const char *link : {"world", "base", "upper", "housing", "fore", "tool", "camera"}) {
        for (const char *tag : {"visual", "collision", "geometry", "material"}) {
            QCOMPARE(countOf(linkElement(after, QLatin1String(link)), tag),
                     countOf(linkElement(before, QLatin1String(link)), tag));
        }
    }
    QCOMPARE(after.documentElement()
                 .firstChildElement(QStringLiteral("gazebo"))
                 .firstChildElement(QStringLiteral("material"))
                 .text(),
             QStringLiteral("Gazebo/Red"));
    // j2 had no <dynamics>: it has one now.
    QCOMPARE(countOf(after.documentElement(), "dynamics"), 2);
    // The note names what was merged into what; "--" cannot stand in an XML comment.
    const QString note = after.firstChild().isComment()
                             ? after.firstChild().nodeValue()
                             : after.firstChild().nextSibling().nodeValue();
    QVERIFY2(note.contains(QLatin1String("into upper: housing")), qPrintable(note));
    QVERIFY2(note.contains(QLatin1String("into fore: ")), qPrintable(note));
    QVERIFY(note.contains(QLatin1String("tool")) && note.contains(QLatin1String("camera")));
    QVERIFY(note.contains(QLatin1String("identified - - on the bench")));
}

void TestUrdfExport::nonPhysicalBody_isRefusedNamingTheLink()
{
    const QByteArray original(twoJointArm);
    const QString source = QStringLiteral("two-joint.urdf");
    const SerialChain chain = parseUrdfChain(original, source, {}, QStringLiteral("tool"));
    const std::vector<IdentifiedJoint> friction(2);
    std::vector<InertialParameters> bodies = bodiesOf(chain);
    const auto refusal = [&] {
        return errorOf([&] { identifiedUrdf(original, source, chain, bodies, friction, {}); });
    };

    // Ixx > Iyy + Izz about the centre of mass: no mass distribution has it.
    bodies[1] = test::inertialOf(1.0, Eigen::Vector3d(0.1, 0.01, 0.01).asDiagonal(),
                                 Eigen::Vector3d(0.0, 0.0, 0.1));
    QVERIFY2(refusal().startsWith(QLatin1String("two-joint.urdf: link \"fore\"")),
             qPrintable(refusal()));
    QVERIFY2(refusal().contains(QLatin1String("physical")), qPrintable(refusal()));
    bodies[1] = chain.joints[1].inertial;
    bodies[0][0] = 0.0;
    QVERIFY2(refusal().contains(QLatin1String("link \"upper\"")) &&
                 refusal().contains(QLatin1String("mass")),
             qPrintable(refusal()));
    bodies[0][0] = -1.0;
    QVERIFY2(refusal().contains(QLatin1String("link \"upper\"")), qPrintable(refusal()));
    bodies[0][0] = std::nan("");
    QVERIFY2(refusal().contains(QLatin1String("link \"upper\"")), qPrintable(refusal()));
}

void TestUrdfExport::otherChainOrBadFriction_isRefused()
{
    const QByteArray original(twoJointArm);
    const QString source = QStringLiteral("two-joint.urdf");
    const SerialChain chain = parseUrdfChain(original, source, {}, QStringLiteral("tool"));
    const std::vector<InertialParameters> bodies = bodiesOf(chain);
    std::vector<IdentifiedJoint> friction(2);

    friction[1].coulomb = -0.1;
    QVERIFY(errorOf([&] {
                identifiedUrdf(original, source, chain, bodies, friction, {});
            }).contains(QLatin1String("joint \"j2\"")));
    friction[1].coulomb = 0.0;
    QVERIFY(errorOf([&] {
                identifiedUrdf(original, source, chain, {bodies[0]}, friction, {});
            }).contains(QLatin1String("bodies for 1 and friction for 2 joints")));
    SerialChain renamed = chain;
    renamed.joints[1].name = QStringLiteral("elbow");
    QVERIFY(
        errorOf([&] { identifiedUrdf(original, source, renamed, bodies, friction, {}); })
            .contains(QLatin1String(
                "(j1, elbow) are not the URDF's from link \"world\" to link \"tool\" (j1, j2)")));
}

void TestUrdfExport::armatureAndOffsets_inTheExtensionThatUrdfdomSkips()
{
    const QByteArray original = kukaUrdf();
    if (original.isEmpty())
        QSKIP(qPrintable(test::sharedDataMissing()));
    const SerialChain chain = parseUrdfChain(original, QStringLiteral("kuka_lwr4.urdf"));
    std::mt19937 rng(11);
    std::vector<IdentifiedJoint> terms = randomFriction(chain.dof(), rng);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (IdentifiedJoint &t : terms) {
        t.armature = 0.1 * std::abs(unit(rng));
        t.offset = 0.5 * unit(rng);
    }
    terms[2].armature = terms[2].offset = 0.0; // nothing to write there
    const QStringList notes = {QStringLiteral("What the data determined: a test note")};
    const QByteArray xml = identifiedUrdf(original, QStringLiteral("kuka_lwr4.urdf"), chain,
                                          bodiesOf(chain), terms, QString(), notes);
    QVERIFY(xml.contains(R"(xmlns:learnid="urn:learnid:urdf:1")"));
    QCOMPARE(xml.mid(xml.indexOf("<robot")).count("<learnid:dynamics "), chain.dof() - 1);
    QVERIFY(xml.left(xml.indexOf("<robot")).contains("What the data determined: a test note"));
    // learnid reads them back exactly.
    const SerialChain read = parseUrdfChain(xml, QStringLiteral("written"));
    for (int j = 0; j < chain.dof(); ++j) {
        QCOMPARE(read.joints[size_t(j)].armature, terms[size_t(j)].armature);
        QCOMPARE(read.joints[size_t(j)].offset, terms[size_t(j)].offset);
    }
    // urdfdom itself (what KDL, pinocchio and MoveIt read with) accepts the file and skips the
    // element: the same joints, dynamics and masses as learnid reads.
    const urdf::ModelInterfaceSharedPtr model = urdf::parseURDF(xml.toStdString());
    QVERIFY(model);
    for (int j = 0; j < chain.dof(); ++j) {
        const urdf::JointConstSharedPtr joint =
            model->getJoint(chain.joints[size_t(j)].name.toStdString());
        QVERIFY(joint && joint->dynamics);
        QCOMPARE(joint->dynamics->damping, terms[size_t(j)].viscous);
        QCOMPARE(joint->dynamics->friction, terms[size_t(j)].coulomb);
    }
    // Written again without these terms (a model without armature and offset): 0, not the old
    // values, so the file says what that model used.
    std::vector<IdentifiedJoint> plain = terms;
    for (IdentifiedJoint &t : plain)
        t.armature = t.offset = 0.0;
    const QByteArray again =
        identifiedUrdf(xml, QStringLiteral("written"), read, bodiesOf(read), plain, QString());
    for (const ChainJoint &j : parseUrdfChain(again, QStringLiteral("again")).joints) {
        QCOMPARE(j.armature, 0.0);
        QCOMPARE(j.offset, 0.0);
    }
    // A negative armature is refused, naming the joint.
    terms[1].armature = -0.01;
    const QString error = errorOf([&] {
        identifiedUrdf(original, QStringLiteral("kuka_lwr4.urdf"), chain, bodiesOf(chain), terms,
                       QString());
    });
    QVERIFY2(error.contains(QLatin1String("joint \"lwr_1_joint\": the armature")),
             qPrintable(error));
}

QTEST_GUILESS_MAIN(TestUrdfExport)
#include "tst_urdfexport.moc"
