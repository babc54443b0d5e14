#pragma once
// The bus of the end-to-end CAN tests: virtualcan on a loopback port of the test's own (the
// default, on any machine), or, with LEARNID_CAN_E2E_PLUGIN=socketcan, a real SocketCAN
// interface (LEARNID_CAN_E2E_INTERFACE, default vcan0) inside the VM of scripts/test-socketcan.
// LEARNID_CAN_E2E_PERIOD_MS sets the SYNC period of the sessions (default: each test's own).

#include "RobotSimProcess.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QString>
#include <QStringList>
#include <QtGlobal>

namespace learnid::test {

inline bool canE2eOnSocketCan()
{
    return qEnvironmentVariable("LEARNID_CAN_E2E_PLUGIN") == QLatin1String("socketcan");
}

inline QString canE2ePlugin()
{
    return canE2eOnSocketCan() ? QStringLiteral("socketcan") : QStringLiteral("virtualcan");
}

/// The interface of a test's bus: the SocketCAN interface, or virtualcan on port.
inline QString canE2eInterface(quint16 port)
{
    if (canE2eOnSocketCan())
        return qEnvironmentVariable("LEARNID_CAN_E2E_INTERFACE", QStringLiteral("vcan0"));
    return QStringLiteral("tcp://127.0.0.1:%1/can0").arg(port);
}

/// A port for canE2eInterface (0 on SocketCAN, where none is needed).
inline quint16 canE2ePort()
{
    return canE2eOnSocketCan() ? quint16(0) : freeLoopbackPort();
}

/// The SYNC period of the sessions [ms], fallback when LEARNID_CAN_E2E_PERIOD_MS is not set.
inline int canE2ePeriodMs(int fallback)
{
    bool ok = false;
    const int ms = qEnvironmentVariableIntValue("LEARNID_CAN_E2E_PERIOD_MS", &ok);
    return ok && ms > 0 ? ms : fallback;
}

/// --can-plugin and --can-interface for either tool.
inline QStringList canE2eBusOptions(quint16 port)
{
    return {QStringLiteral("--can-plugin"), canE2ePlugin(), QStringLiteral("--can-interface"),
            canE2eInterface(port)};
}

/// The paper scenario (JSON of `learnid-cli scenario --print`) at a SYNC period of periodMs,
/// with gains that pass the pre-trial check there (kp 900 / 1000, ki 6, kd 120, lambda 60: the
/// 2 ms gains are unstable at 5 and 10 ms); empty when the JSON is not a scenario.
inline QByteArray paperScenarioAt(const QByteArray &json, int periodMs)
{
    QJsonObject scenario = QJsonDocument::fromJson(json).object();
    if (!scenario.contains(QStringLiteral("controller")))
        return {};
    QJsonObject c = scenario.value(QStringLiteral("controller")).toObject();
    c.insert(QStringLiteral("samplePeriod"), periodMs / 1000.0);
    c.insert(QStringLiteral("kp"), QJsonArray{900, 1000});
    c.insert(QStringLiteral("ki"), QJsonArray{6, 6});
    c.insert(QStringLiteral("kd"), QJsonArray{120, 120});
    c.insert(QStringLiteral("lambda"), 60);
    scenario.insert(QStringLiteral("controller"), c);
    return QJsonDocument(scenario).toJson();
}

} // namespace learnid::test
