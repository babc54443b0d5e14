#include "service/SessionWorker.h"

#include "io/AtomicFile.h"
#include "model/ChainModel.h"
#include "model/Error.h"
#include "model/ModelFactory.h"
#include "service/RobotFactory.h"
#include "service/ServiceLogging.h"
#include "service/TrialSummary.h"
#include "session/ConvergenceFigures.h"
#include "session/ScenarioRobot.h"

#include <QMutexLocker>

namespace learnid {

SessionWorker::SessionWorker(QObject *parent)
    : QObject(parent)
{}

SessionWorker::~SessionWorker() = default;

void SessionWorker::requestCancel()
{
    QMutexLocker lock(&m_sessionMutex);
    if (m_session)
        m_session->requestCancel();
}

void SessionWorker::clearCancel()
{
    QMutexLocker lock(&m_sessionMutex);
    if (m_session)
        m_session->clearCancel();
}

void SessionWorker::open(const Scenario &requested)
{
    close();
    Scenario scenario = requested;
    try {
        // The arm's session does not learn a payload: the payload step does (PayloadRunJob), or
        // `learnid-cli run`. Refused rather than ignored, so that nobody takes the arm's estimate
        // for one learned with the payload.
        if (scenario.payload.enabled)
            throw Error(tr("payload: the arm's session does not learn a payload; learn it in the "
                           "payload step (Robot > Learn a payload) or with learnid-cli run "
                           "--scenario FILE"));
        const auto model = makeRobotModel(scenario.model, scenario.urdf);
        if (!model)
            throw Error(tr("unknown robot model \"%1\"").arg(scenario.model));
        scenario = withRobotDefaults(scenario, *model);
        RobotConnection robot = makeRobot(m_request, scenario, model);
        if (!robot.robot) {
            qCWarning(lcService).noquote() << "connecting the robot failed:" << robot.connectError;
            emit openFailed(robot.connectError, true);
            return;
        }
        if (robot.simulated)
            robot.simulated->setFaults(m_faults);
        auto session = std::make_unique<CommissioningSession>(scenario, model, robot.robot);
        QMutexLocker lock(&m_sessionMutex);
        m_robot = robot.simulated;
        m_session = std::move(session);
    } catch (const Error &e) {
        qCWarning(lcService).noquote() << "opening the session failed:" << e.message();
        emit openFailed(e.message(), false);
        return;
    }
    connectSession();
    SessionInfo info;
    info.scenario = scenario;
    info.robotDescription = m_session->robot().description();
    info.modelId = m_session->model().id();
    info.parameters = m_session->model().parameters();
    info.dof = m_session->model().dof();
    info.jointNames = jointNames(m_session->model()); // the paper's arm: "Joint k" only
    info.truth = m_session->robot().trueParameters();
    info.storedParameters = m_session->robot().storedParameters();
    emit opened(info);
    emitCheck();
}

void SessionWorker::close()
{
    std::unique_ptr<CommissioningSession> old;
    {
        QMutexLocker lock(&m_sessionMutex);
        old = std::move(m_session);
        m_robot.reset();
    }
    if (old)
        emit closed();
}

void SessionWorker::connectSession()
{
    connect(m_session.get(), &CommissioningSession::trialStarted, this,
            [this](int index, int samples) {
                m_lastProgressPercent = -1;
                emit trialStarted(index, samples);
            });
    // The session reports every 100 samples; forward whole percents only, so the GUI's event
    // queue stays short however long the trial.
    connect(m_session.get(), &CommissioningSession::progress, this,
            [this](int index, int done, int total) {
                const int percent = total > 0 ? int(100LL * done / total) : 0;
                if (percent == m_lastProgressPercent)
                    return;
                m_lastProgressPercent = percent;
                emit progress(index, done, total);
            });
    connect(m_session.get(), &CommissioningSession::trialFinished, this,
            [this](const TrialResult &result) {
                // The samples stay here with the session; the GUI thread gets the figures and
                // the plot's curves, computed here, off the GUI thread.
                const QList<TrackingErrorCurve> curves = result.status() == TrialStatus::Refused
                                                             ? QList<TrackingErrorCurve>()
                                                             : trackingErrorCurves(result);
                emit trialFinished(trialSummary(result), curves, m_session->estimates(),
                                   newestEstimateFigures());
            });
}

void SessionWorker::setFaults(const SimulatedFaults &faults)
{
    m_faults = faults;
    if (m_robot)
        m_robot->setFaults(faults);
}

// On the newest trial's planned path (a refused trial has one too): how far each estimate's
// torques are from the truth's and from the newest estimate's.
EstimateFigures SessionWorker::newestEstimateFigures() const
{
    const QVector<TrialResult> &history = m_session->history();
    if (history.isEmpty())
        return {};
    return estimateFigures(m_session->model(), history.constLast().plan().desired,
                           m_session->estimates(), m_session->robot().trueParameters());
}

void SessionWorker::emitCheck()
{
    if (m_session)
        emit checked(m_session->checkNextTrial());
}

void SessionWorker::check()
{
    emitCheck();
}

void SessionWorker::runTrial()
{
    runTrials(1);
}

void SessionWorker::runTrials(int count, bool checkAfter)
{
    if (!m_session) {
        emit operationFailed(SessionOperation::Run, tr("no robot connected"));
        emit runFinished(false);
        return;
    }
    // The Stop flag was cleared when the run was requested (clearCancel): keep a Stop sent since.
    const bool all = m_session->runTrials(count, true);
    emit runFinished(all);
    if (checkAfter || !all)
        emitCheck();
}

void SessionWorker::accept(int estimateIndex, bool nearestConsistent)
{
    if (!m_session)
        return;
    const QString error = m_session->accept(estimateIndex, nearestConsistent);
    if (error.isEmpty())
        emit accepted(estimateIndex);
    else
        emit operationFailed(SessionOperation::Accept, error);
}

void SessionWorker::writeParameters(SessionOperation operation)
{
    // Always answers: the controller waits in Applying for applied() or operationFailed().
    if (!m_session)
        return emit operationFailed(operation, tr("no robot connected"));
    const QString error =
        operation == SessionOperation::Apply ? m_session->apply() : m_session->revert();
    if (error.isEmpty())
        emit applied(m_session->robot().storedParameters(), m_session->appliedEstimateIndex());
    else
        emit operationFailed(operation, error);
}

void SessionWorker::exportTrialCsv(const QString &folder)
{
    ExportRequest request;
    request.trialCsvDir = folder;
    QStringList written;
    const QString error = writeOutputs(request, &written);
    emit trialCsvExported(folder, int(written.size()), error);
}

void SessionWorker::exportParameterFile(const QString &jsonPath, int estimateIndex)
{
    ExportRequest request;
    request.parameterPath = jsonPath;
    request.estimateIndex = estimateIndex;
    QStringList written;
    const QString error = writeOutputs(request, &written);
    emit parameterFileExported(written, error);
}

void SessionWorker::exportOutputs(const ExportRequest &request)
{
    QStringList written;
    const QString error = writeOutputs(request, &written);
    emit exported(written, error);
}

QString SessionWorker::writeOutputs(const ExportRequest &request, QStringList *written)
{
    written->clear();
    if (!m_session)
        return tr("no session to export");
    try {
        *written = writeExport(*m_session, request);
    } catch (const Error &e) {
        return e.message();
    }
    return {};
}

} // namespace learnid
