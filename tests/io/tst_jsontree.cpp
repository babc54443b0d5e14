#include "IoTestSupport.h"
#include "io/JsonTree.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTest>
#include <cmath>
#include <limits>
#include <random>

using namespace learnid;
using learnid::test::bitEqual;

class TestJsonTree : public QObject
{
    Q_OBJECT

private slots:
    void objectMembers_keepInsertionOrder();
    void numbers_readBackBitExactly();
    void integralNumbers_areWrittenWithoutFraction();
    void nonFiniteNumbers_becomeNull();
    void strings_areEscapedAndReadBack();
    void nesting_isIndentedAndParses();
    void toJsonValue_holdsTheSameValues();
};

void TestJsonTree::objectMembers_keepInsertionOrder()
{
    JsonTree t = JsonTree::object();
    t.insert(QStringLiteral("zeta"), 1)
        .insert(QStringLiteral("alpha"), 2)
        .insert(QStringLiteral("mid"), 3);
    QCOMPARE(t.toJson(), QByteArray("{\n    \"zeta\": 1,\n    \"alpha\": 2,\n    \"mid\": 3\n}\n"));
}

void TestJsonTree::numbers_readBackBitExactly()
{
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
    std::uniform_int_distribution<int> exponent(-990, 1000);
    JsonTree a = JsonTree::array();
    // Normal doubles only: Qt's parser reads -0 as 0 and rounds subnormals (below 2.2e-308)
    // inexactly; neither occurs in learnid's files.
    std::vector<double> values = {0.1,
                                  0.2 + 0.1,
                                  1.0 / 3.0,
                                  4500.0,
                                  1e-5,
                                  std::numeric_limits<double>::max(),
                                  std::numeric_limits<double>::min(),
                                  9007199254740993.0,
                                  1e21,
                                  123456789.125,
                                  -2.0 / 3.0 * 1e-300};
    for (int i = 0; i < 20000; ++i)
        values.push_back(std::ldexp(mantissa(rng), exponent(rng)));
    for (double v : values)
        a.append(v);
    const QJsonArray back =
        QJsonDocument::fromJson("{\"a\": " + a.toJson() + "}").object().value("a").toArray();
    QCOMPARE(back.size(), qsizetype(values.size()));
    for (size_t i = 0; i < values.size(); ++i) {
        QVERIFY2(bitEqual(back.at(qsizetype(i)).toDouble(), values[i]),
                 qPrintable(QString::number(values[i], 'g', 17)));
    }
}

void TestJsonTree::integralNumbers_areWrittenWithoutFraction()
{
    QCOMPARE(JsonTree::formatNumber(4500.0), QByteArray("4500"));
    QCOMPARE(JsonTree::formatNumber(-3.0), QByteArray("-3"));
    QCOMPARE(JsonTree::formatNumber(0.002), QByteArray("0.002"));
    QCOMPARE(JsonTree::formatNumber(1e21), QByteArray("1e+21"));
}

void TestJsonTree::nonFiniteNumbers_becomeNull()
{
    Eigen::VectorXd v(3);
    v << 1.0, std::numeric_limits<double>::infinity(), std::numeric_limits<double>::quiet_NaN();
    QCOMPARE(JsonTree::numbers(v).toJson(), QByteArray("[1, null, null]\n"));
}

void TestJsonTree::strings_areEscapedAndReadBack()
{
    const QString text =
        QString::fromUtf8("quote \" backslash \\ tab \t newline \n bell \x07 kg m² °");
    JsonTree t = JsonTree::object();
    t.insert(QStringLiteral("s"), text);
    const QByteArray json = t.toJson();
    QVERIFY(json.contains("\\u0007"));
    QCOMPARE(QJsonDocument::fromJson(json).object().value("s").toString(), text);
}

void TestJsonTree::nesting_isIndentedAndParses()
{
    JsonTree inner = JsonTree::object();
    inner.insert(QStringLiteral("x"), true);
    JsonTree list = JsonTree::array();
    list.append(inner).append(JsonTree::object()).append(JsonTree());
    JsonTree root = JsonTree::object();
    root.insert(QStringLiteral("list"), list).insert(QStringLiteral("empty"), JsonTree::array());
    const QByteArray expected = "{\n"
                                "    \"list\": [\n"
                                "        {\n"
                                "            \"x\": true\n"
                                "        },\n"
                                "        {},\n"
                                "        null\n"
                                "    ],\n"
                                "    \"empty\": []\n"
                                "}\n";
    QCOMPARE(root.toJson(), expected);
}

void TestJsonTree::toJsonValue_holdsTheSameValues()
{
    JsonTree root = JsonTree::object();
    root.insert(QStringLiteral("b"), 2.5).insert(QStringLiteral("a"), QStringLiteral("x"));
    const QJsonObject o = root.toJsonValue().toObject();
    QCOMPARE(o.value("b").toDouble(), 2.5);
    QCOMPARE(o.value("a").toString(), QStringLiteral("x"));
    QCOMPARE(QJsonDocument::fromJson(root.toJson()).object(), o);
}

QTEST_GUILESS_MAIN(TestJsonTree)
#include "tst_jsontree.moc"
