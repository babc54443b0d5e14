#include "ui/SessionWorker.h"

#include "session/ScenarioRobot.h"

#include "canrobot/CanRobot.h"

#include "io/AtomicFile.h"
#include "io/ParameterFile.h"
#include "io/SessionReport.h"
#include "io/TrialCsv.h"
#include "model/Error.h"
#include "model/ModelFactory.h"
#include "ui/TrialSummary.h"
#include "ui/UiLogging.h"

#include <QDir>
#include <QFileInfo>
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

void SessionWorker::open(const Scenario &scenario)
{
    close();
    try {
        const auto model = makeRobotModel(scenario.model);
        if (!model)
            throw Error(tr("unknown robot model \"%1\"").arg(scenario.model));
        std::shared_ptr<SimulatedRobot> simulated;
        std::shared_ptr<Robot> robot;
        if (m_choice.can) {
            auto can = std::make_shared<CanRobot>(model, m_choice.canOptions);
            const QString error = can->connectBus();
            if (!error.isEmpty())
                throw Error(error);
            robot = can;
        } else {
            simulated = makeSimulatedRobot(scenario, model);
            simulated->setFaults(m_faults);
            robot = simulated;
        }
        auto session = std::make_unique<CommissioningSession>(scenario, model, robot);
        QMutexLocker lock(&m_sessionMutex);
        m_robot = simulated;
        m_session = std::move(session);
    } catch (const Error &e) {
        qCWarning(lcUi).noquote() << "opening the session failed:" << e.message();
        emit openFailed(e.message());
        return;
    }
    connectSession();
    SessionInfo info;
    info.scenario = scenario;
    info.robotDescription = m_session->robot().description();
    info.modelId = m_session->model().id();
    info.parameters = m_session->model().parameters();
    info.dof = m_session->model().dof();
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
                const QList<TrackingErrorCurve> curves =
                    result.status() == TrialStatus::Refused ? QList<TrackingErrorCurve>()
                                                            : trackingErrorCurves(result);
                emit trialFinished(trialSummary(result), curves, m_session->estimates());
            });
}

void SessionWorker::setFaults(const SimulatedFaults &faults)
{
    m_faults = faults;
    if (m_robot)
        m_robot->setFaults(faults);
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

void SessionWorker::runTrials(int count)
{
    if (!m_session) {
        emit operationFailed(QStringLiteral("run"), tr("no robot connected"));
        emit runFinished(false);
        return;
    }
    bool all = true;
    if (count == 1) {
        const TrialResult &t = m_session->runTrial();
        all = t.learned();
    } else {
        all = m_session->runTrials(count);
    }
    emit runFinished(all);
    emitCheck();
}

void SessionWorker::accept(int estimateIndex)
{
    if (!m_session)
        return;
    const QString error = m_session->accept(estimateIndex);
    if (error.isEmpty())
        emit accepted(estimateIndex);
    else
        emit operationFailed(QStringLiteral("accept"), error);
}

void SessionWorker::apply()
{
    if (!m_session)
        return;
    const QString error = m_session->apply();
    if (error.isEmpty())
        emit applied(m_session->robot().storedParameters());
    else
        emit operationFailed(QStringLiteral("apply"), error);
}

void SessionWorker::revert()
{
    if (!m_session)
        return;
    const QString error = m_session->revert();
    if (error.isEmpty())
        emit applied(m_session->robot().storedParameters());
    else
        emit operationFailed(QStringLiteral("revert"), error);
}

void SessionWorker::exportTrialCsv(const QString &folder)
{
    if (!m_session) {
        emit trialCsvExported(folder, 0, tr("no session to export"));
        return;
    }
    try {
        if (!QDir().mkpath(folder))
            throw Error(tr("cannot create the folder %1").arg(QDir::toNativeSeparators(folder)));
        const QList<QPair<QString, QByteArray>> files = trialCsvFiles(m_session->history(), folder);
        writeFilesAtomically(files);
        emit trialCsvExported(folder, int(files.size()), {});
    } catch (const Error &e) {
        emit trialCsvExported(folder, 0, e.message());
    }
}

void SessionWorker::exportParameterFile(const QString &jsonPath, int estimateIndex)
{
    if (!m_session) {
        emit parameterFileExported({}, tr("no session to export"));
        return;
    }
    const QFileInfo info(jsonPath);
    const QString dcfPath = info.dir().filePath(info.completeBaseName() + QStringLiteral(".dcf"));
    try {
        const ParameterFileContent content = parameterFileContent(*m_session, estimateIndex);
        writeFilesAtomically({{jsonPath, parameterFileToJson(content)},
                              {dcfPath, parameterDcfFragment(content)}});
    } catch (const Error &e) {
        emit parameterFileExported({}, e.message());
        return;
    }
    emit parameterFileExported({jsonPath, dcfPath}, {});
}

} // namespace learnid
