#pragma once
// Test support: one of the project's executables run to its end, as a user starts it.

#include <QElapsedTimer>
#include <QProcess>
#include <QStringList>

namespace learnid::test {

/// How a tool run ended: exit code (-1 when it crashed or did not finish in time), its
/// standard output and error, and the wall time it took [ms].
struct ToolRun
{
    int exitCode = -1;
    QString out;
    QString err;
    qint64 ms = 0;
};

/// Runs program with args in workingDir (empty: the test's) with the given environment (empty:
/// the test's); a run that does not finish within timeoutMs is killed.
inline ToolRun runTool(const QString &program, const QStringList &args,
                       const QString &workingDir = {}, int timeoutMs = 120000,
                       const QProcessEnvironment &env = {})
{
    QProcess p;
    if (!workingDir.isEmpty())
        p.setWorkingDirectory(workingDir);
    if (!env.isEmpty())
        p.setProcessEnvironment(env);
    QElapsedTimer clock;
    clock.start();
    p.start(program, args);
    if (!p.waitForFinished(timeoutMs)) {
        p.kill();
        p.waitForFinished(5000);
        return {};
    }
    return {p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1,
            QString::fromUtf8(p.readAllStandardOutput()),
            QString::fromUtf8(p.readAllStandardError()), clock.elapsed()};
}

} // namespace learnid::test
