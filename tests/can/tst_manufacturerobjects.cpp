#include "can/ManufacturerObjects.h"
#include "can/SdoAbortCode.h"
#include "model/Error.h"

#include <QTest>
#include <cmath>

using namespace learnid;
using namespace learnid::objects;

class TestManufacturerObjects : public QObject
{
    Q_OBJECT

private slots:
    void saveSignature_isSaveInAscii();
    void parameterWriteSequence_writesEveryNodeThenStoresEveryNode();
    void parameterWriteSequence_rawBytesAreReal32LittleEndian();
    void parameterWriteSequence_invalidInput_throws_data();
    void parameterWriteSequence_invalidInput_throws();
    void trialPdoMappings_fillEightBytes();
    void manufacturerObjects_describeGainsParametersAndLimit();
};

void TestManufacturerObjects::saveSignature_isSaveInAscii()
{
    QCOMPARE(canopen::encodeValue(canopen::DataType::Unsigned32, saveSignature),
             QByteArray("save"));
}

void TestManufacturerObjects::parameterWriteSequence_writesEveryNodeThenStoresEveryNode()
{
    const Eigen::Vector3d phi(20.0, 5.0, 8.0);
    const SdoWriteSequence w = parameterWriteSequence({1, 2}, phi);
    QStringList got;
    for (const SdoWrite &s : w)
        got << s.toString();
    QCOMPARE(got, (QStringList{
                      "node 1: 0x2200:00 UNSIGNED8 = 3 (03)",
                      "node 1: 0x2200:01 REAL32 = 20 (00 00 A0 41)",
                      "node 1: 0x2200:02 REAL32 = 5 (00 00 A0 40)",
                      "node 1: 0x2200:03 REAL32 = 8 (00 00 00 41)",
                      "node 2: 0x2200:00 UNSIGNED8 = 3 (03)",
                      "node 2: 0x2200:01 REAL32 = 20 (00 00 A0 41)",
                      "node 2: 0x2200:02 REAL32 = 5 (00 00 A0 40)",
                      "node 2: 0x2200:03 REAL32 = 8 (00 00 00 41)",
                      "node 1: 0x1010:01 UNSIGNED32 = 1702257011 (73 61 76 65)",
                      "node 2: 0x1010:01 UNSIGNED32 = 1702257011 (73 61 76 65)",
                  }));
}

void TestManufacturerObjects::parameterWriteSequence_rawBytesAreReal32LittleEndian()
{
    Eigen::VectorXd phi(1);
    phi << 0.333333333333;
    const SdoWriteSequence w = parameterWriteSequence({7}, phi);
    QCOMPARE(w.size(), 3);
    QCOMPARE(w[1].dataType, QString("REAL32"));
    QCOMPARE(w[1].raw, QByteArray::fromHex("ABAAAA3E"));
    QCOMPARE(w[1].value, double(float(0.333333333333)));
}

void TestManufacturerObjects::parameterWriteSequence_invalidInput_throws_data()
{
    QTest::addColumn<QList<int>>("nodes");
    QTest::addColumn<Eigen::VectorXd>("phi");
    const Eigen::VectorXd good = Eigen::Vector3d(20, 5, 8);
    QTest::newRow("no node") << QList<int>{} << good;
    QTest::newRow("node 0") << QList<int>{0} << good;
    QTest::newRow("node 128") << QList<int>{1, 128} << good;
    QTest::newRow("node twice") << QList<int>{1, 2, 1} << good;
    QTest::newRow("empty phi") << QList<int>{1} << Eigen::VectorXd();
    QTest::newRow("255 parameters") << QList<int>{1} << Eigen::VectorXd(Eigen::VectorXd::Ones(255));
    QTest::newRow("NaN") << QList<int>{1} << Eigen::VectorXd(Eigen::Vector3d(1, std::nan(""), 1));
    QTest::newRow("beyond float") << QList<int>{1} << Eigen::VectorXd(Eigen::Vector3d(1, 1e39, 1));
}

void TestManufacturerObjects::parameterWriteSequence_invalidInput_throws()
{
    QFETCH(QList<int>, nodes);
    QFETCH(Eigen::VectorXd, phi);
    QVERIFY_THROWS_EXCEPTION(Error, parameterWriteSequence(nodes, phi));
}

void TestManufacturerObjects::trialPdoMappings_fillEightBytes()
{
    QCOMPARE(trialRpdoMapping().byteLength(), 8);
    QCOMPARE(trialTpdoMapping().byteLength(), 8);
    QCOMPARE(trialRpdoMapping().entries().at(0).index, targetPosition);
    QCOMPARE(trialRpdoMapping().entries().at(1).index, torqueOffset);
    QCOMPARE(trialTpdoMapping().entries().at(1).index, torqueActual);
    QCOMPARE(trialTpdoMapping().entries().at(2).index, statusword);
}

void TestManufacturerObjects::manufacturerObjects_describeGainsParametersAndLimit()
{
    const QList<ObjectDescription> list = manufacturerObjects({4500, 30, 600, 200, 8, 3});
    QCOMPARE(list.size(), 5 + 1 + 3 + 1);
    QCOMPARE(list[0].index, gains);
    QCOMPARE(list[0].subIndex, quint8(0));
    QCOMPARE(list[0].access, ObjectDictionary::Access::ReadOnly);
    QCOMPARE(list[0].defaultValue, 4.0); // sub 0 of a RECORD: its highest sub-index
    QCOMPARE(list[4].subIndex, gainLambda);
    QCOMPARE(list[4].defaultValue, 200.0);
    QCOMPARE(list[5].type, canopen::DataType::Unsigned8);
    QCOMPARE(list[5].access, ObjectDictionary::Access::ReadWrite); // the count apply writes
    QCOMPARE(list[8].name, QString("Identified parameter 3"));
    QCOMPARE(list.last().index, torqueLimit);
    QCOMPARE(list.last().defaultValue, 8.0);
    // The write ranges of docs/can-protocol.md §2.2.
    QCOMPARE(writeAbortCode(list[1], 0.0), sdoabort::valueTooLow);   // kp > 0
    QCOMPARE(writeAbortCode(list[2], 0.0), 0u);                      // ki >= 0
    QCOMPARE(writeAbortCode(list[3], -1e-3), sdoabort::valueTooLow); // kd >= 0
    QCOMPARE(writeAbortCode(list[4], qQNaN()), sdoabort::invalidValue);
    QCOMPARE(writeAbortCode(list[5], 3.0), 0u);
    QCOMPARE(writeAbortCode(list[5], 4.0), sdoabort::valueTooHigh); // count <= m
    QCOMPARE(writeAbortCode(list[6], -1e30), 0u);
    QCOMPARE(writeAbortCode(list[6], qInf()), sdoabort::invalidValue);
    QCOMPARE(writeAbortCode(list.last(), 1e6), 0u);
    QCOMPARE(writeAbortCode(list.last(), 1.5e6), sdoabort::valueTooHigh);
}

QTEST_GUILESS_MAIN(TestManufacturerObjects)
#include "tst_manufacturerobjects.moc"
