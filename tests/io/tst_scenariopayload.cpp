// The scenario's payload keys (docs/scenario.md, payload and simulation.payload): a round trip
// bit for bit, and each bad value refused with its key path.
#include "IoTestSupport.h"
#include "io/ScenarioFile.h"
#include "model/PayloadPrior.h"
#include "session/RobotScenario.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTest>
#include <limits>

using namespace learnid;
using learnid::test::bitEqual;

namespace {

const QString source = QStringLiteral("scenario.json");

// The Panda's starting scenario with a payload on its flange link and a simulated one.
Scenario pandaWithPayload()
{
    Scenario s = scenarioForRobot(QStringLiteral("panda"));
    s.payload.enabled = true;
    s.payload.link = QStringLiteral("panda_link7");
    s.payload.mass = 2.5;
    s.payload.com = Eigen::Vector3d(0.01, -0.02, 0.05);
    s.payload.inertia = (Eigen::VectorXd(6) << 0.01, 0.001, 0.012, 0.0, 0.0, 0.008).finished();
    s.payload.box = (Eigen::VectorXd(6) << -0.1, -0.1, -0.05, 0.1, 0.1, 0.2).finished();
    s.payload.baselineTrials = 2;
    s.payload.baselineKp = s.controller.kp / 3.0;
    s.payload.baselineKi = s.controller.ki / 3.0;
    s.payload.baselineKd = s.controller.kd / 7.0;
    s.simulation.payload.present = true;
    s.simulation.payload.mass = 3.0;
    s.simulation.payload.com = Eigen::Vector3d(0.05, 0.0, 0.08);
    s.simulation.payload.inertia << 0.012, 0.001, 0.011, 0.0, 0.0, 0.006;
    return s;
}

QJsonObject pandaObject()
{
    return QJsonDocument::fromJson(scenarioToJson(pandaWithPayload())).object();
}

// Sets (undefined: removes) member `name` of the object at `section` ("payload.prior").
QByteArray with(const QString &section, const QString &name, const QJsonValue &value)
{
    const QStringList parts = section.split(QLatin1Char('.'));
    std::function<QJsonObject(QJsonObject, int)> set = [&](QJsonObject o, int depth) {
        if (depth == parts.size()) {
            if (value.isUndefined())
                o.remove(name);
            else
                o.insert(name, value);
            return o;
        }
        o.insert(parts[depth], set(o.value(parts[depth]).toObject(), depth + 1));
        return o;
    };
    return QJsonDocument(set(pandaObject(), 0)).toJson();
}

} // namespace

class TestScenarioPayload : public QObject
{
    Q_OBJECT

private slots:
    void payloadKeys_roundTripBitExactly()
    {
        const Scenario s = pandaWithPayload();
        const Scenario r = scenarioFromJson(scenarioToJson(s), source);
        QVERIFY(r.payload.enabled);
        QCOMPARE(r.payload.link, s.payload.link);
        QVERIFY(bitEqual(r.payload.mass, s.payload.mass));
        QVERIFY(bitEqual(Eigen::VectorXd(r.payload.com), Eigen::VectorXd(s.payload.com)));
        QVERIFY(bitEqual(r.payload.inertia, s.payload.inertia));
        QVERIFY(bitEqual(r.payload.box, s.payload.box));
        QCOMPARE(r.payload.baselineTrials, 2);
        QVERIFY(bitEqual(r.payload.baselineKp, s.payload.baselineKp));
        QVERIFY(bitEqual(r.payload.baselineKi, s.payload.baselineKi));
        QVERIFY(bitEqual(r.payload.baselineKd, s.payload.baselineKd));
        QVERIFY(r.simulation.payload.present);
        QVERIFY(bitEqual(r.simulation.payload.mass, s.simulation.payload.mass));
        QVERIFY(bitEqual(Eigen::VectorXd(r.simulation.payload.com),
                         Eigen::VectorXd(s.simulation.payload.com)));
        QVERIFY(bitEqual(Eigen::VectorXd(r.simulation.payload.inertia),
                         Eigen::VectorXd(s.simulation.payload.inertia)));
        QCOMPARE(scenarioToJson(r), scenarioToJson(s));
        // The prior the keys describe: the given body in the given box.
        const PayloadPrior prior = payloadPriorOf(r.payload);
        QVERIFY(prior.bound.box);
        QCOMPARE(prior.bound.lower, Eigen::Vector3d(-0.1, -0.1, -0.05));
        QCOMPARE(prior.parameters()[0], 2.5);
        QCOMPARE(prior.parameters()[3], 2.5 * 0.05); // m cz
    }

    void noPayload_writesNoPayloadKeys()
    {
        const QByteArray json = scenarioToJson(scenarioForRobot(QStringLiteral("panda")));
        QVERIFY(!json.contains("payload"));
        QVERIFY(!scenarioFromJson(json, source).payload.enabled);
    }

    void sphereByDefault_andMinimalSection()
    {
        QJsonObject o = pandaObject();
        o.insert(
            QStringLiteral("payload"),
            QJsonObject{{QStringLiteral("prior"), QJsonObject{{QStringLiteral("mass"), 1.5}}}});
        const Scenario r = scenarioFromJson(QJsonDocument(o).toJson(), source);
        QVERIFY(r.payload.enabled);
        QVERIFY(r.payload.link.isEmpty());
        QCOMPARE(r.payload.mass, 1.5);
        QCOMPARE(r.payload.radius, defaultPayloadRadius);
        QCOMPARE(r.payload.box.size(), 0);
        QCOMPARE(r.payload.inertia.size(), 0);
        QCOMPARE(r.payload.baselineTrials, 0);
    }

    void badValue_isRejectedWithKeyPath_data()
    {
        QTest::addColumn<QString>("section");
        QTest::addColumn<QString>("name");
        QTest::addColumn<QJsonValue>("value");
        QTest::addColumn<QString>("expected"); // the message after "scenario.json: " starts so
        const auto row = [](const char *tag, const char *section, const char *name,
                            const QJsonValue &v, const char *msg) {
            QTest::newRow(tag) << QString::fromLatin1(section) << QString::fromLatin1(name) << v
                               << QString::fromUtf8(msg);
        };
        row("negative mass", "payload.prior", "mass", -1.0,
            "payload.prior.mass: the payload's mass must be a positive number of kg, not -1");
        row("zero mass", "payload.prior", "mass", 0.0,
            "payload.prior.mass: the payload's mass must be a positive number of kg, not 0");
        row("mass null", "payload.prior", "mass", QJsonValue(QJsonValue::Null),
            "payload.prior.mass: must be a number, got null");
        row("mass nan", "payload.prior", "mass", QStringLiteral("nan"),
            "payload.prior.mass: must be a number, got \"nan\"");
        row("no mass", "payload.prior", "mass", QJsonValue(QJsonValue::Undefined),
            "payload.prior.mass: is missing; this key is required");
        row("no prior", "payload", "prior", QJsonValue(QJsonValue::Undefined),
            "payload.prior: is missing; this key is required");
        row("com length", "payload.prior", "com", QJsonArray{0.0, 0.1},
            "payload.prior.com: must have 3 entries (x, y and z), got 2");
        row("inertia length", "payload.prior", "inertia", QJsonArray{0.1, 0.0, 0.1},
            "payload.prior.inertia: must have 6 entries (Ixx, Ixy, Iyy, Ixz, Iyz and Izz), got 3");
        row("inertia not a body", "payload.prior", "inertia",
            QJsonArray{0.001, 0.0, 0.001, 0.0, 0.0, 0.01},
            "payload.prior.inertia: the inertia is not a real body's");
        row("unknown link", "payload", "link", QStringLiteral("gripper"),
            "payload.link: payload link 'gripper' is not a moving link");
        row("box without the com", "payload.bound", "box", QJsonArray{0.1, 0.1, 0.1, 0.2, 0.2, 0.2},
            "payload.bound.box: the prior centre of mass (0.01, -0.02, 0.05) m is not inside "
            "the bound");
        row("box upside down", "payload.bound", "box", QJsonArray{0.1, 0.1, 0.1, 0.0, 0.2, 0.2},
            "payload.bound.box: the box's upper corner");
        row("baselineTrials negative", "payload", "baselineTrials", -1,
            "payload.baselineTrials: must be an integer from 0 to 100, got -1");
        row("baselineTrials fraction", "payload", "baselineTrials", 1.5,
            "payload.baselineTrials: must be an integer from 0 to 100, got 1.5");
        row("baseline kp length", "payload.baselineGains", "kp", QJsonArray{100.0, 100.0},
            "payload.baselineGains.kp: must have 7 entries (one per joint), got 2");
        row("baseline kd negative", "payload.baselineGains", "kd",
            QJsonArray{1.0, 1.0, 1.0, -1.0, 1.0, 1.0, 1.0}, "payload.baselineGains.kd[3]:");
        row("baseline no ki", "payload.baselineGains", "ki", QJsonValue(QJsonValue::Undefined),
            "payload.baselineGains.ki: is missing; this key is required");
        row("baseline unknown key", "payload.baselineGains", "lambda", 100.0,
            "payload.baselineGains.lambda: unknown key; allowed here: kp, ki, kd");
        row("unknown prior key", "payload.prior", "volume", 1.0,
            "payload.prior.volume: unknown key; allowed here: mass, com, inertia");
        row("sim negative mass", "simulation.payload", "mass", -3.0,
            "simulation.payload.mass: must be a positive number, got -3");
        row("sim inertia not a body", "simulation.payload", "inertia",
            QJsonArray{-0.01, 0.0, 0.01, 0.0, 0.0, 0.01},
            "simulation.payload.inertia: not a "
            "real body's inertia");
        row("sim unknown key", "simulation.payload", "link", QStringLiteral("panda_link7"),
            "simulation.payload.link: unknown key; allowed here: mass, com, inertia");
    }

    void badValue_isRejectedWithKeyPath()
    {
        QFETCH(QString, section);
        QFETCH(QString, name);
        QFETCH(QJsonValue, value);
        QFETCH(QString, expected);
        const QString message =
            test::errorOf([&] { scenarioFromJson(with(section, name, value), source); });
        QVERIFY2(message.startsWith(source + QStringLiteral(": ") + expected), qPrintable(message));
    }

    void radiusWithoutTheCom_andBothBounds_areRejected()
    {
        QJsonObject o = pandaObject();
        QJsonObject payload = o.value(QStringLiteral("payload")).toObject();
        payload.insert(QStringLiteral("bound"), QJsonObject{{QStringLiteral("radius"), 0.04}});
        o.insert(QStringLiteral("payload"), payload);
        QString message =
            test::errorOf([&] { scenarioFromJson(QJsonDocument(o).toJson(), source); });
        QVERIFY2(message.startsWith(QStringLiteral("scenario.json: payload.bound.radius: the prior "
                                                   "centre of mass")),
                 qPrintable(message));
        payload.insert(QStringLiteral("bound"),
                       QJsonObject{{QStringLiteral("radius"), 0.3},
                                   {QStringLiteral("box"), QJsonArray{-1, -1, -1, 1, 1, 1}}});
        o.insert(QStringLiteral("payload"), payload);
        message = test::errorOf([&] { scenarioFromJson(QJsonDocument(o).toJson(), source); });
        QVERIFY2(message.startsWith(QStringLiteral("scenario.json: payload.bound.box: give the "
                                                   "bound either")),
                 qPrintable(message));
    }

    void notANumber_fromAnEditor_isRejectedWithKeyPath()
    {
        Scenario s = pandaWithPayload();
        s.payload.mass = std::numeric_limits<double>::quiet_NaN();
        QString message = test::errorOf([&] { validateScenario(s); });
        QVERIFY2(message.startsWith(QStringLiteral("payload.prior.mass:")), qPrintable(message));
        s = pandaWithPayload();
        s.simulation.payload.com.y() = std::numeric_limits<double>::quiet_NaN();
        message = test::errorOf([&] { validateScenario(s); });
        QVERIFY2(message.startsWith(QStringLiteral("simulation.payload.com[1]:")),
                 qPrintable(message));
    }

    void payloadOnThePaperArm_isRejected()
    {
        Scenario s;
        s.payload.enabled = true;
        s.payload.mass = 1.0;
        const QString message = test::errorOf([&] { validateScenario(s); });
        QVERIFY2(message.startsWith(QStringLiteral("payload: only a URDF robot carries a payload")),
                 qPrintable(message));
    }
};

QTEST_GUILESS_MAIN(TestScenarioPayload)
#include "tst_scenariopayload.moc"
