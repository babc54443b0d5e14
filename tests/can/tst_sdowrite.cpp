#include "can/SdoWrite.h"
#include "model/Error.h"

#include <QTest>

using namespace learnid;
using canopen::DataType;

class TestSdoWrite : public QObject
{
    Q_OBJECT

private slots:
    void make_encodesTheValueLittleEndian();
    void make_real32_keepsTheValueTheNodeWillHold();
    void make_valueOutsideType_throwsNamingNodeAndObject();
    void make_invalidNode_throws();
    void toString_showsWhatIsSent();
    void equality_comparesWhatIsSent();
};

void TestSdoWrite::make_encodesTheValueLittleEndian()
{
    const SdoWrite w = SdoWrite::make(1, 0x1017, 0, DataType::Unsigned16, 100);
    QCOMPARE(w.node, quint8(1));
    QCOMPARE(w.index, quint16(0x1017));
    QCOMPARE(w.subIndex, quint8(0));
    QCOMPARE(w.dataType, QString("UNSIGNED16"));
    QCOMPARE(w.value, 100.0);
    QCOMPARE(w.raw, QByteArray::fromHex("6400"));
}

void TestSdoWrite::make_real32_keepsTheValueTheNodeWillHold()
{
    const SdoWrite w = SdoWrite::make(1, 0x2200, 1, DataType::Real32, 0.1);
    QCOMPARE(w.value, double(0.1f));
    QCOMPARE(w.raw, QByteArray::fromHex("CDCCCC3D"));
}

void TestSdoWrite::make_valueOutsideType_throwsNamingNodeAndObject()
{
    try {
        SdoWrite::make(2, 0x60B2, 0, DataType::Integer16, 40000);
        QFAIL("no exception");
    } catch (const Error &e) {
        QVERIFY2(e.message().contains("Node 2"), qPrintable(e.message()));
        QVERIFY2(e.message().contains("0x60B2:00"), qPrintable(e.message()));
        QVERIFY2(e.message().contains("INTEGER16"), qPrintable(e.message()));
    }
}

void TestSdoWrite::make_invalidNode_throws()
{
    QVERIFY_THROWS_EXCEPTION(Error, SdoWrite::make(0, 0x6040, 0, DataType::Unsigned16, 6));
    QVERIFY_THROWS_EXCEPTION(Error, SdoWrite::make(128, 0x6040, 0, DataType::Unsigned16, 6));
}

void TestSdoWrite::toString_showsWhatIsSent()
{
    QCOMPARE(SdoWrite::make(2, 0x2200, 1, DataType::Real32, 20).toString(),
             QString("node 2: 0x2200:01 REAL32 = 20 (00 00 A0 41)"));
    QCOMPARE(SdoWrite::make(2, 0x607A, 0, DataType::Integer32, -2147483648.0).toString(),
             QString("node 2: 0x607A:00 INTEGER32 = -2147483648 (00 00 00 80)"));
}

void TestSdoWrite::equality_comparesWhatIsSent()
{
    const SdoWrite a = SdoWrite::make(2, 0x2200, 1, DataType::Real32, 20);
    QVERIFY(a == SdoWrite::make(2, 0x2200, 1, DataType::Real32, 20));
    QVERIFY(a != SdoWrite::make(3, 0x2200, 1, DataType::Real32, 20));
    QVERIFY(a != SdoWrite::make(2, 0x2200, 1, DataType::Real32, 21));
}

QTEST_GUILESS_MAIN(TestSdoWrite)
#include "tst_sdowrite.moc"
