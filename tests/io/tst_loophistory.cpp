#include "IoTestSupport.h"
#include "io/LoopHistory.h"

#include <QTest>

using namespace learnid;
using learnid::test::bitEqual;

class TestLoopHistory : public QObject
{
    Q_OBJECT

private slots:
    void writeThenRead_keepsEverything();
    void badIndex_namesTheKey_data();
    void badIndex_namesTheKey();
    void writer_refusesWhatTheReaderWould();
    void payloadLink_isWrittenOnlyForThePayloadsLoop();
};

namespace {

const QString source = QStringLiteral("history.json");

LoopHistory sampleHistory()
{
    LoopHistory h;
    h.robotModel = QStringLiteral("paper-2link");
    h.joints = 2;
    h.parameters = 3;
    h.law = QStringLiteral("improved");
    h.estimates = {QStringLiteral("estimate-0.json"), QStringLiteral("estimate-1.json")};
    LoopHistory::Trial t;
    t.planId = QString(64, QLatin1Char('a'));
    t.plan = QStringLiteral("trial-000-plan.csv");
    t.logs = {QStringLiteral("trial-000-log.csv")};
    t.maxTrackingErrorDeg = Eigen::Vector2d(0.04405 / 3, 0.1);
    t.rmsTrackingErrorDeg = Eigen::Vector2d(0.01, 1e-17);
    h.trials << t;
    h.pendingPlans << LoopHistory::PendingPlan{QString(64, QLatin1Char('b')),
                                               QStringLiteral("plan-bbbbbbbbbbbbbbbb.csv")};
    return h;
}

// The sample's JSON with one text replaced.
QByteArray edited(const QByteArray &from, const QByteArray &to)
{
    QByteArray json = loopHistoryToJson(sampleHistory());
    json.replace(from, to);
    return json;
}

} // namespace

void TestLoopHistory::writeThenRead_keepsEverything()
{
    const LoopHistory h = sampleHistory();
    const LoopHistory read = loopHistoryFromJson(loopHistoryToJson(h), source);
    QCOMPARE(read.robotModel, h.robotModel);
    QCOMPARE(read.joints, 2);
    QCOMPARE(read.parameters, 3);
    QCOMPARE(read.law, h.law);
    QCOMPARE(read.estimates, h.estimates);
    QCOMPARE(read.trials.size(), 1);
    QCOMPARE(read.trials.at(0).planId, h.trials.at(0).planId);
    QCOMPARE(read.trials.at(0).plan, h.trials.at(0).plan);
    QCOMPARE(read.trials.at(0).logs, h.trials.at(0).logs);
    QVERIFY(bitEqual(read.trials.at(0).maxTrackingErrorDeg, h.trials.at(0).maxTrackingErrorDeg));
    QVERIFY(bitEqual(read.trials.at(0).rmsTrackingErrorDeg, h.trials.at(0).rmsTrackingErrorDeg));
    QCOMPARE(read.pendingPlans.size(), 1);
    QCOMPARE(read.pendingPlans.at(0).planId, h.pendingPlans.at(0).planId);
    QCOMPARE(read.pendingPlans.at(0).plan, h.pendingPlans.at(0).plan);
}

void TestLoopHistory::badIndex_namesTheKey_data()
{
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QString>("message");
    QTest::newRow("schema") << edited("learnid-history/1", "learnid-history/9")
                            << "history.json: schema: this version of learnid reads";
    QTest::newRow("unknown key") << edited("\"law\"", "\"lore\"")
                                 << "history.json: law: is missing";
    QTest::newRow("joints") << edited("\"joints\": 2", "\"joints\": 0")
                            << "history.json: robot.joints: must be an integer from 1 to 64";
    QTest::newRow("estimates") << edited(", \"estimate-1.json\"", "")
                               << "history.json: estimates: must have 2 entries (one more than "
                                  "trials, the initial estimate first), got";
    QTest::newRow("path in a name") << edited("trial-000-log.csv", "../escape.csv")
                                    << "history.json: trials[0].logs[0]: must be a plain file name";
    QTest::newRow("plan-id") << edited(QByteArray(64, 'b'), "b")
                             << "history.json: pendingPlans[0].planId: must be 64 lower-case hex";
    QTest::newRow("figures") << edited("[0.01, 1e-17]", "[0.01]")
                             << "history.json: trials[0].rmsTrackingErrorDeg: must have 2 entries";
    QTest::newRow("syntax") << QByteArray("{") << "history.json";
}

void TestLoopHistory::badIndex_namesTheKey()
{
    QFETCH(QByteArray, json);
    QFETCH(QString, message);
    LEARNID_VERIFY_ERROR(loopHistoryFromJson(json, source), message);
}

void TestLoopHistory::writer_refusesWhatTheReaderWould()
{
    LoopHistory h = sampleHistory();
    h.estimates.removeLast();
    LEARNID_VERIFY_ERROR(loopHistoryToJson(h), "estimates: must have 2 entries");
    h = sampleHistory();
    h.trials[0].plan = QStringLiteral("/etc/passwd");
    LEARNID_VERIFY_ERROR(loopHistoryToJson(h), "trials[0].plan: must be a plain file name");
}

// The payload's loop marks its history with "payload": {"link": ...}; the arm's history stays
// as it was (no such key), so histories of earlier versions read unchanged.
void TestLoopHistory::payloadLink_isWrittenOnlyForThePayloadsLoop()
{
    const QByteArray arm = loopHistoryToJson(sampleHistory());
    QVERIFY(!arm.contains("payload"));
    QVERIFY(loopHistoryFromJson(arm, source).payloadLink.isEmpty());
    LoopHistory h = sampleHistory();
    h.payloadLink = QStringLiteral("panda_link7");
    const QByteArray json = loopHistoryToJson(h);
    QVERIFY2(json.contains("\"payload\": {\n        \"link\": \"panda_link7\"\n    }"),
             json.constData());
    QCOMPARE(loopHistoryFromJson(json, source).payloadLink, h.payloadLink);
    QByteArray bad = json;
    bad.replace("\"link\": \"panda_link7\"", "\"link\": \"\"");
    LEARNID_VERIFY_ERROR(loopHistoryFromJson(bad, source),
                         "history.json: payload.link: must not be empty");
    bad = json;
    bad.replace("\"link\": \"panda_link7\"", "\"link\": \"panda_link7\", \"mass\": 1");
    LEARNID_VERIFY_ERROR(loopHistoryFromJson(bad, source), "history.json: payload.mass");
    bad = json;
    bad.replace("\"link\": \"panda_link7\"", "\"name\": \"panda_link7\"");
    LEARNID_VERIFY_ERROR(loopHistoryFromJson(bad, source),
                         "history.json: payload.link: is missing");
}

QTEST_GUILESS_MAIN(TestLoopHistory)
#include "tst_loophistory.moc"
