#pragma once
// The bus of the end-to-end CAN tests: virtualcan on a loopback port of the test's own (the
// default, on any machine), or, with LEARNID_CAN_E2E_PLUGIN=socketcan, a real SocketCAN
// interface (LEARNID_CAN_E2E_INTERFACE, default vcan0) inside the VM of scripts/test-socketcan.
// LEARNID_CAN_E2E_PERIOD_MS sets the SYNC period of the sessions (default: each test's own).

#include "RobotSimProcess.h"

#include <QElapsedTimer>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QString>
#include <QStringList>
#include <QTest>
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

/// Tells when the drives follow set-points, so that a test can break something in the middle of
/// a trial: on SocketCAN a candump of the bus sees the master's RPDO to node with controlword
/// 0x000F (enable operation, bytes 6 and 7); virtualcan cannot be listened to, so there it is 3 s
/// after the tool started (configuration, enable walk and return move take about 1.5 s on this
/// machine). Start it before the tool.
class DrivesFollowWatch
{
public:
    DrivesFollowWatch(const QString &interface, quint32 node)
    {
        if (!canE2eOnSocketCan())
            return;
        m_candump.start(QStringLiteral("candump"),
                        {QStringLiteral("-L"), QStringLiteral("%1,%2:7FF")
                                                   .arg(interface)
                                                   .arg(0x200 + node, 3, 16, QLatin1Char('0'))});
        m_candump.waitForStarted();
    }
    ~DrivesFollowWatch()
    {
        m_candump.kill();
        m_candump.waitForFinished(2000);
    }

    /// Waits (60 s at most) until the drives follow, plus settleMs, gathering the tool's stderr
    /// meanwhile; false when the tool ended first or nothing came.
    bool wait(QProcess &tool, QByteArray *toolErr, int settleMs = 500)
    {
        QElapsedTimer clock;
        clock.start();
        const auto gather = [&](int ms) {
            tool.waitForReadyRead(ms);
            *toolErr += tool.readAllStandardError();
            return tool.state() == QProcess::Running;
        };
        if (!canE2eOnSocketCan()) {
            while (clock.elapsed() < 3000)
                if (!gather(50))
                    return false;
            return true;
        }
        bool enabled = false;
        while (!enabled && clock.elapsed() < 60000) {
            if (!gather(20))
                return false;
            m_candump.waitForReadyRead(0);
            while (m_candump.canReadLine()) {
                // "(1712345678.123456) vcan0 201#0000000000000F00"
                const QByteArray data = m_candump.readLine().trimmed().split('#').value(1);
                enabled = enabled || data.mid(12, 4).toUpper() == "0F00";
            }
        }
        QElapsedTimer settle;
        settle.start();
        while (enabled && settle.elapsed() < settleMs)
            if (!gather(20))
                return false;
        return enabled;
    }

private:
    QProcess m_candump;
};

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
