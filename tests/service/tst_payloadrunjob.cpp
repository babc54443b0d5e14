// The window's payload step without widgets (PayloadRun.h, PayloadRunJob, PayloadRunExport): on
// the simulated Panda carrying 1.5 kg 5 cm off the flange axis (test::pandaWithPayload()), the job
// learns what a PayloadSession built as `learnid-cli run` builds it learns, bit for bit; Stop ends
// the running trial and leaves no result; the exports read back.
#include "../session/PayloadScenarios.h"
#include "../support/NumericAssert.h"
#include "io/ParameterFile.h"
#include "model/ModelFactory.h"
#include "model/UrdfChain.h"
#include "service/PayloadRunExport.h"
#include "service/PayloadRunJob.h"
#include "session/ScenarioRobot.h"

#include <QElapsedTimer>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

using namespace learnid;

Q_DECLARE_METATYPE(learnid::PayloadTrialRow)
Q_DECLARE_METATYPE(learnid::PayloadPreview)
Q_DECLARE_METATYPE(std::shared_ptr<const learnid::PayloadRunResult>)

namespace {

// The session as PayloadRunCommand (app/cli) builds it, run as PayloadSession::runTrials runs.
std::unique_ptr<PayloadSession> cliSession(const Scenario &given)
{
    const auto model = makeRobotModel(given.model, given.urdf);
    const Scenario s = withRobotDefaults(given, *model);
    return std::make_unique<PayloadSession>(s, model, makeSimulatedRobot(s, model),
                                            makeSimulatedBareRobot(s, model));
}

std::shared_ptr<const PayloadRunResult> runJob(PayloadRunJob &job, const Scenario &s)
{
    QSignalSpy done(&job, &PayloadRunJob::succeeded);
    QSignalSpy failed(&job, &PayloadRunJob::failed);
    if (!job.start(s))
        return {};
    if (!done.wait(30000)) {
        if (!failed.isEmpty())
            qWarning("%s", qPrintable(failed.constFirst().at(0).toString()));
        return {};
    }
    return done.constFirst().at(0).value<std::shared_ptr<const PayloadRunResult>>();
}

} // namespace

class TestPayloadRunJob : public QObject
{
    Q_OBJECT

private slots:
    void job_learnsWhatPayloadSessionLearns()
    {
        const Scenario s = test::pandaWithPayload();
        PayloadRunJob job;
        QSignalSpy started(&job, &PayloadRunJob::trialStarted);
        QSignalSpy rows(&job, &PayloadRunJob::trialFinished);
        const auto result = runJob(job, s);
        QVERIFY(result);
        QVERIFY(!job.isRunning());

        const auto session = cliSession(s);
        QVERIFY(session->runTrials(s.iterations));
        const PayloadTrial &last = session->history().back();
        // The same simulated robot, the same trials: the same doubles.
        QCOMPARE(result->learnedTrial, last.index);
        QCOMPARE(result->fit.estimate.parameters, last.fit->estimate.parameters);
        QCOMPARE(result->maxTrackingErrorDeg, last.maxTrackingErrorDeg);
        QCOMPARE(started.size(), 3);
        QCOMPARE(rows.size(), 3);
        for (int i = 0; i < 3; ++i) {
            QCOMPARE(started.at(i).at(0).toInt(), i);
            QCOMPARE(started.at(i).at(1).toInt(), 3);
            const auto row = rows.at(i).at(0).value<PayloadTrialRow>();
            const PayloadTrial &t = session->history().at(size_t(i));
            QCOMPARE(row.index, i);
            QVERIFY(row.learned);
            QCOMPARE(row.mass, t.fit->estimate.body.mass);
            QCOMPARE(row.com, t.fit->estimate.body.com);
            QCOMPARE(row.maxTrackingErrorDeg, t.maxTrackingErrorDeg.maxCoeff());
            // Its curves for the plot: one per joint over the trial's time, whose largest error
            // is the session's figure (kept through the decimation).
            QCOMPARE(row.curves.size(), 7);
            double worst = 0.0;
            for (const TrackingErrorCurve &c : row.curves) {
                QCOMPARE(c.trial, i);
                QVERIFY(c.points.size() <= 800);
                for (const QPointF &p : c.points)
                    worst = std::max(worst, std::abs(p.y()));
            }
            QVERIFY2(std::abs(worst - row.maxTrackingErrorDeg) <= 1e-9 * row.maxTrackingErrorDeg,
                     qPrintable(QString::number(worst - row.maxTrackingErrorDeg)));
        }
        // Issue 25's targets: mass within 1 %, centre of mass within 3 mm.
        const PayloadBody &b = result->fit.estimate.body;
        QVERIFY2(std::abs(b.mass - 1.5) < 0.015, qPrintable(QString::number(b.mass)));
        QVERIFY2((b.com - s.simulation.payload.com).norm() < 0.003,
                 qPrintable(QString::number((b.com - s.simulation.payload.com).norm())));
    }

    void baselineTrials_runFirstAndCountInTheTotal()
    {
        Scenario s = test::pandaWithPayload();
        s.payload.baselineTrials = 1;
        s.iterations = 1;
        PayloadRunJob job;
        QSignalSpy started(&job, &PayloadRunJob::trialStarted);
        const auto result = runJob(job, s);
        QVERIFY(result);
        QCOMPARE(started.size(), 2);
        QCOMPARE(started.at(0).at(2).toBool(), true);
        QCOMPARE(started.at(1).at(2).toBool(), false);
        QCOMPARE(started.at(1).at(1).toInt(), 2);
        QVERIFY(result->trials.at(0).baseline && result->trials.at(0).usable);
        QVERIFY(!result->trials.at(0).learned);
        const auto session = cliSession(s);
        QVERIFY(session->runTrials(1));
        QCOMPARE(result->fit.estimate.parameters,
                 session->history().back().fit->estimate.parameters);
    }

    void mounting_offBeforeTheBaselinesAndOnAfterThem()
    {
        // The technician's part on the CAN robot (the CLI asks on stdin, the window with
        // Continue; tst_cli_can_payload, tst_ui_canpayload): trial indices count the baselines.
        QCOMPARE(payloadMountingBefore(0, 0), PayloadMounting::Unchanged);
        QCOMPARE(payloadMountingBefore(1, 0), PayloadMounting::Unchanged);
        QCOMPARE(payloadMountingBefore(0, 2), PayloadMounting::TakeOff);
        QCOMPARE(payloadMountingBefore(1, 2), PayloadMounting::Unchanged);
        QCOMPARE(payloadMountingBefore(2, 2), PayloadMounting::Mount);
        QCOMPARE(payloadMountingBefore(3, 2), PayloadMounting::Unchanged);
        QCOMPARE(payloadMountingBefore(0, 1), PayloadMounting::TakeOff);
        QCOMPARE(payloadMountingBefore(1, 1), PayloadMounting::Mount);
    }

    void stop_endsTheRunningTrialAndLeavesNoResult()
    {
        Scenario s = test::pandaWithPayload();
        // A long path (the waypoints there and back five times): a trial runs for seconds
        // unless it is stopped.
        const auto there = s.path.waypoints;
        for (int k = 0; k < 5; ++k) {
            for (auto it = there.rbegin() + 1; it != there.rend(); ++it)
                s.path.waypoints.push_back(*it);
            for (auto it = there.begin() + 1; it != there.end(); ++it)
                s.path.waypoints.push_back(*it);
        }
        PayloadRunJob job;
        QSignalSpy rows(&job, &PayloadRunJob::trialFinished);
        QSignalSpy cancelled(&job, &PayloadRunJob::cancelled);
        QSignalSpy succeeded(&job, &PayloadRunJob::succeeded);
        QSignalSpy records(&job, &PayloadRunJob::endedEarlyRecord);
        connect(&job, &PayloadRunJob::cancelled, this,
                [&] { QCOMPARE(records.size(), 1); }); // the record comes first
        QElapsedTimer stopped;
        const auto stop = connect(&job, &PayloadRunJob::trialStarted, this, [&](int index) {
            if (index == 0) {
                job.cancel();
                stopped.start();
            }
        });
        QVERIFY(job.start(s));
        QVERIFY(job.isRunning());
        QVERIFY(!job.start(s)); // one run at a time
        QSignalSpy failed(&job, &PayloadRunJob::failed);
        QVERIFY2(cancelled.wait(30000),
                 qPrintable(failed.isEmpty() ? QString() : failed.constFirst().at(0).toString()));
        QVERIFY(!job.isRunning());
        QVERIFY(succeeded.isEmpty());
        QCOMPARE(rows.size(), 1);
        const auto row = rows.constFirst().at(0).value<PayloadTrialRow>();
        QVERIFY(!row.usable);
        QVERIFY2(row.message.contains(QStringLiteral("did not complete")), qPrintable(row.message));
        qInfo("stopped %lld ms after Stop", stopped.elapsed());
        // Nothing lost: the stopped trial's record, up to the stop, and why the run ended.
        QCOMPARE(records.size(), 1);
        const auto record =
            records.constFirst().at(0).value<std::shared_ptr<const PayloadRunRecord>>();
        QCOMPARE(record->endedEarly, QStringLiteral("stopped (Stop) by the technician"));
        QCOMPARE(record->trialCsvs.size(), 1);
        QCOMPARE(record->trialCsvs.constFirst().first, QStringLiteral("trial-000.csv"));
        const QJsonObject report = QJsonDocument::fromJson(record->report).object();
        QCOMPARE(report.value(QStringLiteral("endedEarly")).toString(), record->endedEarly);
        const QJsonObject trial = report.value(QStringLiteral("trials")).toArray().at(0).toObject();
        QCOMPARE(trial.value(QStringLiteral("message")).toString(), row.message);
        // A header line, then one line per sample recorded before the stop (file-formats.md).
        const int samples = trial.value(QStringLiteral("samples")).toInt();
        QVERIFY(samples > 0);
        QCOMPARE(record->trialCsvs.constFirst().second.count('\n'), qsizetype(samples + 1));

        disconnect(stop);
        // Nothing of the stopped run is left: the next run learns what a fresh one learns.
        Scenario shortPath = test::pandaWithPayload();
        shortPath.iterations = 1;
        const auto result = runJob(job, shortPath);
        QVERIFY(result);
        const auto session = cliSession(shortPath);
        QVERIFY(session->runTrials(1));
        QCOMPARE(result->fit.estimate.parameters,
                 session->history().back().fit->estimate.parameters);
    }

    void check_reportsWhatThePathSeesOrNamesTheKey()
    {
        const Scenario s = test::pandaWithPayload();
        PayloadRunJob job;
        QSignalSpy checked(&job, &PayloadRunJob::checked);
        QSignalSpy failed(&job, &PayloadRunJob::checkFailed);
        QVERIFY(job.check(s));
        QVERIFY(checked.wait(20000));
        const auto preview = checked.constFirst().at(0).value<PayloadPreview>();
        const auto session = cliSession(s);
        const PayloadObservability o = session->observability();
        QCOMPARE(preview.observability.rank, o.rank);
        QCOMPARE(preview.advice, o.advice(QStringLiteral("panda_link7")));
        QCOMPARE(preview.link, QStringLiteral("panda_link7"));
        QCOMPARE(preview.trials, 3);
        QVERIFY(preview.checkReason.isEmpty());
        QVERIFY(preview.observability.massIdentified() && preview.observability.comIdentified());

        Scenario bad = s;
        bad.payload.mass = -1.0;
        QVERIFY(job.check(bad));
        QVERIFY(failed.wait(20000));
        const QString message = failed.constFirst().at(0).toString();
        QVERIFY2(message.startsWith(QStringLiteral("payload.prior.mass")), qPrintable(message));
        bad = s;
        bad.payload.link = QStringLiteral("no_such_link");
        QVERIFY(job.check(bad));
        QVERIFY(failed.wait(20000));
        QVERIFY2(failed.constLast().at(0).toString().startsWith(QStringLiteral("payload.link")),
                 qPrintable(failed.constLast().at(0).toString()));
    }

    void export_writesFilesThatReadBack()
    {
        Scenario s = test::pandaWithPayload();
        s.iterations = 1;
        PayloadRunJob job;
        const auto result = runJob(job, s);
        QVERIFY(result);
        QTemporaryDir dir;
        LogExportRequest request;
        request.parameterPath = dir.filePath(QStringLiteral("panda+payload.json"));
        request.urdfPath = dir.filePath(QStringLiteral("panda+payload.urdf"));
        request.urdfComment = QStringLiteral("tst_payloadrunjob");
        const QStringList paths = writePayloadRunExport(*result, request);
        QCOMPARE(paths.size(), 3); // with the DCF fragment
        const ParameterFileContent file = readParameterFile(request.parameterPath);
        QCOMPARE(file.robotModel, QStringLiteral("panda"));
        QVERIFY(file.payload);
        const PayloadEstimate &e = result->fit.estimate;
        QCOMPARE(file.payload->link, QStringLiteral("panda_link7"));
        QCOMPARE(file.payload->mass, e.body.mass);
        QCOMPARE(file.payload->com, e.body.com);
        for (size_t k = 0; k < 10; ++k) {
            QCOMPARE(file.payload->identified[k], e.bodyIdentified[k]);
            if (e.bodyIdentified[k])
                QCOMPARE(file.payload->standardUncertainty[k], e.bodyStandardError[k]);
        }
        QCOMPARE(file.values, result->scenario.initialParameters);
        QCOMPARE(file.controller.kp, s.controller.kp);

        // The URDF read back: link 7's body is the arm's plus the payload, the others the arm's.
        const SerialChain back = readUrdfChain(request.urdfPath, result->model->chain().baseLink,
                                               result->model->chain().tipLink);
        const Eigen::VectorXd arm =
            result->model->standardFromBase(result->scenario.initialParameters);
        for (int j = 0; j < 7; ++j) {
            const InertialParameters expected =
                arm.segment<10>(10 * j) + (j == 6 ? e.parameters : InertialParameters::Zero());
            LEARNID_COMPARE_MATRIX(back.joints[size_t(j)].inertial, expected, 1e-9);
        }
    }
};

QTEST_MAIN(TestPayloadRunJob)
#include "tst_payloadrunjob.moc"
