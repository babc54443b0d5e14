#include "service/LogIdentificationJob.h"

#include "service/ServiceLogging.h"

#include <QMetaObject>
#include <exception>

namespace learnid {

LogIdentificationJob::LogIdentificationJob(QObject *parent)
    : QObject(parent)
    , m_context(new QObject)
{
    m_thread.setObjectName(QStringLiteral("learnid-identify"));
    m_context->moveToThread(&m_thread);
    connect(&m_thread, &QThread::finished, m_context, &QObject::deleteLater);
    m_thread.start();
}

LogIdentificationJob::~LogIdentificationJob()
{
    if (m_cancel)
        m_cancel->store(true);
    m_thread.quit();
    m_thread.wait();
}

bool LogIdentificationJob::start(const LogIdentificationRequest &request)
{
    if (m_running)
        return false;
    m_running = true;
    const int run = ++m_run;
    m_cancel = std::make_shared<std::atomic<bool>>(false);
    // Value copies only cross the threads: the request in, the progress and the result out.
    QMetaObject::invokeMethod(m_context, [this, request, run, cancel = m_cancel] {
        const auto report = [this, run](const LogIdentificationProgress &p) {
            QMetaObject::invokeMethod(
                this,
                [this, run, p] {
                    if (run == m_run && m_running)
                        emit progress(p);
                },
                Qt::QueuedConnection);
        };
        std::shared_ptr<const LogIdentificationResult> result;
        QString error;
        bool wasCancelled = false;
        try {
            result = std::make_shared<const LogIdentificationResult>(
                identifyFromLogs(request, report, cancel.get()));
        } catch (const LogIdentificationCancelled &) {
            wasCancelled = true;
        } catch (const Error &e) {
            error = e.message();
        } catch (const std::exception &e) { // e.g. bad_alloc on an enormous log
            error = QString::fromLocal8Bit(e.what());
        }
        QMetaObject::invokeMethod(
            this,
            [this, run, result, error, wasCancelled, cancel] {
                if (run != m_run)
                    return; // superseded
                m_running = false;
                // A cancel that came after the last stage still wins: the window asked for none.
                if (wasCancelled || cancel->load())
                    emit cancelled();
                else if (result)
                    emit succeeded(result);
                else
                    emit failed(error);
            },
            Qt::QueuedConnection);
    });
    return true;
}

void LogIdentificationJob::cancel()
{
    if (m_running && m_cancel) {
        qCInfo(lcService) << "identification cancel requested";
        m_cancel->store(true);
    }
}

} // namespace learnid
