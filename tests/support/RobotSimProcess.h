#pragma once
// Test support for end-to-end tests over virtualcan: a loopback port nobody listens on, and
// learnid-robot-sim as a second process that is stopped when the test ends.

#include <QElapsedTimer>
#include <QHostAddress>
#include <QProcess>
#include <QStringList>
#include <QTcpServer>

namespace learnid::test {

/// A loopback TCP port free right now (0 when none could be had). virtualcan's server is then
/// hosted by the first process that opens tcp://127.0.0.1:PORT/can0.
inline quint16 freeLoopbackPort()
{
    QTcpServer probe;
    return probe.listen(QHostAddress::LocalHost, 0) ? probe.serverPort() : 0;
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
    /// most) for its "ready" line. The drives wait 25 SYNC periods for a set-point: CI shares
    /// 2 cores with other tests; the protocol does not change, only how long a drive waits.
    bool start(const QString &interface, const QStringList &options = {})
    {
        return startOn(QStringLiteral("virtualcan"), interface,
                       QStringList{QStringLiteral("--setpoint-timeout"), QStringLiteral("25")} +
                           options);
    }

    /// Starts the simulator on any plugin's interface with the given options (its own default
    /// set-point timeout unless they say otherwise) and waits for its "ready" line.
    bool startOn(const QString &plugin, const QString &interface, const QStringList &options)
    {
        m_process.start(m_program, QStringList{QStringLiteral("--can-plugin"), plugin,
                                               QStringLiteral("--can-interface"), interface} +
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
