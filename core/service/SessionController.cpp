#include "service/SessionController.h"

#include "service/ServiceLogging.h"
#include "service/SessionWorker.h"

#include <QCoreApplication>
#include <QEvent>

namespace learnid {

namespace {

/// Posted when a trial of a series has finished: handled after the events the window's update
/// posted (layout, and paint at Qt::LowEventPriority), since posted events are handled in order
/// of priority and this one's is lower.
class NextTrialEvent : public QEvent
{
public:
    explicit NextTrialEvent(int series)
        : QEvent(type())
        , series(series)
    {}
    static QEvent::Type type()
    {
        static const auto t = QEvent::Type(QEvent::registerEventType());
        return t;
    }
    const int series;
};

constexpr int kAfterTheWindowsUpdate = int(Qt::LowEventPriority) - 1;

} // namespace

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
        m_figures = {};
        m_check.reset();
        m_accepted.reset();
        m_stored = info.storedParameters;
        m_appliedCount = 0;
        m_appliedIndex = -1;
        m_state = SessionState::Idle;
        emit opened();
        emit historyChanged();
        emit stateChanged();
    });
    connect(m_worker, &SessionWorker::openFailed, this, [this](const QString &message) {
        m_info.reset();
        m_state = SessionState::NotConnected;
        emit openFailed(message);
        emit stateChanged();
    });
    connect(m_worker, &SessionWorker::closed, this, [this] {
        m_info.reset();
        m_check.reset();
        // A new open() may be on its way already (closed comes first from the worker's open).
        if (m_state != SessionState::Connecting)
            m_state = SessionState::NotConnected;
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
                   const QVector<Eigen::VectorXd> &estimates, const EstimateFigures &figures) {
                m_history.append(summary);
                m_estimates = estimates;
                m_figures = figures;
                emit trialFinished(summary, curves);
                emit historyChanged();
            });
    connect(m_worker, &SessionWorker::runFinished, this, [this](bool all) {
        --m_seriesLeft;
        if (all && m_seriesLeft > 0 && m_state == SessionState::RunningTrial) {
            m_waitingForWindow = true;
            QCoreApplication::postEvent(this, new NextTrialEvent(m_series), kAfterTheWindowsUpdate);
            return;
        }
        // Stopped between two trials (all, trials left): the worker checked nothing.
        endSeries(all && m_seriesLeft <= 0, all && m_seriesLeft > 0);
    });
    connect(m_worker, &SessionWorker::accepted, this, [this](int k) {
        m_accepted = k;
        emit acceptedChanged(k);
        emit historyChanged();
        emit stateChanged();
    });
    connect(m_worker, &SessionWorker::applied, this,
            [this](const Eigen::VectorXd &stored, int estimateIndex) {
                m_stored = stored;
                m_appliedIndex = estimateIndex;
                ++m_appliedCount;
                setState(SessionState::Idle);
                emit applied(stored);
                emit historyChanged();
            });
    connect(m_worker, &SessionWorker::operationFailed, this,
            [this](SessionOperation operation, const QString &message) {
                // A failed apply or revert ends the Applying state; a failed run ends with
                // runFinished; a refused accept changes nothing.
                if (m_state == SessionState::Applying &&
                    (operation == SessionOperation::Apply || operation == SessionOperation::Revert))
                    setState(SessionState::Idle);
                emit operationFailed(operation, message);
            });
    connect(m_worker, &SessionWorker::parameterFileExported, this,
            &SessionController::parameterFileExported);
    connect(m_worker, &SessionWorker::exported, this, &SessionController::urdfExported);
    connect(m_worker, &SessionWorker::trialCsvExported, this, &SessionController::trialCsvExported);
    m_thread.start();
}

SessionController::~SessionController()
{
    m_worker->requestCancel();
    m_thread.quit();
    m_thread.wait();
}

template <typename F> void SessionController::post(F &&call)
{
    QMetaObject::invokeMethod(m_worker, std::forward<F>(call), Qt::QueuedConnection);
}

SessionFacts SessionController::facts() const
{
    SessionFacts f;
    f.checkPassed = m_check && m_check->passed();
    f.learned = m_estimates.size() > 1;
    f.ranTrial = !m_history.isEmpty();
    f.accepted = m_accepted.has_value();
    f.applied = m_appliedCount > 0;
    return f;
}

bool SessionController::event(QEvent *event)
{
    if (event->type() != NextTrialEvent::type())
        return QObject::event(event);
    if (!m_waitingForWindow || static_cast<NextTrialEvent *>(event)->series != m_series)
        return true; // the series ended meanwhile (Stop)
    m_waitingForWindow = false;
    postTrial();
    return true;
}

void SessionController::postTrial()
{
    const bool last = m_seriesLeft == 1;
    SessionWorker *w = m_worker;
    post([w, last] { w->runTrials(1, last); });
}

void SessionController::endSeries(bool allCompleted, bool checkNext)
{
    if (checkNext)
        post([w = m_worker] { w->check(); });
    m_seriesLeft = 0;
    setState(SessionState::Idle);
    emit runFinished(allCompleted);
}

void SessionController::setState(SessionState state)
{
    if (m_state == state)
        return;
    m_state = state;
    emit stateChanged();
}

void SessionController::open(const Scenario &scenario)
{
    if (isConnected(m_state) && m_state != SessionState::Idle)
        return; // something runs; the worker opens nothing in between
    setState(SessionState::Connecting);
    SessionWorker *w = m_worker;
    post([w, scenario] { w->open(scenario); });
}

void SessionController::setRobotRequest(const RobotRequest &request)
{
    SessionWorker *w = m_worker;
    post([w, request] { w->setRobotRequest(request); });
}

void SessionController::close()
{
    if (m_state == SessionState::RunningTrial)
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
    if (m_state != SessionState::Idle || count < 1)
        return;
    qCInfo(lcService) << "running" << count << "trial(s)";
    setState(SessionState::RunningTrial);
    m_worker->clearCancel();
    ++m_series;
    m_seriesLeft = count;
    postTrial();
}

void SessionController::stop()
{
    qCInfo(lcService) << "stop requested";
    m_worker->requestCancel();
    if (m_state == SessionState::RunningTrial)
        setState(SessionState::Stopping);
    if (m_waitingForWindow) { // between two trials of a series: nothing runs to stop
        m_waitingForWindow = false;
        endSeries(false, true);
    }
}

void SessionController::accept(int estimateIndex)
{
    SessionWorker *w = m_worker;
    post([w, estimateIndex] { w->accept(estimateIndex); });
}

void SessionController::apply()
{
    writeParameters(SessionOperation::Apply);
}

void SessionController::revert()
{
    writeParameters(SessionOperation::Revert);
}

void SessionController::writeParameters(SessionOperation operation)
{
    if (m_state != SessionState::Idle)
        return;
    setState(SessionState::Applying);
    SessionWorker *w = m_worker;
    post([w, operation] { w->writeParameters(operation); });
}

void SessionController::exportTrialCsv(const QString &folder)
{
    SessionWorker *w = m_worker;
    post([w, folder] { w->exportTrialCsv(folder); });
}

void SessionController::exportIdentifiedUrdf(const QString &path, int estimateIndex,
                                             const QString &comment)
{
    ExportRequest request;
    request.urdfPath = path;
    request.estimateIndex = estimateIndex;
    request.urdfComment = comment;
    SessionWorker *w = m_worker;
    post([w, request] { w->exportOutputs(request); });
}

void SessionController::exportParameterFile(const QString &jsonPath, int estimateIndex)
{
    SessionWorker *w = m_worker;
    post([w, jsonPath, estimateIndex] { w->exportParameterFile(jsonPath, estimateIndex); });
}

} // namespace learnid
