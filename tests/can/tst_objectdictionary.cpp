#include "can/ObjectDictionary.h"
#include "can/SdoAbortCode.h"
#include "model/Error.h"

#include <QSignalSpy>
#include <QTest>
#include <cmath>

using namespace learnid;
using canopen::DataType;
using Access = ObjectDictionary::Access;

class TestObjectDictionary : public QObject
{
    Q_OBJECT

private slots:
    void read_existingEntry_givesLittleEndianBytes();
    void read_missingObjectOrSubIndex_givesTheirAbortCodes();
    void read_writeOnly_isRefused();
    void write_readOnlyOrConstant_isRefused();
    void write_wrongLength_isRefusedWithTooHighOrTooLow();
    void write_checksValidatorAndEmitsValueWritten();
    void rangeValidator_refusesValuesOutsideTheRange();
    void variableLengthEntry_boundsWrittenSize();
    void checkWrite_beforeDataArrive_reportsTheSameCodes();
    void localAccess_bypassesAccessRightsButNotTypes();
    void add_twiceOrWrongKind_throws();
};

void TestObjectDictionary::read_existingEntry_givesLittleEndianBytes()
{
    ObjectDictionary od;
    od.add(0x6041, 0, DataType::Unsigned16, Access::ReadOnly, 0x1234);
    QByteArray out;
    QCOMPARE(od.read(0x6041, 0, &out), 0u);
    QCOMPARE(out, QByteArray::fromHex("3412"));
    QVERIFY(od.contains(0x6041, 0));
    QVERIFY(od.containsIndex(0x6041));
    QCOMPARE(od.type(0x6041, 0), DataType::Unsigned16);
}

void TestObjectDictionary::read_missingObjectOrSubIndex_givesTheirAbortCodes()
{
    ObjectDictionary od;
    od.add(0x2200, 0, DataType::Unsigned8, Access::ReadWrite, 3);
    od.add(0x2201, 0, DataType::Unsigned8, Access::ReadWrite, 3);
    QCOMPARE(od.read(0x2200, 1, nullptr), sdoabort::subIndexDoesNotExist);
    QCOMPARE(od.read(0x21FF, 0, nullptr), sdoabort::objectDoesNotExist);
    QCOMPARE(od.read(0x2202, 0, nullptr), sdoabort::objectDoesNotExist);
    QVERIFY(!od.containsIndex(0x2202));
}

void TestObjectDictionary::read_writeOnly_isRefused()
{
    ObjectDictionary od;
    od.add(0x1010, 1, DataType::Unsigned32, Access::WriteOnly);
    QByteArray out("untouched");
    QCOMPARE(od.read(0x1010, 1, &out), sdoabort::writeOnly);
    QCOMPARE(out, QByteArray("untouched"));
}

void TestObjectDictionary::write_readOnlyOrConstant_isRefused()
{
    ObjectDictionary od;
    od.add(0x6041, 0, DataType::Unsigned16, Access::ReadOnly);
    od.add(0x1000, 0, DataType::Unsigned32, Access::Constant, 0x00020192);
    QCOMPARE(od.write(0x6041, 0, QByteArray(2, '\x01')), sdoabort::readOnly);
    QCOMPARE(od.write(0x1000, 0, QByteArray(4, '\x01')), sdoabort::readOnly);
    QCOMPARE(od.value(0x1000, 0), double(0x00020192));
}

void TestObjectDictionary::write_wrongLength_isRefusedWithTooHighOrTooLow()
{
    ObjectDictionary od;
    od.add(0x607A, 0, DataType::Integer32, Access::ReadWrite);
    QCOMPARE(od.write(0x607A, 0, QByteArray(2, '\0')), sdoabort::lengthTooLow);
    QCOMPARE(od.write(0x607A, 0, QByteArray(5, '\0')), sdoabort::lengthTooHigh);
    QCOMPARE(od.write(0x607A, 0, QByteArray::fromHex("FFFFFFFF")), 0u);
    QCOMPARE(od.value(0x607A, 0), -1.0);
}

void TestObjectDictionary::write_checksValidatorAndEmitsValueWritten()
{
    ObjectDictionary od;
    od.add(0x1010, 1, DataType::Unsigned32, Access::WriteOnly, 0,
           [](const QByteArray &raw) { return raw == "save" ? 0u : sdoabort::cannotStore; });
    QSignalSpy written(&od, &ObjectDictionary::valueWritten);
    QCOMPARE(od.write(0x1010, 1, QByteArray("SAVE")), sdoabort::cannotStore);
    QCOMPARE(written.count(), 0);
    QCOMPARE(od.write(0x1010, 1, QByteArray("save")), 0u);
    QCOMPARE(written.count(), 1);
    QCOMPARE(written.at(0).at(0).value<quint16>(), quint16(0x1010));
    QCOMPARE(written.at(0).at(1).value<quint8>(), quint8(1));
}

void TestObjectDictionary::rangeValidator_refusesValuesOutsideTheRange()
{
    ObjectDictionary od;
    od.add(0x2300, 0, DataType::Real32, Access::ReadWrite, 8.0,
           ObjectDictionary::rangeValidator(DataType::Real32, 0.0, 100.0));
    const auto real = [](double v) {
        return canopen::encodeValue(DataType::Real32, v);
    };
    QCOMPARE(od.write(0x2300, 0, real(100.5)), sdoabort::valueTooHigh);
    QCOMPARE(od.write(0x2300, 0, real(-0.5)), sdoabort::valueTooLow);
    QCOMPARE(od.write(0x2300, 0, QByteArray::fromHex("0000C07F")), sdoabort::invalidValue); // NaN
    QCOMPARE(od.write(0x2300, 0, real(100.0)), 0u);
    QCOMPARE(od.value(0x2300, 0), 100.0);
}

void TestObjectDictionary::variableLengthEntry_boundsWrittenSize()
{
    ObjectDictionary od;
    od.addBytes(0x2400, 0, DataType::Domain, Access::ReadWrite, "abc", 4);
    QCOMPARE(od.write(0x2400, 0, "abcde"), sdoabort::lengthTooHigh);
    QCOMPARE(od.write(0x2400, 0, "x"), 0u);
    QCOMPARE(od.bytes(0x2400, 0), QByteArray("x"));
}

void TestObjectDictionary::checkWrite_beforeDataArrive_reportsTheSameCodes()
{
    ObjectDictionary od;
    od.add(0x607A, 0, DataType::Integer32, Access::ReadWrite);
    QCOMPARE(od.checkWrite(0x607A, 0, -1), 0u);
    QCOMPARE(od.checkWrite(0x607A, 0, 4), 0u);
    QCOMPARE(od.checkWrite(0x607A, 0, 8), sdoabort::lengthTooHigh);
    QCOMPARE(od.checkWrite(0x607B, 0, 4), sdoabort::objectDoesNotExist);
}

void TestObjectDictionary::localAccess_bypassesAccessRightsButNotTypes()
{
    ObjectDictionary od;
    od.add(0x6064, 0, DataType::Integer32, Access::ReadOnly);
    QSignalSpy written(&od, &ObjectDictionary::valueWritten);
    od.setValue(0x6064, 0, -2147483648.0);
    QCOMPARE(od.value(0x6064, 0), -2147483648.0);
    QCOMPARE(written.count(), 0);
    QVERIFY_THROWS_EXCEPTION(Error, od.setValue(0x6064, 0, 2147483648.0));
    QVERIFY_THROWS_EXCEPTION(Error, od.setValue(0x6065, 0, 1.0));
    QVERIFY_THROWS_EXCEPTION(Error, od.setBytes(0x6064, 0, QByteArray(2, '\0')));
    QVERIFY_THROWS_EXCEPTION(Error, od.value(0x6065, 0));
}

void TestObjectDictionary::add_twiceOrWrongKind_throws()
{
    ObjectDictionary od;
    od.add(0x6040, 0, DataType::Unsigned16, Access::ReadWrite);
    QVERIFY_THROWS_EXCEPTION(Error, od.add(0x6040, 0, DataType::Unsigned16, Access::ReadWrite));
    QVERIFY_THROWS_EXCEPTION(Error, od.add(0x6041, 0, DataType::Domain, Access::ReadWrite));
    QVERIFY_THROWS_EXCEPTION(Error,
                             od.addBytes(0x6042, 0, DataType::Integer8, Access::ReadWrite, {}));
    QVERIFY_THROWS_EXCEPTION(Error, od.add(0x6043, 0, DataType::Unsigned8, Access::ReadWrite, 300));
}

QTEST_GUILESS_MAIN(TestObjectDictionary)
#include "tst_objectdictionary.moc"
