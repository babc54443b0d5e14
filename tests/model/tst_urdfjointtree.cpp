// A URDF whose joints do not form a tree (a link its own child, a link with two parent joints, a
// loop of joints) and a file that is not well-formed XML are refused before urdfdom reads them,
// naming the joints, links or line and column; trees, with and without branches, still load.
// urdfdom itself would link a loop through shared pointers that are never freed (the ASan stage
// of the tests reports any such leak) and walking a self-parented link never ends.

#include "model/Error.h"
#include "model/UrdfChain.h"

#include <QTest>

using namespace learnid;

namespace {

QByteArray joint(const char *name, const char *parent, const char *child)
{
    return QByteArray("  <joint name=\"") + name + "\" type=\"revolute\"><parent link=\"" + parent +
           "\"/><child link=\"" + child +
           "\"/><axis xyz=\"0 0 1\"/><limit lower=\"-1\" upper=\"1\" effort=\"10\" "
           "velocity=\"1\"/></joint>\n";
}

QByteArray robot(const QByteArray &joints)
{
    QByteArray links;
    for (const char *l : {"base", "a", "b", "c", "d"}) {
        links += QByteArray("  <link name=\"") + l +
                 "\"><inertial><mass value=\"1\"/><inertia ixx=\"0.01\" iyy=\"0.01\" "
                 "izz=\"0.01\" ixy=\"0\" ixz=\"0\" iyz=\"0\"/></inertial></link>\n";
    }
    return "<?xml version=\"1.0\"?>\n<robot name=\"r\">\n" + links + joints + "</robot>\n";
}

} // namespace

class TestUrdfJointTree : public QObject
{
    Q_OBJECT

private slots:
    void notATree_isRefusedNamingJointsAndLinks_data();
    void notATree_isRefusedNamingJointsAndLinks();
    void tree_withABranchAndANamedTip_loads();
};

void TestUrdfJointTree::notATree_isRefusedNamingJointsAndLinks_data()
{
    QTest::addColumn<QByteArray>("urdf");
    QTest::addColumn<QString>("message");
    const QByteArray chain = joint("j1", "base", "a") + joint("j2", "a", "b");
    QTest::newRow("own child") << robot(chain + joint("j3", "b", "b"))
                               << "r.urdf: joint \"j3\" connects link \"b\" to itself";
    QTest::newRow("two parents")
        << robot(chain + joint("j3", "base", "c") + joint("j4", "c", "b"))
        << "r.urdf: link \"b\" is the child of two joints, \"j2\" and \"j4\": the joints of a "
           "URDF form a tree";
    // base -> a and a loop c -> d -> c beside it: urdfdom finds one root and accepts the file.
    QTest::newRow("loop of two")
        << robot(chain + joint("j3", "c", "d") + joint("j4", "d", "c"))
        << "r.urdf: the joints form a loop through links \"d\", \"c\": the joints of a URDF "
           "form a tree";
    QTest::newRow("loop of three")
        << robot(joint("j1", "base", "a") + joint("j2", "b", "c") + joint("j3", "c", "d") +
                 joint("j4", "d", "b"))
        << "r.urdf: the joints form a loop through links \"c\", \"b\", \"d\": the joints of a "
           "URDF form a tree";
    QByteArray broken = robot(chain);
    broken.replace("<robot name=\"r\">", "<robot name=\"r\" name=\"s\">");
    QTest::newRow("not well-formed")
        << broken << "r.urdf: line 2, column 25: not well-formed XML: Attribute 'name' redefined.";
}

void TestUrdfJointTree::notATree_isRefusedNamingJointsAndLinks()
{
    QFETCH(QByteArray, urdf);
    QFETCH(QString, message);
    try {
        parseUrdfChain(urdf, QStringLiteral("r.urdf"), {}, QStringLiteral("a"));
        QFAIL("a URDF whose joints are not a tree was read");
    } catch (const Error &e) {
        QCOMPARE(e.message(), message);
    }
}

void TestUrdfJointTree::tree_withABranchAndANamedTip_loads()
{
    const QByteArray urdf = robot(joint("j1", "base", "a") + joint("j2", "a", "b") +
                                  joint("j3", "a", "c") + joint("j4", "c", "d"));
    const SerialChain chain =
        parseUrdfChain(urdf, QStringLiteral("r.urdf"), {}, QStringLiteral("d"));
    QCOMPARE(chain.dof(), 3);
    QCOMPARE(chain.joints[0].name, QStringLiteral("j1"));
    QCOMPARE(chain.joints[1].name, QStringLiteral("j3"));
    QCOMPARE(chain.joints[2].name, QStringLiteral("j4"));
    // Without a tip the branch at "a" is named, as before.
    try {
        parseUrdfChain(urdf, QStringLiteral("r.urdf"));
        QFAIL("a branching robot without a tip was read");
    } catch (const Error &e) {
        QVERIFY2(e.message().contains(QLatin1String("branches at link \"a\"")),
                 qPrintable(e.message()));
    }
}

QTEST_GUILESS_MAIN(TestUrdfJointTree)
#include "tst_urdfjointtree.moc"
