// The payload object 0x2500 (docs/can-protocol.md §2.5): the writes of a payload's apply, node
// after node, each value's REAL32 bytes, and what cannot be sent refused before anything is.
#include "can/PayloadObjects.h"
#include "model/Error.h"

#include <QTest>
#include <cmath>

using namespace learnid;
using namespace learnid::objects;

class TestPayloadObjects : public QObject
{
    Q_OBJECT

private slots:
    void payloadWrites_jointThenTheTenParameters_nodeAfterNode()
    {
        Eigen::VectorXd body(10);
        body << 1.5, 0.075, 0.0, 0.12, 0.02, 0.0, 0.021, -0.006, 0.0, 0.004;
        const QList<SdoWrite> w = payloadWrites({3, 4}, 2, body);
        QCOMPARE(w.size(), 2 * 11);
        QCOMPARE(w[0].toString(), QStringLiteral("node 3: 0x2500:01 UNSIGNED8 = 2 (02)"));
        QCOMPARE(w[1].toString(), QStringLiteral("node 3: 0x2500:02 REAL32 = 1.5 (00 00 C0 3F)"));
        QCOMPARE(w[11].toString(), QStringLiteral("node 4: 0x2500:01 UNSIGNED8 = 2 (02)"));
        for (int node = 0; node < 2; ++node) {
            for (int i = 0; i < 10; ++i) {
                const SdoWrite &s = w[node * 11 + 1 + i];
                QCOMPARE(s.index, quint16(0x2500));
                QCOMPARE(s.subIndex, quint8(2 + i));
                QCOMPARE(s.dataType, QStringLiteral("REAL32"));
                QCOMPARE(s.value, double(float(body[i])));
            }
        }
    }

    void payloadWrites_whatCannotBeSent_throws_data()
    {
        QTest::addColumn<int>("joint");
        QTest::addColumn<Eigen::VectorXd>("body");
        const Eigen::VectorXd good = Eigen::VectorXd::Constant(10, 0.1);
        Eigen::VectorXd nan = good, huge = good;
        nan[3] = std::nan("");
        huge[0] = 1e39;
        QTest::newRow("joint 0") << 0 << good;
        QTest::newRow("joint beyond the nodes") << 3 << good;
        QTest::newRow("9 parameters") << 1 << Eigen::VectorXd(Eigen::VectorXd::Ones(9));
        QTest::newRow("NaN") << 1 << nan;
        QTest::newRow("beyond float") << 1 << huge;
    }

    void payloadWrites_whatCannotBeSent_throws()
    {
        QFETCH(int, joint);
        QFETCH(Eigen::VectorXd, body);
        QVERIFY_THROWS_EXCEPTION(Error, payloadWrites({1, 2}, joint, body));
    }
};

QTEST_GUILESS_MAIN(TestPayloadObjects)
#include "tst_payloadobjects.moc"
