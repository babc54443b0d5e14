#include "canrobot/CanRobot.h"

#include "canrobot/CanRobotWorker.h"

#include <QCoreApplication>
#include <future>

namespace learnid {

CanRobot::CanRobot(std::shared_ptr<const RobotModel> model, CanRobotOptions options,
                   CanDeviceFactory factory)
    : m_options(std::move(options))
{
    if (!factory)
        factory = qcanbusDeviceFactory(m_options.plugin, m_options.interface);
    m_thread.setObjectName(QStringLiteral("learnid CAN"));
    m_worker = new CanRobotWorker(std::move(model), m_options, std::move(factory));
    m_worker->moveToThread(&m_thread);
    m_thread.start(QThread::TimeCriticalPriority);
}

CanRobot::~CanRobot()
{
    CanRobotWorker *worker = m_worker;
    // Deleted in its own thread: the thread processes deferred deletes when it finishes.
    QMetaObject::invokeMethod(
        worker,
        [worker] {
            worker->shutdown();
            worker->deleteLater();
        },
        Qt::BlockingQueuedConnection);
    m_thread.quit();
    m_thread.wait();
}

template <typename F> void CanRobot::runInCanThread(F &&f) const
{
    Q_ASSERT(QThread::currentThread() != &m_thread);
    QMetaObject::invokeMethod(m_worker, std::forward<F>(f), Qt::QueuedConnection);
}

QString CanRobot::connectBus()
{
    auto promise = std::make_shared<std::promise<QString>>();
    CanRobotWorker *worker = m_worker;
    runInCanThread([worker, promise] {
        worker->connectBus([promise](const QString &error) { promise->set_value(error); });
    });
    return promise->get_future().get();
}

QString CanRobot::description() const
{
    QStringList nodes;
    for (const int n : m_options.nodes)
        nodes << QString::number(n);
    return QCoreApplication::translate("CanRobot", "CAN %1/%2, nodes %3")
        .arg(m_options.plugin, m_options.interface, nodes.join(QLatin1Char(',')));
}

TrialRecord CanRobot::runTrial(const TrialPlan &plan, const TrialMonitor &monitor)
{
    auto promise = std::make_shared<std::promise<TrialRecord>>();
    CanRobotWorker *worker = m_worker;
    // plan and monitor outlive the call: this thread waits until the worker has finished.
    const TrialPlan *p = &plan;
    const TrialMonitor *m = &monitor;
    runInCanThread([worker, promise, p, m] {
        worker->runTrial(*p, *m, [promise](const TrialRecord &r) { promise->set_value(r); });
    });
    return promise->get_future().get();
}

QString CanRobot::applyParameters(const Eigen::VectorXd &phi)
{
    auto promise = std::make_shared<std::promise<QString>>();
    CanRobotWorker *worker = m_worker;
    runInCanThread([worker, promise, phi] {
        worker->apply(phi, [promise](const QString &error) { promise->set_value(error); });
    });
    const QString error = promise->get_future().get();
    if (error.isEmpty())
        m_stored = phi;
    return error;
}

QString CanRobot::applyPayload(int joint, const Eigen::VectorXd &body)
{
    auto promise = std::make_shared<std::promise<QString>>();
    CanRobotWorker *worker = m_worker;
    runInCanThread([worker, promise, joint, body] {
        worker->applyPayload(joint, body,
                             [promise](const QString &error) { promise->set_value(error); });
    });
    return promise->get_future().get();
}

QList<DriveIdentity> CanRobot::driveIdentities() const
{
    QList<DriveIdentity> drives;
    CanRobotWorker *worker = m_worker;
    QMetaObject::invokeMethod(
        worker, [worker, &drives] { drives = worker->driveIdentities(); },
        Qt::BlockingQueuedConnection);
    return drives;
}

TrialStreamStatistics CanRobot::lastTrialStatistics() const
{
    TrialStreamStatistics stats;
    CanRobotWorker *worker = m_worker;
    QMetaObject::invokeMethod(
        worker, [worker, &stats] { stats = worker->lastStatistics(); },
        Qt::BlockingQueuedConnection);
    return stats;
}

} // namespace learnid
