#include "service/LogIdentification.h"

#include "io/AtomicFile.h"
#include "model/ModelCheck.h"
#include "model/ModelFactory.h"
#include "model/UrdfChain.h"
#include "session/EstimateConsistency.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <algorithm>

namespace learnid {

namespace {

/// Reports stages and checks the cancel flag between them.
class StageReporter
{
public:
    StageReporter(const LogIdentificationObserver &observer, const std::atomic<bool> *cancel,
                  int steps)
        : m_observer(observer)
        , m_cancel(cancel)
        , m_steps(steps)
    {}

    void begin(LogIdentificationStage stage, int index, int count, const QString &path)
    {
        checkCancel();
        if (m_observer)
            m_observer({stage, index, count, path, m_step, m_steps});
        ++m_step;
    }

    void checkCancel() const
    {
        if (m_cancel && m_cancel->load())
            throw LogIdentificationCancelled();
    }

private:
    const LogIdentificationObserver &m_observer;
    const std::atomic<bool> *m_cancel;
    int m_steps;
    int m_step = 0;
};

FilteredLog loadLog(const QString &path, const ChainModel &model,
                    const LogIdentificationRequest &request, std::vector<LogReading> &readings)
{
    QList<bool> angular; // revolute joints: a log in degrees is refused
    for (const ChainJoint &j : model.chain().joints)
        angular << (j.type == JointType::Revolute);
    const RobotLog log = readRobotLogFile(path, model.dof(), request.columns, angular);
    readings.push_back({path, log.samples(), log.repeatedSamples, log.staleSamples()});
    ResampleOptions resample = request.resample;
    resample.fitBandwidth = request.filter.rho; // the default gap allowed follows the filter
    return filterLog(resampleUniform(log, resample), request.filter);
}

LogValidation validate(const ChainModel &model, const LogFit &fit, const FilteredLog &log)
{
    LogValidation v;
    v.source = log.source;
    v.time.resize(log.keptSamples());
    for (Eigen::Index k = 0; k < v.time.size(); ++k)
        v.time[k] = log.keptTime(k);
    v.measured = measuredTorque(log);
    v.predictedGiven = predictedTorque(model, model.cadStandard(), log);
    v.predictedIdentified = predictedTorque(model, fit.standard, log);
    v.given = torqueFigures(v.measured, v.predictedGiven);
    v.identified = torqueFigures(v.measured, v.predictedIdentified);
    return v;
}

} // namespace

LogIdentificationCancelled::LogIdentificationCancelled()
    : Error(QCoreApplication::translate("LogIdentification",
                                        "identification cancelled; nothing was produced"))
{}

QStringList builtInUrdfRobots()
{
    QStringList ids;
    for (const QString &id : knownRobotModels())
        if (isUrdfModel(id) && id != QLatin1String("urdf"))
            ids << id;
    return ids;
}

LogRobot loadLogRobot(const LogIdentificationRequest &request)
{
    const QStringList builtIns = builtInUrdfRobots();
    const bool builtIn = builtIns.contains(request.robot);
    if (!builtIn && !QFileInfo(request.robot).isFile()) {
        throw Error(QCoreApplication::translate(
                        "LogIdentification",
                        "the robot '%1' is neither a URDF file nor a built-in robot (%2)")
                        .arg(request.robot, builtIns.join(QStringLiteral(", "))));
    }
    LogRobot r;
    r.modelId = builtIn ? request.robot : QStringLiteral("urdf");
    const QString path = builtIn ? urdfFileOf(request.robot, {}) : request.robot;
    r.source =
        builtIn ? QCoreApplication::translate("LogIdentification", "built-in %1").arg(request.robot)
                : QDir::toNativeSeparators(path);
    r.urdf = readFile(path);
    r.chain = parseUrdfChain(r.urdf, r.source, request.baseLink, request.tipLink,
                             QFileInfo(path).absolutePath());
    r.model = std::make_shared<const ChainModel>(r.chain, request.terms, r.modelId);
    r.warnings = modelWarnings(*r.model);
    return r;
}

namespace {

int stageCount(const LogIdentificationRequest &request)
{
    return int(request.trainingLogs.size()) + 2 * int(request.validationLogs.size()) + 1;
}

LogIdentificationResult run(const LogRobot &robot, const LogIdentificationRequest &request,
                            StageReporter &stages)
{
    if (request.trainingLogs.isEmpty()) {
        throw Error(QCoreApplication::translate("LogIdentification",
                                                "no log to identify from: add a training log"));
    }
    const ChainModel &model = *robot.model;
    const int training = int(request.trainingLogs.size());
    const int validation = int(request.validationLogs.size());
    LogIdentificationResult r;
    std::vector<FilteredLog> trainingLogs;
    for (int i = 0; i < training; ++i) {
        stages.begin(LogIdentificationStage::ReadTraining, i, training, request.trainingLogs[i]);
        trainingLogs.push_back(loadLog(request.trainingLogs[i], model, request, r.readings));
    }
    std::vector<FilteredLog> validationLogs;
    for (int i = 0; i < validation; ++i) {
        stages.begin(LogIdentificationStage::ReadValidation, i, validation,
                     request.validationLogs[i]);
        validationLogs.push_back(loadLog(request.validationLogs[i], model, request, r.readings));
    }
    stages.begin(LogIdentificationStage::Fit, 0, training, {});
    r.robot = robot;
    r.trainingLogs = request.trainingLogs;
    r.fit = fitLogs(model, trainingLogs, request.fit);
    trainingLogs.clear();
    r.verdict = checkStandardConsistency(model, r.fit.standard);
    r.consistency = r.verdict.describe(model);
    r.consistent = r.verdict.consistent;
    for (const int i : r.fit.undetermined())
        r.undetermined << model.parameters().at(i).name;
    for (int i = 0; i < validation; ++i) {
        stages.begin(LogIdentificationStage::Validate, i, validation, request.validationLogs[i]);
        r.validation.push_back(validate(model, r.fit, validationLogs[size_t(i)]));
    }
    stages.checkCancel(); // a cancel during the last stage: no result either
    return r;
}

} // namespace

LogIdentificationResult identifyFromLogs(const LogRobot &robot,
                                         const LogIdentificationRequest &request,
                                         const LogIdentificationObserver &observer,
                                         const std::atomic<bool> *cancel)
{
    StageReporter stages(observer, cancel, stageCount(request));
    return run(robot, request, stages);
}

LogIdentificationResult identifyFromLogs(const LogIdentificationRequest &request,
                                         const LogIdentificationObserver &observer,
                                         const std::atomic<bool> *cancel)
{
    StageReporter stages(observer, cancel, stageCount(request) + 1);
    stages.begin(LogIdentificationStage::Robot, 0, 1, request.robot);
    return run(loadLogRobot(request), request, stages);
}

} // namespace learnid
