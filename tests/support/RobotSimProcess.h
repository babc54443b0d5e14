#pragma once
// Test support for end-to-end tests over virtualcan: a loopback port nobody listens on, and
// learnid-robot-sim as a second process that is stopped when the test ends.

#include <QElapsedTimer>
#include <QFile>
#include <QHostAddress>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QStringList>
#include <QTcpServer>
#include <cmath>

namespace learnid::test {

/// A loopback TCP port free right now (0 when none could be had). virtualcan's server is then
/// hosted by the first process that opens tcp://127.0.0.1:PORT/can0.
inline quint16 freeLoopbackPort()
{
    QTcpServer probe;
    return probe.listen(QHostAddress::LocalHost, 0) ? probe.serverPort() : 0;
}

/// What learnid-robot-sim's --state file says of the payload every node stored (0x2500),
/// against `joints` nodes holding `expected` on `joint`: empty when each does to within
/// relative x |value| + absolute (0, 0: exactly), else the first difference in words.
inline QString storedPayloadMismatch(const QString &statePath, int joints, int joint,
                                     const QList<double> &expected, double relative,
                                     double absolute)
{
    QFile f(statePath);
    if (!f.open(QIODevice::ReadOnly))
        return QStringLiteral("%1 cannot be read").arg(statePath);
    const QJsonObject nodes =
        QJsonDocument::fromJson(f.readAll()).object().value(QStringLiteral("nodes")).toObject();
    if (nodes.size() != joints)
        return QStringLiteral("%1 nodes, not %2").arg(nodes.size()).arg(joints);
    for (const QString &node : nodes.keys()) {
        const QJsonObject stored =
            nodes.value(node).toObject().value(QStringLiteral("storedPayload")).toObject();
        if (stored.value(QStringLiteral("joint")).toInt() != joint)
            return QStringLiteral("node %1 stored no payload on joint %2").arg(node).arg(joint);
        const QJsonArray values = stored.value(QStringLiteral("parameters")).toArray();
        if (values.size() != expected.size())
            return QStringLiteral("node %1 stored %2 values").arg(node).arg(values.size());
        for (int i = 0; i < values.size(); ++i) {
            if (std::abs(values[i].toDouble() - expected[i]) >
                relative * std::abs(expected[i]) + absolute)
                return QStringLiteral("node %1, 0x2500:%2: %3 against %4")
                    .arg(node)
                    .arg(i + 2)
                    .arg(values[i].toDouble())
                    .arg(expected[i]);
        }
    }
    return {};
}

/// learnid-robot-sim on a virtualcan interface, terminated (then killed) on destruction.
class RobotSimProcess
{
public:
    explicit RobotSimProcess(QString program)
        : m_program(std::move(program))
    {}
    ~RobotSimProcess()
    {
        if (m_process.state() == QProcess::NotRunning)
            return;
        m_process.terminate();
        if (!m_process.waitForFinished(5000))
            m_process.kill();
        m_process.waitForFinished(5000);
    }

    /// Starts the simulator on the virtualcan interface with further options and waits (10 s at
    /// most) for its "ready" line.
    bool start(const QString &interface, const QStringList &options = {})
    {
        return startOn(QStringLiteral("virtualcan"), interface, options);
    }

    /// Starts the simulator on any plugin's interface with the given options and waits for its
    /// "ready" line. The drives wait 25 SYNC periods for a set-point (drivesWait) unless the
    /// options say otherwise.
    bool startOn(const QString &plugin, const QString &interface, const QStringList &options)
    {
        m_process.start(m_program, QStringList{QStringLiteral("--can-plugin"), plugin,
                                               QStringLiteral("--can-interface"), interface} +
                                       (options.contains(QStringLiteral("--setpoint-timeout"))
                                            ? QStringList{}
                                            : drivesWait()) +
                                       options);
        QElapsedTimer clock;
        clock.start();
        while (clock.elapsed() < 10000) {
            if (m_process.canReadLine() &&
                m_process.readLine().trimmed() == QByteArrayLiteral("ready"))
                return true;
            if (!m_process.waitForReadyRead(200) && m_process.state() == QProcess::NotRunning)
                return false;
        }
        return false;
    }

    /// How long the drives of the tests wait for a set-point: 25 SYNC periods (their default is
    /// 3, at least 50 ms). CI shares 2 cores with other tests, and in the VM of
    /// scripts/test-socketcan (emulated CPUs) the tool paused longer than 50 ms in sessions and in
    /// a fault test that had to complete its trial (EMCY 0x8100). The protocol does not change,
    /// only how long a drive waits; tests/cansim checks the default itself.
    static QStringList drivesWait()
    {
        return {QStringLiteral("--setpoint-timeout"), QStringLiteral("25")};
    }

    QString stderrText() { return QString::fromUtf8(m_process.readAllStandardError()); }

    /// Writes to the simulator's stdin (its commands, e.g. "mount\n" with --payload-off).
    void write(const QByteArray &data) { m_process.write(data); }
    /// Waits (at most ms) for a line on its stdout.
    bool waitForLine(const QByteArray &line, int ms)
    {
        QElapsedTimer clock;
        clock.start();
        while (clock.elapsed() < ms) {
            while (m_process.canReadLine()) {
                if (m_process.readLine().trimmed() == line)
                    return true;
            }
            m_process.waitForReadyRead(100);
        }
        return false;
    }

private:
    QString m_program;
    QProcess m_process;
};

} // namespace learnid::test
