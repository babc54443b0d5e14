#include "ui/SessionController.h"

#include "ui/SessionWorker.h"
#include "ui/UiLogging.h"

namespace learnid {

SessionController::SessionController(QObject *parent)
    : QObject(parent)
    , m_worker(new SessionWorker)
{
    registerSessionMetaTypes();
    m_thread.setObjectName(QStringLiteral("learnid-session"));
    m_worker->moveToThread(&m_thread);
    connect(&m_thread, &QThread::finished, m_worker, &QObject::deleteLater);

    connect(m_worker, &SessionWorker::opened, this, [this](const SessionInfo &info) {
        m_info = info;
        m_history.clear();
        m_estimates = {info.scenario.initialParameters};
        m_check.reset();
        m_accepted.reset();
        m_stored = info.storedParameters;
        m_appliedCount = 0;
        emit opened();
        emit historyChanged();
        emit stateChanged();
    });
    connect(m_worker, &SessionWorker::openFailed, this, [this](const QString &message) {
        m_info.reset();
        emit openFailed(message);
        emit stateChanged();
    });
    connect(m_worker, &SessionWorker::closed, this, [this] {
        m_info.reset();
        m_check.reset();
        emit closed();
        emit stateChanged();
    });
    connect(m_worker, &SessionWorker::checked, this, [this](const PreTrialCheck &check) {
        m_check = check;
        emit checkChanged();
        emit stateChanged();
    });
    connect(m_worker, &SessionWorker::trialStarted, this, &SessionController::trialStarted);
    connect(m_worker, &SessionWorker::progress, this, &SessionController::progress);
    connect(m_worker, &SessionWorker::trialFinished, this,
            [this](const TrialResult &summary, const QList<TrackingErrorCurve> &curves,
                   const QVector<Eigen::VectorXd> &estimates) {
                m_history.append(summary);
                m_estimates = estimates;
                emit trialFinished(summary, curves);
                emit historyChanged();
            });
    connect(m_worker, &SessionWorker::runFinished, this, [this](bool all) {
        setBusy(false);
        emit runFinished(all);
    });
    connect(m_worker, &SessionWorker::accepted, this, [this](int k) {
        m_accepted = k;
        emit acceptedChanged(k);
        emit historyChanged();
        emit stateChanged();
    });
    connect(m_worker, &SessionWorker::applied, this, [this](const Eigen::VectorXd &stored) {
        m_stored = stored;
        ++m_appliedCount;
        setBusy(false);
        emit applied(stored);
        emit historyChanged();
    });
    connect(m_worker, &SessionWorker::operationFailed, this,
            [this](const QString &operation, const QString &message) {
                if (operation != QLatin1String("accept"))
                    setBusy(false);
                emit operationFailed(operation, message);
            });
    connect(m_worker, &SessionWorker::parameterFileExported, this,
            &SessionController::parameterFileExported);
    connect(m_worker, &SessionWorker::trialCsvExported, this, &SessionController::trialCsvExported);
    m_thread.start();
}

SessionController::~SessionController()
{
    m_worker->requestCancel();
    m_thread.quit();
    m_thread.wait();
}

template <typename F>
void SessionController::post(F &&call)
{
    QMetaObject::invokeMethod(m_worker, std::forward<F>(call), Qt::QueuedConnection);
}

int SessionController::storedEstimateIndex() const
{
    if (m_stored.size() == 0)
        return -1;
    for (int k = int(m_estimates.size()) - 1; k >= 0; --k)
        if (m_estimates.at(k).size() == m_stored.size() && m_estimates.at(k) == m_stored)
            return k;
    return -1;
}

bool SessionController::canRun() const
{
    return isOpen() && !m_busy && m_check && m_check->passed();
}

void SessionController::setBusy(bool busy)
{
    if (m_busy == busy)
        return;
    m_busy = busy;
    emit stateChanged();
}

void SessionController::open(const Scenario &scenario)
{
    if (m_busy)
        return;
    SessionWorker *w = m_worker;
    post([w, scenario] { w->open(scenario); });
}

void SessionController::setRobotChoice(const RobotChoice &choice)
{
    SessionWorker *w = m_worker;
    post([w, choice] { w->setRobotChoice(choice); });
}

void SessionController::close()
{
    if (m_busy)
        stop();
    SessionWorker *w = m_worker;
    post([w] { w->close(); });
}

void SessionController::setSimulatedFaults(const SimulatedFaults &faults)
{
    SessionWorker *w = m_worker;
    post([w, faults] { w->setFaults(faults); });
}

void SessionController::runTrial()
{
    runTrials(1);
}

void SessionController::runTrials(int count)
{
    if (!isOpen() || m_busy || count < 1)
        return;
    qCInfo(lcUi) << "running" << count << "trial(s)";
    setBusy(true);
    SessionWorker *w = m_worker;
    post([w, count] { w->runTrials(count); });
}

void SessionController::stop()
{
    qCInfo(lcUi) << "stop requested";
    m_worker->requestCancel();
}

void SessionController::accept(int estimateIndex)
{
    SessionWorker *w = m_worker;
    post([w, estimateIndex] { w->accept(estimateIndex); });
}

void SessionController::apply()
{
    if (m_busy)
        return;
    setBusy(true);
    SessionWorker *w = m_worker;
    post([w] { w->apply(); });
}

void SessionController::revert()
{
    if (m_busy)
        return;
    setBusy(true);
    SessionWorker *w = m_worker;
    post([w] { w->revert(); });
}

void SessionController::exportTrialCsv(const QString &folder)
{
    SessionWorker *w = m_worker;
    post([w, folder] { w->exportTrialCsv(folder); });
}

void SessionController::exportParameterFile(const QString &jsonPath, int estimateIndex)
{
    SessionWorker *w = m_worker;
    post([w, jsonPath, estimateIndex] { w->exportParameterFile(jsonPath, estimateIndex); });
}

} // namespace learnid
