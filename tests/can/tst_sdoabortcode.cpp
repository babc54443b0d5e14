#include "can/SdoAbortCode.h"

#include <QTest>

using namespace learnid;

class TestSdoAbortCode : public QObject
{
    Q_OBJECT

private slots:
    void knownCodes_haveTheirCiA301Meaning_data();
    void knownCodes_haveTheirCiA301Meaning();
    void unknownCode_isNamedInTheMessage();
    void codeText_isEightHexDigits();
};

void TestSdoAbortCode::knownCodes_haveTheirCiA301Meaning_data()
{
    QTest::addColumn<quint32>("code");
    QTest::addColumn<QString>("words");
    QTest::newRow("toggle") << 0x05030000u << "Toggle bit";
    QTest::newRow("timeout") << 0x05040000u << "timed out";
    QTest::newRow("command") << 0x05040001u << "command specifier";
    QTest::newRow("unsupported") << 0x06010000u << "Unsupported access";
    QTest::newRow("write-only") << 0x06010001u << "write-only";
    QTest::newRow("read-only") << 0x06010002u << "read-only";
    QTest::newRow("no object") << 0x06020000u << "does not exist";
    QTest::newRow("not mappable") << 0x06040041u << "cannot be mapped";
    QTest::newRow("PDO length") << 0x06040042u << "PDO length";
    QTest::newRow("length") << 0x06070010u << "length";
    QTest::newRow("too high") << 0x06070012u << "too high";
    QTest::newRow("too low") << 0x06070013u << "too low";
    QTest::newRow("no sub-index") << 0x06090011u << "Sub-index does not exist";
    QTest::newRow("value") << 0x06090030u << "Invalid value";
    QTest::newRow("value high") << 0x06090031u << "too high";
    QTest::newRow("value low") << 0x06090032u << "too low";
    QTest::newRow("general") << 0x08000000u << "General error";
    QTest::newRow("store") << 0x08000020u << "cannot be transferred or stored";
    QTest::newRow("local control") << 0x08000021u << "local control";
    QTest::newRow("device state") << 0x08000022u << "device state";
}

void TestSdoAbortCode::knownCodes_haveTheirCiA301Meaning()
{
    QFETCH(quint32, code);
    QFETCH(QString, words);
    const QString text = sdoabort::message(code);
    QVERIFY2(text.contains(words), qPrintable(text));
    QVERIFY(!text.contains("Unknown"));
}

void TestSdoAbortCode::unknownCode_isNamedInTheMessage()
{
    QCOMPARE(sdoabort::message(0x12345678), QString("Unknown abort code 0x12345678."));
}

void TestSdoAbortCode::codeText_isEightHexDigits()
{
    QCOMPARE(sdoabort::codeText(0x0602000A), QString("0x0602000A"));
    QCOMPARE(sdoabort::codeText(0), QString("0x00000000"));
}

QTEST_GUILESS_MAIN(TestSdoAbortCode)
#include "tst_sdoabortcode.moc"
