// identifyFromLogs() against the library's steps run one by one (bench/realdata.cpp), its stages
// and its cancel flag, the exports, and LogIdentificationJob's thread; on the double pendulum's
// recorded logs (../shared/data, read in place; skipped without them).
#include "../support/NumericAssert.h"
#include "../support/SharedData.h"
#include "io/ParameterFile.h"
#include "model/UrdfChain.h"
#include "service/LogIdentification.h"
#include "service/LogIdentificationJob.h"
#include "service/SessionExport.h"

#include <QDir>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

using namespace learnid;
using Stage = LogIdentificationStage;

class TestLogIdentification : public QObject
{
    Q_OBJECT

private slots:
    void init();
    void doublePendulum_isTheLibrarysStepsInStages();
    void cancelFlag_stopsAtTheNextStageWithNothing();
    void exports_areTheFitAndRefuseGainsOfAnotherRobot();
    void job_runsInItsThreadAndCancels();
    void unknownRobot_namesTheBuiltIns();

private:
    LogIdentificationRequest m_request;
};

void TestLogIdentification::init()
{
    m_request = {};
    m_request.robot = QStringLiteral("double-pendulum");
    m_request.columns =
        parseLogColumns(QStringLiteral("t=time,q=pos_meas%1,dq=vel_meas%1,tau=tau_meas%1"));
    for (int i = 0; i < 4; ++i) {
        const QString file = test::sharedDataFile(
            QStringLiteral("double-pendulum/trajectory_%1.csv").arg(i, 2, 10, QLatin1Char('0')));
        if (file.isEmpty())
            QSKIP(qPrintable(test::sharedDataMissing()));
        (i < 3 ? m_request.trainingLogs : m_request.validationLogs) << file;
    }
}

void TestLogIdentification::doublePendulum_isTheLibrarysStepsInStages()
{
    QList<LogIdentificationProgress> stages;
    const LogIdentificationResult r =
        identifyFromLogs(m_request, [&stages](const LogIdentificationProgress &p) { stages << p; });

    const QList<Stage> expected = {Stage::Robot,        Stage::ReadTraining,   Stage::ReadTraining,
                                   Stage::ReadTraining, Stage::ReadValidation, Stage::Fit,
                                   Stage::Validate};
    QCOMPARE(stages.size(), expected.size());
    for (int i = 0; i < stages.size(); ++i) {
        QCOMPARE(stages[i].stage, expected[i]);
        QCOMPARE(stages[i].step, i);
        QCOMPARE(stages[i].steps, int(expected.size()));
    }
    QCOMPARE(stages[2].path, m_request.trainingLogs[1]);
    QCOMPARE(stages[2].index, 1);
    QCOMPARE(stages[2].count, 3);

    // The steps one by one.
    const ChainModel &model = r.model();
    const auto load = [&](const QString &path) {
        return filterLog(
            resampleUniform(readRobotLogFile(path, 2, m_request.columns, {true, true})),
            LogFilterSettings{});
    };
    const LogFit fit = fitLogs(model,
                               {load(m_request.trainingLogs[0]), load(m_request.trainingLogs[1]),
                                load(m_request.trainingLogs[2])},
                               LogFitSettings{});
    QCOMPARE(r.fit.standard, fit.standard);
    QCOMPARE(r.fit.base, fit.base);
    const FilteredLog validation = load(m_request.validationLogs[0]);
    QCOMPARE(r.validation.size(), size_t(1));
    const LogValidation &v = r.validation.front();
    QCOMPARE(v.identified.overall, torqueFigures(model, fit.standard, validation).overall);
    QCOMPARE(v.given.overall, torqueFigures(model, model.cadStandard(), validation).overall);
    QCOMPARE(v.samples(), validation.keptSamples());
    QCOMPARE(v.time[0], validation.keptTime(0));
    QCOMPARE(v.measured, measuredTorque(validation));
    QCOMPARE(v.predictedIdentified, predictedTorque(model, fit.standard, validation));
    QCOMPARE(v.predictedGiven, predictedTorque(model, model.cadStandard(), validation));
    QVERIFY(r.consistent);
    QVERIFY(r.undetermined.isEmpty());
    QCOMPARE(r.robot.modelId, QStringLiteral("double-pendulum"));
}

void TestLogIdentification::cancelFlag_stopsAtTheNextStageWithNothing()
{
    std::atomic<bool> cancel{false};
    QList<Stage> seen;
    const auto observer = [&](const LogIdentificationProgress &p) {
        seen << p.stage;
        if (p.stage == Stage::ReadTraining && p.index == 1)
            cancel = true; // while the second log is read
    };
    QVERIFY_THROWS_EXCEPTION(LogIdentificationCancelled,
                             identifyFromLogs(m_request, observer, &cancel));
    QCOMPARE(seen, (QList<Stage>{Stage::Robot, Stage::ReadTraining, Stage::ReadTraining}));
    // A flag set before the run: not even the robot is read.
    seen.clear();
    QVERIFY_THROWS_EXCEPTION(LogIdentificationCancelled,
                             identifyFromLogs(m_request, observer, &cancel));
    QVERIFY(seen.isEmpty());
}

void TestLogIdentification::exports_areTheFitAndRefuseGainsOfAnotherRobot()
{
    const LogIdentificationResult r = identifyFromLogs(m_request);
    QTemporaryDir dir;
    LogExportRequest request;
    request.parameterPath = dir.filePath(QStringLiteral("p.json"));
    request.controller = ControllerSettings(); // the scenario defaults: two joints
    request.urdfPath = dir.filePath(QStringLiteral("r.urdf"));
    request.urdfComment = QStringLiteral("test");
    QCOMPARE(
        writeLogExport(r, request),
        (QStringList{request.parameterPath, dcfPathFor(request.parameterPath), request.urdfPath}));
    const ParameterFileContent params = readParameterFile(request.parameterPath);
    LEARNID_COMPARE_MATRIX(params.values, r.fit.base, 1e-12 * r.fit.base.cwiseAbs().maxCoeff());
    QCOMPARE(params.law, QStringLiteral("improved"));
    QCOMPARE(readUrdfChain(request.urdfPath).dof(), 2);

    QVERIFY(params.hasController);
    // Without gains the file holds the model alone: base and standard parameters.
    request.controller.reset();
    request.parameterPath = dir.filePath(QStringLiteral("model.json"));
    request.urdfPath.clear();
    writeLogExport(r, request);
    const ParameterFileContent model = readParameterFile(request.parameterPath);
    QVERIFY(!model.hasController);
    QCOMPARE(model.jointNodes, (QList<int>{1, 2}));
    LEARNID_COMPARE_MATRIX(model.standardValues, r.fit.standard, 0.0);
    QCOMPARE(model.standardDetermined, r.fit.standardDetermined);
    ControllerSettings three;
    three.kp = three.ki = three.kd = Eigen::Vector3d(1, 1, 1);
    request.controller = three;
    request.parameterPath = dir.filePath(QStringLiteral("q.json"));
    QVERIFY_THROWS_EXCEPTION(Error, logExportFiles(r, request));
    QVERIFY(!QFile::exists(request.parameterPath));
}

void TestLogIdentification::job_runsInItsThreadAndCancels()
{
    LogIdentificationJob job;
    QSignalSpy progress(&job, &LogIdentificationJob::progress);
    QSignalSpy succeeded(&job, &LogIdentificationJob::succeeded);
    QSignalSpy cancelled(&job, &LogIdentificationJob::cancelled);
    QVERIFY(job.start(m_request));
    QVERIFY(!job.start(m_request)); // one run at a time
    QVERIFY(succeeded.wait(60000));
    QCOMPARE(progress.size(), 7);
    const auto result =
        succeeded.constFirst().at(0).value<std::shared_ptr<const LogIdentificationResult>>();
    QVERIFY(result);
    QCOMPARE(result->validation.size(), size_t(1));
    QVERIFY(!job.isRunning());

    QVERIFY(job.start(m_request));
    job.cancel();
    QVERIFY(cancelled.wait(60000));
    QCOMPARE(succeeded.size(), 1);
    QVERIFY(!job.isRunning());
}

void TestLogIdentification::unknownRobot_namesTheBuiltIns()
{
    m_request.robot = QStringLiteral("no-such-robot");
    try {
        loadLogRobot(m_request);
        QFAIL("no error");
    } catch (const Error &e) {
        QVERIFY2(e.message().contains(QStringLiteral("double-pendulum")), qPrintable(e.message()));
    }
}

QTEST_GUILESS_MAIN(TestLogIdentification)
#include "tst_logidentification.moc"
