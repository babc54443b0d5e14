#include "can/Pdo.h"
#include "model/Error.h"

#include <QTest>

using namespace learnid;
using canopen::DataType;

namespace {

PdoMapping trialLikeMapping()
{
    return PdoMapping({{0x607A, 0, DataType::Integer32},
                       {0x60B2, 0, DataType::Integer16},
                       {0x6040, 0, DataType::Unsigned16}});
}

} // namespace

class TestPdo : public QObject
{
    Q_OBJECT

private slots:
    void pack_atTypeLimits_isLittleEndianBackToBack_data();
    void pack_atTypeLimits_isLittleEndianBackToBack();
    void pack_valueOutsideItsType_throwsNamingTheObject_data();
    void pack_valueOutsideItsType_throwsNamingTheObject();
    void pack_wrongValueCount_throws();
    void unpack_shortPayload_throws_longPayloadIgnoresTheRest();
    void mapping_ofExactly64Bits_isValid();
    void mapping_over64BitsOrNonNumeric_isRejected();
    void mappingValue_isIndexSubIndexAndBitLength();
    void indicesAndCobIds_followCiA301();
    void configurationWrites_disableMapEnable_data();
    void configurationWrites_disableMapEnable();
    void configurationWrites_invalidPdoNumber_throws();
};

void TestPdo::pack_atTypeLimits_isLittleEndianBackToBack_data()
{
    QTest::addColumn<QList<double>>("values");
    QTest::addColumn<QByteArray>("payload");
    QTest::newRow("minimum") << QList<double>{-2147483648.0, -32768.0, 0.0}
                             << QByteArray::fromHex("0000008000800000");
    QTest::newRow("maximum") << QList<double>{2147483647.0, 32767.0, 65535.0}
                             << QByteArray::fromHex("FFFFFF7FFF7FFFFF");
    QTest::newRow("typical") << QList<double>{-1.0, 500.0, 15.0}
                             << QByteArray::fromHex("FFFFFFFFF4010F00");
}

void TestPdo::pack_atTypeLimits_isLittleEndianBackToBack()
{
    QFETCH(QList<double>, values);
    QFETCH(QByteArray, payload);
    const PdoMapping m = trialLikeMapping();
    QCOMPARE(m.bitLength(), 64);
    QCOMPARE(m.byteLength(), 8);
    QCOMPARE(m.pack(values), payload);
    QCOMPARE(m.unpack(payload), values);
}

void TestPdo::pack_valueOutsideItsType_throwsNamingTheObject_data()
{
    QTest::addColumn<QList<double>>("values");
    QTest::addColumn<QString>("object");
    QTest::newRow("INT32 max + 1") << QList<double>{2147483648.0, 0.0, 0.0} << "0x607A:00";
    QTest::newRow("INT32 min - 1") << QList<double>{-2147483649.0, 0.0, 0.0} << "0x607A:00";
    QTest::newRow("INT16 max + 1") << QList<double>{0.0, 32768.0, 0.0} << "0x60B2:00";
    QTest::newRow("INT16 min - 1") << QList<double>{0.0, -32769.0, 0.0} << "0x60B2:00";
    QTest::newRow("UNSIGNED16 -1") << QList<double>{0.0, 0.0, -1.0} << "0x6040:00";
    QTest::newRow("UNSIGNED16 max + 1") << QList<double>{0.0, 0.0, 65536.0} << "0x6040:00";
}

void TestPdo::pack_valueOutsideItsType_throwsNamingTheObject()
{
    QFETCH(QList<double>, values);
    QFETCH(QString, object);
    try {
        trialLikeMapping().pack(values);
        QFAIL("no exception");
    } catch (const Error &e) {
        QVERIFY2(e.message().contains(object), qPrintable(e.message()));
    }
}

void TestPdo::pack_wrongValueCount_throws()
{
    QVERIFY_THROWS_EXCEPTION(Error, trialLikeMapping().pack({1.0, 2.0}));
}

void TestPdo::unpack_shortPayload_throws_longPayloadIgnoresTheRest()
{
    const PdoMapping m({{0x6041, 0, DataType::Unsigned16}, {0x6061, 0, DataType::Integer8}});
    QVERIFY_THROWS_EXCEPTION(Error, m.unpack(QByteArray::fromHex("3702")));
    QCOMPARE(m.unpack(QByteArray::fromHex("3702F8FFFF")), (QList<double>{0x0237, -8.0}));
}

void TestPdo::mapping_ofExactly64Bits_isValid()
{
    const PdoMapping m({{0x2000, 1, DataType::Real32},
                        {0x2000, 2, DataType::Integer8},
                        {0x2000, 3, DataType::Unsigned8},
                        {0x2000, 4, DataType::Integer16}});
    QCOMPARE(m.bitLength(), 64);
    QCOMPARE(m.unpack(m.pack({0.5, -128.0, 255.0, -32768.0})),
             (QList<double>{0.5, -128.0, 255.0, -32768.0}));
    QCOMPARE(PdoMapping().byteLength(), 0);
    QCOMPARE(PdoMapping().pack({}), QByteArray());
}

void TestPdo::mapping_over64BitsOrNonNumeric_isRejected()
{
    const QList<PdoMappingEntry> tooLong = {{0x6064, 0, DataType::Integer32},
                                            {0x6077, 0, DataType::Integer16},
                                            {0x6041, 0, DataType::Unsigned16},
                                            {0x6061, 0, DataType::Integer8}};
    QVERIFY(PdoMapping::validationError(tooLong).contains("72 bits"));
    QVERIFY_THROWS_EXCEPTION(Error, PdoMapping{tooLong});
    QVERIFY_THROWS_EXCEPTION(Error, PdoMapping({{0x1008, 0, DataType::VisibleString}}));
}

void TestPdo::mappingValue_isIndexSubIndexAndBitLength()
{
    QCOMPARE((PdoMappingEntry{0x607A, 0, DataType::Integer32}.mappingValue()), 0x607A0020u);
    QCOMPARE((PdoMappingEntry{0x6041, 0, DataType::Unsigned16}.mappingValue()), 0x60410010u);
    QCOMPARE((PdoMappingEntry{0x2200, 3, DataType::Unsigned8}.mappingValue()), 0x22000308u);
}

void TestPdo::indicesAndCobIds_followCiA301()
{
    QCOMPARE(pdoCommunicationIndex(PdoDirection::Receive, 1), quint16(0x1400));
    QCOMPARE(pdoCommunicationIndex(PdoDirection::Transmit, 4), quint16(0x1803));
    QCOMPARE(pdoMappingIndex(PdoDirection::Receive, 2), quint16(0x1601));
    QCOMPARE(pdoMappingIndex(PdoDirection::Transmit, 1), quint16(0x1A00));
    QCOMPARE(pdoCobId(PdoDirection::Receive, 1, 3), 0x203u);
    QCOMPARE(pdoCobId(PdoDirection::Transmit, 1, 3), 0x183u);
}

void TestPdo::configurationWrites_disableMapEnable_data()
{
    QTest::addColumn<int>("direction");
    QTest::addColumn<QStringList>("expected");
    QTest::newRow("RPDO1 node 3") << int(PdoDirection::Receive)
                                  << QStringList{
                                         "node 3: 0x1400:01 UNSIGNED32 = 2147484163 (03 02 00 80)",
                                         "node 3: 0x1400:02 UNSIGNED8 = 1 (01)",
                                         "node 3: 0x1600:00 UNSIGNED8 = 0 (00)",
                                         "node 3: 0x1600:01 UNSIGNED32 = 1618608160 (20 00 7A 60)",
                                         "node 3: 0x1600:02 UNSIGNED32 = 1622278160 (10 00 B2 60)",
                                         "node 3: 0x1600:03 UNSIGNED32 = 1614807056 (10 00 40 60)",
                                         "node 3: 0x1600:00 UNSIGNED8 = 3 (03)",
                                         "node 3: 0x1400:01 UNSIGNED32 = 515 (03 02 00 00)"};
    QTest::newRow("TPDO1 node 3") << int(PdoDirection::Transmit)
                                  << QStringList{
                                         "node 3: 0x1800:01 UNSIGNED32 = 2147484035 (83 01 00 80)",
                                         "node 3: 0x1800:02 UNSIGNED8 = 1 (01)",
                                         "node 3: 0x1A00:00 UNSIGNED8 = 0 (00)",
                                         "node 3: 0x1A00:01 UNSIGNED32 = 1618608160 (20 00 7A 60)",
                                         "node 3: 0x1A00:02 UNSIGNED32 = 1622278160 (10 00 B2 60)",
                                         "node 3: 0x1A00:03 UNSIGNED32 = 1614807056 (10 00 40 60)",
                                         "node 3: 0x1A00:00 UNSIGNED8 = 3 (03)",
                                         "node 3: 0x1800:01 UNSIGNED32 = 387 (83 01 00 00)"};
}

void TestPdo::configurationWrites_disableMapEnable()
{
    QFETCH(int, direction);
    QFETCH(QStringList, expected);
    const SdoWriteSequence writes =
        pdoConfigurationWrites(3, PdoDirection(direction), 1, trialLikeMapping());
    QStringList got;
    for (const SdoWrite &w : writes)
        got << w.toString();
    QCOMPARE(got, expected);
}

void TestPdo::configurationWrites_invalidPdoNumber_throws()
{
    QVERIFY_THROWS_EXCEPTION(Error,
                             pdoConfigurationWrites(3, PdoDirection::Receive, 5, PdoMapping()));
    QVERIFY_THROWS_EXCEPTION(Error,
                             pdoConfigurationWrites(0, PdoDirection::Receive, 1, PdoMapping()));
}

QTEST_GUILESS_MAIN(TestPdo)
#include "tst_pdo.moc"
