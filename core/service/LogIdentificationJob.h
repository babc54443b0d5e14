#pragma once

#include "service/LogIdentification.h"

#include <QObject>
#include <QThread>
#include <memory>

namespace learnid {

/// Runs identifyFromLogs() for the window in a thread of its own, so that the window stays
/// responsive: start() hands a request to the thread; progress(), then one of succeeded(),
/// failed() or cancelled() come back queued, in the thread the job lives in. One run at a time;
/// cancel() is answered at the next stage (LogIdentification.h). What a run that was cancelled
/// or superseded produces is dropped, so nothing of it reaches the window.
class LogIdentificationJob : public QObject
{
    Q_OBJECT

public:
    explicit LogIdentificationJob(QObject *parent = nullptr);
    /// Cancels a run and waits for it to end (at its next stage).
    ~LogIdentificationJob() override;

    bool isRunning() const { return m_running; }

public slots:
    /// Starts a run; ignored (returns false) while one runs.
    bool start(const learnid::LogIdentificationRequest &request);
    /// Asks the running run to stop at its next stage; cancelled() follows.
    void cancel();

signals:
    void progress(const learnid::LogIdentificationProgress &progress);
    void succeeded(std::shared_ptr<const learnid::LogIdentificationResult> result);
    /// message: the core's, naming file, line and column where it has them.
    void failed(const QString &message);
    void cancelled();

private:
    QThread m_thread;
    QObject *m_context; ///< lives in m_thread: the queued calls run there
    std::shared_ptr<std::atomic<bool>> m_cancel;
    int m_run = 0;
    bool m_running = false;
};

} // namespace learnid
