#pragma once

#include <QObject>
#include <QSocketNotifier>
#include <memory>

namespace learnid::robotsim {

/// Turns SIGINT, SIGTERM and the end of stdin into a queued stopRequested() in the Qt event loop
/// (a signal handler only writes one byte to a socket pair, which is async-signal-safe), and
/// each line on stdin into lineReceived() (trimmed).
/// stdin is watched only when it is a pipe or a socket: a terminal or /dev/null never ends a run.
/// One instance per process.
class StopRequests : public QObject
{
    Q_OBJECT

public:
    explicit StopRequests(QObject *parent = nullptr);
    ~StopRequests() override;

signals:
    void stopRequested(const QString &reason);
    void lineReceived(const QString &line);

private:
    void readSignal();
    void readStdin();

    std::unique_ptr<QSocketNotifier> m_signalNotifier;
    std::unique_ptr<QSocketNotifier> m_stdinNotifier;
    QByteArray m_stdinBuffer; ///< the part of a line read so far
};

} // namespace learnid::robotsim
