#include "service/PayloadRunJob.h"

#include "model/Error.h"
#include "service/ServiceLogging.h"

#include <QMetaObject>
#include <exception>

namespace learnid {

PayloadRunJob::PayloadRunJob(QObject *parent)
    : QObject(parent)
    , m_context(new QObject)
{
    m_thread.setObjectName(QStringLiteral("learnid-payload"));
    m_context->moveToThread(&m_thread);
    connect(&m_thread, &QThread::finished, m_context, &QObject::deleteLater);
    m_thread.start();
}

PayloadRunJob::~PayloadRunJob()
{
    cancel();
    // The last run's robot ends in the thread it was made in (a CAN robot disconnects there).
    QMetaObject::invokeMethod(
        m_context, [this] { m_last.reset(); }, Qt::BlockingQueuedConnection);
    m_thread.quit();
    m_thread.wait();
}

bool PayloadRunJob::check(const Scenario &scenario)
{
    if (m_running)
        return false;
    const int id = ++m_check;
    QMetaObject::invokeMethod(m_context, [this, scenario, id] { checkInThread(scenario, id); });
    return true;
}

void PayloadRunJob::checkInThread(const Scenario &scenario, int id)
{
    if (id != m_check.load())
        return; // a newer check is queued behind this one
    std::optional<PayloadPreview> preview;
    QString error;
    try {
        PayloadRunSession run = makeSimulatedPayloadSession(scenario);
        preview = payloadPreview(*run.session);
    } catch (const Error &e) {
        error = e.message();
    } catch (const std::exception &e) {
        error = QString::fromLocal8Bit(e.what());
    }
    QMetaObject::invokeMethod(
        this,
        [this, id, preview, error] {
            if (id != m_check.load())
                return;
            if (preview)
                emit checked(*preview);
            else
                emit checkFailed(error);
        },
        Qt::QueuedConnection);
}

bool PayloadRunJob::start(const Scenario &scenario, const RobotRequest &robot)
{
    if (m_running)
        return false;
    m_running = true;
    m_lastResult.reset();
    // A check still queued runs before the run in the job's thread and is about this run's
    // scenario (the form cannot change without a new check): its preview stays.
    const int run = ++m_run;
    m_cancel = std::make_shared<std::atomic<bool>>(false);
    QMetaObject::invokeMethod(m_context, [this, scenario, robot, run, cancel = m_cancel] {
        runInThread(scenario, robot, run, cancel);
    });
    return true;
}

bool PayloadRunJob::applyResult()
{
    if (m_running || !m_lastResult)
        return false;
    m_running = true;
    QMetaObject::invokeMethod(m_context, [this, result = m_lastResult] {
        QString error;
        try {
            error = m_last ? applyRunPayload(*m_last, *result)
                           : tr("the run's robot is no longer connected: run again");
        } catch (const Error &e) {
            error = e.message();
        }
        QMetaObject::invokeMethod(
            this,
            [this, error] {
                m_running = false;
                emit applied(error);
            },
            Qt::QueuedConnection);
    });
    return true;
}

void PayloadRunJob::runInThread(const Scenario &scenario, const RobotRequest &robot, int run,
                                std::shared_ptr<std::atomic<bool>> cancel)
{
    // The previous run's robot first: one master on a bus.
    m_last.reset();
    // Value copies only cross the threads: the scenario in, the rows and the result out.
    const auto post = [this, run](auto emitter) {
        QMetaObject::invokeMethod(
            this,
            [this, run, emitter] {
                if (run == m_run && m_running)
                    emitter();
            },
            Qt::QueuedConnection);
    };
    std::shared_ptr<PayloadRunSession> made;
    std::shared_ptr<const PayloadRunResult> result;
    QString error;
    try {
        {
            QMutexLocker lock(&m_mountMutex);
            m_mountConfirmed = false;
        }
        made = std::make_shared<PayloadRunSession>(robot.kind == RobotRequest::Kind::Can
                                                       ? makeCanPayloadSession(scenario, robot)
                                                       : makeSimulatedPayloadSession(scenario));
        if (!made->session)
            throw Error(made->connectError);
        PayloadRunSession &s = *made;
        // cancel() reaches the session while it lives, however this block is left.
        struct Registration
        {
            PayloadRunJob *job;
            Registration(PayloadRunJob *j, PayloadSession *session)
                : job(j)
            {
                QMutexLocker lock(&job->m_sessionMutex);
                job->m_session = session;
            }
            ~Registration()
            {
                QMutexLocker lock(&job->m_sessionMutex);
                job->m_session = nullptr;
            }
        } registration(this, s.session.get());
        const int baselines = s.session->scenario().payload.baselineTrials;
        const int total = baselines + scenario.iterations;
        const QString link = s.session->payloadModel().link();
        for (int i = 0; i < total && !cancel->load(); ++i) {
            // The CAN robot carries the payload itself: the technician changes it.
            const PayloadMounting mounting = payloadMountingBefore(i, baselines);
            if (robot.kind == RobotRequest::Kind::Can && mounting != PayloadMounting::Unchanged) {
                const bool mount = mounting == PayloadMounting::Mount;
                post([this, mount, link, baselines] {
                    emit mountingRequested(mount, link, baselines);
                });
                if (!waitForMounting(*cancel))
                    break;
            }
            const bool baseline = s.session->nextTrialIsBaseline();
            post([this, i, total, baseline] { emit trialStarted(i, total, baseline); });
            const PayloadTrial &t = s.session->runTrial();
            const PayloadTrialRow row = payloadTrialRow(t);
            post([this, row] { emit trialFinished(row); });
            if (!t.usable()) {
                error = t.message;
                break;
            }
        }
        if (error.isEmpty() && !cancel->load()) {
            result = std::make_shared<const PayloadRunResult>(payloadRunResult(s));
            m_last = made;
        }
    } catch (const Error &e) {
        error = e.message();
    } catch (const std::exception &e) {
        error = QString::fromLocal8Bit(e.what());
    }
    // Nothing lost: a run that ended early keeps the record of the trials it ran.
    std::shared_ptr<const PayloadRunRecord> record;
    if (!result && made && made->session && !made->session->history().empty()) {
        const QString why = cancel->load() ? tr("stopped (Stop) by the technician") : error;
        try {
            record =
                std::make_shared<const PayloadRunRecord>(payloadRunRecord(*made->session, why));
        } catch (const std::exception &e) {
            qCWarning(lcService) << "payload run: the record of the ended run failed:" << e.what();
        }
    }
    QMetaObject::invokeMethod(
        this,
        [this, run, result, record, error, cancel] {
            if (run != m_run)
                return;
            m_running = false;
            if (record)
                emit endedEarlyRecord(record);
            // A cancel that came after the last trial still wins: the window asked for no result.
            if (cancel->load())
                emit cancelled();
            else if (result) {
                m_lastResult = result;
                emit succeeded(result);
            } else
                emit failed(error);
        },
        Qt::QueuedConnection);
}

bool PayloadRunJob::waitForMounting(const std::atomic<bool> &cancel)
{
    QMutexLocker lock(&m_mountMutex);
    while (!m_mountConfirmed && !cancel.load())
        m_mountWake.wait(&m_mountMutex, 200); // cancel() wakes it; the timeout is a safety net
    const bool confirmed = m_mountConfirmed && !cancel.load();
    m_mountConfirmed = false;
    return confirmed;
}

void PayloadRunJob::confirmMounting()
{
    if (!m_running)
        return;
    qCInfo(lcService) << "payload mounting confirmed";
    QMutexLocker lock(&m_mountMutex);
    m_mountConfirmed = true;
    m_mountWake.wakeAll();
}

void PayloadRunJob::cancel()
{
    if (!m_running || !m_cancel)
        return;
    qCInfo(lcService) << "payload run cancel requested";
    m_cancel->store(true);
    {
        QMutexLocker lock(&m_mountMutex);
        m_mountWake.wakeAll();
    }
    QMutexLocker lock(&m_sessionMutex);
    if (m_session)
        m_session->requestCancel();
}

} // namespace learnid
