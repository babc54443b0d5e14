#include "can/CanOpen.h"
#include "model/Error.h"

#include <QTest>
#include <cmath>
#include <limits>

using namespace learnid;
using namespace learnid::canopen;

Q_DECLARE_METATYPE(learnid::canopen::DataType)

class TestCanOpen : public QObject
{
    Q_OBJECT

private slots:
    void cobIds_followThePredefinedConnectionSet();
    void cobIds_decodeToNodeAndFunction();
    void nodeIds_validRangeIs1To127();
    void encodeValue_atTypeLimits_isLittleEndian_data();
    void encodeValue_atTypeLimits_isLittleEndian();
    void encodeValue_outsideRange_throws_data();
    void encodeValue_outsideRange_throws();
    void encodeValue_nonNumericType_throws();
    void decodeValue_tooFewBytes_throws();
    void decodeValue_atOffset_readsThere();
    void real32_roundTripsFloatValues();
    void dataTypeNames_roundTrip();
    void objectAddress_andHexBytes_formatForTechnicians();
};

void TestCanOpen::cobIds_followThePredefinedConnectionSet()
{
    QCOMPARE(nmtCobId, 0x000u);
    QCOMPARE(syncCobId, 0x080u);
    QCOMPARE(emcyCobId(5), 0x085u);
    QCOMPARE(tpdoCobId(1, 5), 0x185u);
    QCOMPARE(tpdoCobId(2, 5), 0x285u);
    QCOMPARE(tpdoCobId(3, 5), 0x385u);
    QCOMPARE(tpdoCobId(4, 5), 0x485u);
    QCOMPARE(rpdoCobId(1, 5), 0x205u);
    QCOMPARE(rpdoCobId(2, 5), 0x305u);
    QCOMPARE(rpdoCobId(3, 5), 0x405u);
    QCOMPARE(rpdoCobId(4, 5), 0x505u);
    QCOMPARE(sdoTxCobId(5), 0x585u);
    QCOMPARE(sdoRxCobId(5), 0x605u);
    QCOMPARE(heartbeatCobId(5), 0x705u);
    QCOMPARE(heartbeatCobId(127), 0x77Fu);
}

void TestCanOpen::cobIds_decodeToNodeAndFunction()
{
    QCOMPARE(nodeOfCobId(0x5FF), quint8(127));
    QCOMPARE(nodeOfCobId(0x701), quint8(1));
    QCOMPARE(functionCodeOfCobId(0x701), 0xE);
    QCOMPARE(functionCodeOfCobId(0x080), 1);
    QCOMPARE(functionCodeOfCobId(0x581), 0xB);
}

void TestCanOpen::nodeIds_validRangeIs1To127()
{
    QVERIFY(!isValidNodeId(0));
    QVERIFY(isValidNodeId(1));
    QVERIFY(isValidNodeId(127));
    QVERIFY(!isValidNodeId(128));
}

void TestCanOpen::encodeValue_atTypeLimits_isLittleEndian_data()
{
    QTest::addColumn<DataType>("type");
    QTest::addColumn<double>("value");
    QTest::addColumn<QByteArray>("bytes");
    QTest::newRow("INTEGER8 min") << DataType::Integer8 << -128.0 << QByteArray::fromHex("80");
    QTest::newRow("INTEGER8 max") << DataType::Integer8 << 127.0 << QByteArray::fromHex("7F");
    QTest::newRow("INTEGER16 min")
        << DataType::Integer16 << -32768.0 << QByteArray::fromHex("0080");
    QTest::newRow("INTEGER16 -1") << DataType::Integer16 << -1.0 << QByteArray::fromHex("FFFF");
    QTest::newRow("INTEGER16 max") << DataType::Integer16 << 32767.0 << QByteArray::fromHex("FF7F");
    QTest::newRow("INTEGER32 min")
        << DataType::Integer32 << -2147483648.0 << QByteArray::fromHex("00000080");
    QTest::newRow("INTEGER32 max")
        << DataType::Integer32 << 2147483647.0 << QByteArray::fromHex("FFFFFF7F");
    QTest::newRow("UNSIGNED8 max") << DataType::Unsigned8 << 255.0 << QByteArray::fromHex("FF");
    QTest::newRow("UNSIGNED16 max")
        << DataType::Unsigned16 << 65535.0 << QByteArray::fromHex("FFFF");
    QTest::newRow("UNSIGNED16 0x1234")
        << DataType::Unsigned16 << double(0x1234) << QByteArray::fromHex("3412");
    QTest::newRow("UNSIGNED32 max")
        << DataType::Unsigned32 << 4294967295.0 << QByteArray::fromHex("FFFFFFFF");
    QTest::newRow("UNSIGNED32 save")
        << DataType::Unsigned32 << double(0x65766173) << QByteArray("save");
    QTest::newRow("REAL32 1.0") << DataType::Real32 << 1.0 << QByteArray::fromHex("0000803F");
    QTest::newRow("REAL32 -2.5") << DataType::Real32 << -2.5 << QByteArray::fromHex("000020C0");
}

void TestCanOpen::encodeValue_atTypeLimits_isLittleEndian()
{
    QFETCH(DataType, type);
    QFETCH(double, value);
    QFETCH(QByteArray, bytes);
    QCOMPARE(encodeValue(type, value), bytes);
    QCOMPARE(decodeValue(type, bytes), value);
    QVERIFY(fitsType(type, value));
}

void TestCanOpen::encodeValue_outsideRange_throws_data()
{
    QTest::addColumn<DataType>("type");
    QTest::addColumn<double>("value");
    QTest::newRow("INTEGER8 -129") << DataType::Integer8 << -129.0;
    QTest::newRow("INTEGER8 128") << DataType::Integer8 << 128.0;
    QTest::newRow("INTEGER16 32768") << DataType::Integer16 << 32768.0;
    QTest::newRow("INTEGER16 -32769") << DataType::Integer16 << -32769.0;
    QTest::newRow("INTEGER32 2^31") << DataType::Integer32 << 2147483648.0;
    QTest::newRow("INTEGER32 -2^31-1") << DataType::Integer32 << -2147483649.0;
    QTest::newRow("UNSIGNED8 -1") << DataType::Unsigned8 << -1.0;
    QTest::newRow("UNSIGNED8 256") << DataType::Unsigned8 << 256.0;
    QTest::newRow("UNSIGNED16 65536") << DataType::Unsigned16 << 65536.0;
    QTest::newRow("UNSIGNED32 2^32") << DataType::Unsigned32 << 4294967296.0;
    QTest::newRow("INTEGER16 fraction") << DataType::Integer16 << 1.5;
    QTest::newRow("INTEGER32 NaN") << DataType::Integer32 << std::nan("");
    QTest::newRow("REAL32 infinity") << DataType::Real32 << std::numeric_limits<double>::infinity();
    QTest::newRow("REAL32 1e39") << DataType::Real32 << 1e39;
}

void TestCanOpen::encodeValue_outsideRange_throws()
{
    QFETCH(DataType, type);
    QFETCH(double, value);
    QVERIFY(!fitsType(type, value));
    try {
        encodeValue(type, value);
        QFAIL("no exception");
    } catch (const Error &e) {
        QVERIFY2(e.message().contains(dataTypeName(type)), qPrintable(e.message()));
    }
}

void TestCanOpen::encodeValue_nonNumericType_throws()
{
    QVERIFY_THROWS_EXCEPTION(Error, encodeValue(DataType::VisibleString, 1.0));
    QVERIFY(!isNumeric(DataType::Domain));
    QCOMPARE(dataTypeSize(DataType::Domain), 0);
}

void TestCanOpen::decodeValue_tooFewBytes_throws()
{
    QVERIFY_THROWS_EXCEPTION(Error, decodeValue(DataType::Integer32, QByteArray(3, '\0')));
    QVERIFY_THROWS_EXCEPTION(Error, decodeValue(DataType::Integer16, QByteArray(8, '\0'), 7));
    QVERIFY_THROWS_EXCEPTION(Error, decodeValue(DataType::Integer8, QByteArray(1, '\0'), -1));
}

void TestCanOpen::decodeValue_atOffset_readsThere()
{
    const QByteArray bytes = QByteArray::fromHex("00FEFF0000");
    QCOMPARE(decodeValue(DataType::Integer16, bytes, 1), -2.0);
    QCOMPARE(decodeValue(DataType::Unsigned16, bytes, 1), 65534.0);
    QCOMPARE(readU32(QByteArray::fromHex("78563412"), 0), 0x12345678u);
}

void TestCanOpen::real32_roundTripsFloatValues()
{
    for (const double v : {20.0, 5.0, 8.0, 0.1, -1e-3, 3.4e38}) {
        const double back = decodeValue(DataType::Real32, encodeValue(DataType::Real32, v));
        QCOMPARE(back, double(float(v)));
    }
}

void TestCanOpen::dataTypeNames_roundTrip()
{
    for (const DataType t : {DataType::Integer8, DataType::Integer16, DataType::Integer32,
                             DataType::Unsigned8, DataType::Unsigned16, DataType::Unsigned32,
                             DataType::Real32, DataType::VisibleString, DataType::Domain})
        QCOMPARE(dataTypeFromName(dataTypeName(t)), t);
    QCOMPARE(dataTypeName(DataType::Real32), QString("REAL32"));
    QVERIFY_THROWS_EXCEPTION(Error, dataTypeFromName("REAL64"));
}

void TestCanOpen::objectAddress_andHexBytes_formatForTechnicians()
{
    QCOMPARE(objectAddress(0x2200, 1), QString("0x2200:01"));
    QCOMPARE(objectAddress(0x60b2, 0xab), QString("0x60B2:AB"));
    QCOMPARE(hexBytes(QByteArray::fromHex("deadbeef")), QString("DE AD BE EF"));
}

QTEST_GUILESS_MAIN(TestCanOpen)
#include "tst_canopen.moc"
