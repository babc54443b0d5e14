#include "service/PayloadIdentification.h"

#include "io/RobotLogCsv.h"

#include <QCoreApplication>

namespace learnid {

namespace {

FilteredLog readLog(const QString &path, const ChainModel &model,
                    const LogIdentificationRequest &request, std::vector<LogReading> &readings)
{
    QList<bool> angular; // revolute joints: a log in degrees is refused
    for (const ChainJoint &j : model.chain().joints)
        angular << (j.type == JointType::Revolute);
    const RobotLog log = readRobotLogFile(path, model.dof(), request.columns, angular);
    readings.push_back({path, log.samples(), log.repeatedSamples, log.staleSamples()});
    ResampleOptions resample = request.resample;
    resample.fitBandwidth = request.filter.rho;
    return filterLog(resampleUniform(log, resample), request.filter);
}

} // namespace

BaselineSettings recordedBaselineSettings()
{
    BaselineSettings s;
    s.maxShift = 2.0;
    s.maxAngleRmsDeg = 2.0;
    s.minOverlap = 0.8;
    return s;
}

PayloadIdentificationResult identifyPayloadFromLogs(const PayloadIdentificationRequest &request,
                                                    const PayloadFieldNames &names)
{
    validatePayloadPrior(request.prior, names);
    if (request.logs.trainingLogs.isEmpty()) {
        throw Error(QCoreApplication::translate("PayloadIdentification",
                                                "no log to identify the payload from"));
    }
    PayloadIdentificationResult r;
    r.arm = loadPayloadArm(request.logs, request.armUrdf, request.armUrdfName);
    const LogRobot &robot = r.arm.robot;
    try {
        r.model = std::make_shared<const PayloadModel>(robot.model, r.arm.standard, request.link);
    } catch (const Error &e) {
        throw Error(QStringLiteral("%1: %2").arg(names.link, e.message()));
    }
    std::vector<FilteredLog> training, validation, baselines;
    for (const QString &path : request.logs.trainingLogs)
        training.push_back(readLog(path, *robot.model, request.logs, r.readings));
    for (const QString &path : request.baselineLogs)
        baselines.push_back(readLog(path, *robot.model, request.logs, r.readings));
    for (FilteredLog &log : training)
        log = withBaselineSubtracted(*r.model, log, baselines, request.baseline, &r.baselines);
    for (const QString &path : request.logs.validationLogs)
        validation.push_back(readLog(path, *robot.model, request.logs, r.readings));
    r.trainingLogs = request.logs.trainingLogs;
    r.fit = fitPayload(*r.model, training, request.prior, request.fit);
    for (const FilteredLog &log : validation) {
        LogValidation v;
        v.source = log.source;
        v.time.resize(log.keptSamples());
        for (Eigen::Index k = 0; k < v.time.size(); ++k)
            v.time[k] = log.keptTime(k);
        v.measured = measuredTorque(log);
        v.predictedGiven = payloadPredictedTorque(*r.model, InertialParameters::Zero(), log);
        v.predictedIdentified = payloadPredictedTorque(*r.model, r.fit.estimate.parameters, log);
        v.given = torqueFigures(v.measured, v.predictedGiven);
        v.identified = torqueFigures(v.measured, v.predictedIdentified);
        r.validation.push_back(std::move(v));
    }
    return r;
}

} // namespace learnid
