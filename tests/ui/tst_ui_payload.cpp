// The payload step through its real widgets (PayloadDialog, offscreen): the simulated Panda
// carrying 1.5 kg 5 cm off the flange axis (test::pandaWithPayload()) learned to the issue's
// targets by clicking, the estimate table against the run's result, the run's report and trial
// CSVs and the exports read back, Stop and a stop at the tracking limit leaving no result but
// the record of the run's trials, refused values named at their fields,
// the gains designed for the payload (the Panda's rated 3 kg then learned), Save scenario keeping
// the edits, and the window routing a scenario file with a payload section to the payload step
// instead of the arm's session.
#include "../session/PayloadScenarios.h"
#include "UiTestSupport.h"
#include "io/ParameterFile.h"
#include "io/ScenarioFile.h"
#include "service/PayloadRun.h"
#include "service/SessionController.h"
#include "session/RobotScenario.h"
#include "ui/FileController.h"
#include "ui/MainActions.h"
#include "ui/MessageBar.h"
#include "ui/PayloadDialog.h"
#include "ui/PayloadEstimateTableModel.h"
#include "ui/PayloadForm.h"
#include "ui/PayloadTrialTableModel.h"
#include "ui/ScenarioForm.h"
#include "ui/TrackingErrorPlot.h"

#include <QAction>
#include <QComboBox>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

using namespace learnid;
using Column = PayloadEstimateTableModel::Column;

namespace {

void typeInto(QLineEdit *edit, const QString &text)
{
    edit->selectAll();
    QTest::keyClicks(edit, text);
    if (text.isEmpty())
        QTest::keyClick(edit, Qt::Key_Delete);
}

double cell(const QAbstractItemModel *m, int row, int column)
{
    return m->index(row, column).data(Qt::UserRole).toDouble();
}

/// Saves the dialog's record by clicking `button` into a new folder, checks the report's trials
/// and the CSV of each of the `rows` trials, and returns the report.
QJsonObject savedRecord(PayloadDialog &d, QPushButton *button, int rows)
{
    QTemporaryDir dir;
    d.setPathChooser([&dir](PayloadDialog::ExportKind, const QString &) {
        return dir.filePath(QStringLiteral("ended.json"));
    });
    QFile file(dir.filePath(QStringLiteral("ended.json")));
    if (button->isEnabled())
        QTest::mouseClick(button, Qt::LeftButton);
    if (d.messageBar()->severity() != MessageBar::Severity::Success ||
        !file.open(QIODevice::ReadOnly))
        return {};
    const QJsonObject report = QJsonDocument::fromJson(file.readAll()).object();
    for (int i = 0; i < rows; ++i) {
        const QString csv = QStringLiteral("ended-trials/trial-%1.csv").arg(i, 3, 10, QChar('0'));
        if (QFileInfo(dir.filePath(csv)).size() == 0)
            return {};
    }
    return report.value(QStringLiteral("trials")).toArray().size() == rows ? report : QJsonObject();
}

} // namespace

class TestUiPayload : public QObject
{
    Q_OBJECT

private slots:
    void pandaPayload_learnedByClicking_andExported()
    {
        const Scenario s = test::pandaWithPayload();
        PayloadDialog d(nullptr);
        QSignalSpy preview(&d, &PayloadDialog::previewShown);
        d.setScenario(s);
        d.show();
        QVERIFY(preview.wait(20000));
        QCOMPARE(preview.constLast().at(0).toBool(), true);
        // What the path sees, as PayloadSession::observability() says before any motion.
        const int rank = makeSimulatedPayloadSession(s).session->observability().rank;
        QVERIFY2(d.previewText().contains(
                     QStringLiteral("<b>%1 of the payload's 10 parameters</b>").arg(rank)),
                 qPrintable(d.previewText()));
        QVERIFY(d.previewText().contains(QStringLiteral("passes its check")));
        auto *run = d.findChild<QPushButton *>(QStringLiteral("runPayloadButton"));
        auto *accept = d.findChild<QPushButton *>(QStringLiteral("acceptPayloadButton"));
        auto *exportFile =
            d.findChild<QPushButton *>(QStringLiteral("exportPayloadParametersButton"));
        auto *exportUrdf = d.findChild<QPushButton *>(QStringLiteral("exportPayloadUrdfButton"));
        QVERIFY(run->isEnabled() && !accept->isEnabled() && !exportFile->isEnabled());

        QSignalSpy finished(&d, &PayloadDialog::runFinished);
        QTest::mouseClick(run, Qt::LeftButton);
        QVERIFY(!run->isEnabled()); // one run at a time
        QVERIFY(finished.wait(30000));
        QCOMPARE(finished.constFirst().at(0).toBool(), true);
        const auto result = d.result();
        QVERIFY(result);
        QCOMPARE(d.trialTable()->rowCount(), 3);
        QCOMPARE(cell(d.trialTable(), 2, PayloadTrialTableModel::Mass),
                 result->fit.estimate.body.mass);
        // Every trial's tracking error drawn, the joints named as the URDF names them.
        QCOMPARE(d.trackingPlot()->trialCount(), 3);
        QCOMPARE(d.trackingPlot()->jointCount(), 7);

        // The estimate table: mass within 1 % and centre of mass within 3 mm of the simulated
        // payload, each with a standard error, from the trials' data.
        const PayloadEstimateTableModel *t = d.estimateTable();
        QCOMPARE(t->rowCount(), 10);
        const double mass = cell(t, 0, Column::Estimate);
        QVERIFY2(std::abs(mass - 1.5) < 0.015, qPrintable(QString::number(mass)));
        Eigen::Vector3d comMm;
        for (int a = 0; a < 3; ++a)
            comMm[a] = cell(t, 1 + a, Column::Estimate);
        const double comError = (comMm - 1000.0 * s.simulation.payload.com).norm();
        QVERIFY2(comError < 3.0, qPrintable(QString::number(comError)));
        for (int row = 0; row < 4; ++row) {
            const double error = cell(t, row, Column::StandardError);
            QVERIFY2(std::isfinite(error) && error > 0.0, qPrintable(QString::number(row)));
            QVERIFY(
                t->index(row, Column::Source).data().toString().startsWith(QStringLiteral("data")));
        }
        QCOMPARE(cell(t, 0, Column::Prior), 1.2);
        QCOMPARE(cell(t, 0, Column::StandardError), result->fit.estimate.bodyStandardError[0]);

        // The run's record, before any Accept: the report and every trial's CSV, read back
        // against the table (the same report `learnid-cli run --report` writes).
        QTemporaryDir dir;
        d.setPathChooser([&dir](PayloadDialog::ExportKind kind, const QString &) {
            return dir.filePath(kind == PayloadDialog::ExportKind::ParameterFile
                                    ? QStringLiteral("panda-payload.json")
                                : kind == PayloadDialog::ExportKind::Record
                                    ? QStringLiteral("run.json")
                                    : QStringLiteral("panda-payload.urdf"));
        });
        auto *record = d.findChild<QPushButton *>(QStringLiteral("savePayloadRecordButton"));
        QVERIFY(record && record->isEnabled());
        QTest::mouseClick(record, Qt::LeftButton);
        QVERIFY2(d.messageBar()->severity() == MessageBar::Severity::Success,
                 qPrintable(d.messageBar()->text()));
        QFile reportFile(dir.filePath(QStringLiteral("run.json")));
        QVERIFY(reportFile.open(QIODevice::ReadOnly));
        const QJsonObject report = QJsonDocument::fromJson(reportFile.readAll()).object();
        QCOMPARE(report.value(QStringLiteral("schema")).toString(),
                 QStringLiteral("learnid-payload-report/1"));
        const QJsonArray reported = report.value(QStringLiteral("trials")).toArray();
        QCOMPARE(reported.size(), d.trialTable()->rowCount());
        QCOMPARE(reported.last().toObject().value(QStringLiteral("mass")).toDouble(),
                 result->fit.estimate.body.mass);
        for (int i = 0; i < 3; ++i) {
            const QString csv = dir.filePath(
                QStringLiteral("run-trials/trial-%1.csv").arg(i, 3, 10, QLatin1Char('0')));
            QVERIFY2(QFileInfo(csv).size() > 0, qPrintable(csv));
        }

        // Accept, then both exports, written where the chooser says; they read back.
        QVERIFY(accept->isEnabled() && !exportFile->isEnabled());
        QTest::mouseClick(accept, Qt::LeftButton);
        QVERIFY(exportFile->isEnabled() && exportUrdf->isEnabled());
        QTest::mouseClick(exportFile, Qt::LeftButton);
        QCOMPARE(d.messageBar()->severity(), MessageBar::Severity::Success);
        const ParameterFileContent file =
            readParameterFile(dir.filePath(QStringLiteral("panda-payload.json")));
        QVERIFY(file.payload);
        QCOMPARE(file.payload->mass, result->fit.estimate.body.mass);
        QCOMPARE(file.payload->link, QStringLiteral("panda_link7"));
        QVERIFY(QFileInfo::exists(dir.filePath(QStringLiteral("panda-payload.dcf"))));
        QTest::mouseClick(exportUrdf, Qt::LeftButton);
        QCOMPARE(d.messageBar()->severity(), MessageBar::Severity::Success);
        QVERIFY(QFileInfo::exists(dir.filePath(QStringLiteral("panda-payload.urdf"))));

        // An edit makes the result stale: it is dropped, nothing left to export; the record of
        // the trials in the table stays.
        typeInto(d.form()->field(QStringLiteral("payload.prior.mass")), QStringLiteral("1.3"));
        QVERIFY(!d.result());
        QVERIFY(!exportFile->isEnabled() && !accept->isEnabled() && record->isEnabled());
        QCOMPARE(d.estimateTable()->rowCount(), 0);
    }

    void stop_leavesNoResult_butTheRecordOfItsTrials()
    {
        Scenario s = test::pandaWithPayload();
        s.iterations = 5;
        PayloadDialog d(nullptr);
        d.setScenario(s);
        d.show();
        QSignalSpy finished(&d, &PayloadDialog::runFinished);
        auto *stop = d.findChild<QPushButton *>(QStringLiteral("stopPayloadButton"));
        auto *record = d.findChild<QPushButton *>(QStringLiteral("savePayloadRecordButton"));
        QVERIFY(!stop->isEnabled() && !record->isEnabled());
        // Stop while the second trial runs: the first one finished.
        connect(d.trialTable(), &QAbstractItemModel::rowsInserted, stop,
                [stop] { QTest::mouseClick(stop, Qt::LeftButton); });
        d.run();
        QVERIFY(stop->isEnabled());
        QVERIFY(finished.wait(60000));
        QCOMPARE(finished.constFirst().at(0).toBool(), false);
        QVERIFY(!d.result());
        QCOMPARE(d.estimateTable()->rowCount(), 0);
        const int rows = d.trialTable()->rowCount();
        QVERIFY2(rows >= 1 && rows < 5, qPrintable(QString::number(rows)));
        QVERIFY(!d.findChild<QPushButton *>(QStringLiteral("acceptPayloadButton"))->isEnabled());
        QVERIFY(d.findChild<QPushButton *>(QStringLiteral("runPayloadButton"))->isEnabled());
        QCOMPARE(d.messageBar()->severity(), MessageBar::Severity::Info);

        // Nothing lost: the report, marked as stopped, and the CSV of every trial that moved.
        const QJsonObject report = savedRecord(d, record, rows);
        QCOMPARE(report.value(QStringLiteral("endedEarly")).toString(),
                 QStringLiteral("stopped (Stop) by the technician"));
        QVERIFY(report.value(QStringLiteral("result")).isNull() ||
                report.value(QStringLiteral("result")).isObject()); // trial 0 may have learned
    }

    void trackingStop_failsTheRun_andKeepsItsRecord()
    {
        // An abort limit far below what the prior tracks (trial 0 of this payload: 1.6 deg): the
        // first trial stops at once, and the run ends on a stop too short to learn from (or on
        // the second stop in a row). No result; the record says why: the last trial's reason.
        Scenario s = test::pandaWithPayload();
        s.maxTrackingErrorDeg = 0.01;
        PayloadDialog d(nullptr);
        d.setScenario(s);
        QSignalSpy finished(&d, &PayloadDialog::runFinished);
        d.run();
        QVERIFY(finished.wait(60000));
        QCOMPARE(finished.constFirst().at(0).toBool(), false);
        QVERIFY(!d.result());
        QCOMPARE(d.messageBar()->severity(), MessageBar::Severity::Error);
        const int rows = d.trialTable()->rowCount();
        QVERIFY(rows >= 1 && rows <= 2);
        auto *record = d.findChild<QPushButton *>(QStringLiteral("savePayloadRecordButton"));
        const QJsonObject report = savedRecord(d, record, rows);
        const QString why = report.value(QStringLiteral("endedEarly")).toString();
        const QJsonArray trials = report.value(QStringLiteral("trials")).toArray();
        QCOMPARE(trials.size(), rows);
        QVERIFY(!why.isEmpty());
        QCOMPARE(why, trials.last().toObject().value(QStringLiteral("message")).toString());
        QVERIFY2(d.messageBar()->text().contains(why), qPrintable(d.messageBar()->text()));
        QVERIFY(trials.first().toObject().value(QStringLiteral("status")).toString() !=
                QStringLiteral("completed"));
    }

    void designForPayload_stiffensForThePrior_keepsTheRest_andLearnsTheRatedPayload()
    {
        // The Panda's bare starter with its rated 3 kg mounted (prior 2.5 kg): the bare gains
        // let the first trial sag to the 5 deg limit (learnid-bench-payload --starter); the
        // technician designs the gains for the payload in the step.
        Scenario s = scenarioForRobot(QStringLiteral("panda"));
        s.simulation.inertiaPerturbation = 0.0;
        s.iterations = 3;
        s.payload.enabled = true;
        s.payload.link = QStringLiteral("panda_link7");
        s.payload.mass = 2.5;
        s.payload.com = Eigen::Vector3d(0.0, 0.0, 0.05);
        s.simulation.payload = test::pandaWithRatedPayload().simulation.payload;
        PayloadDialog d(nullptr);
        QSignalSpy preview(&d, &PayloadDialog::previewShown);
        d.setScenario(s);
        d.show();
        QVERIFY(preview.wait(20000));
        auto *design = d.findChild<QPushButton *>(QStringLiteral("designPayloadGainsButton"));
        QVERIFY(design && design->isEnabled());
        preview.clear();
        QTest::mouseClick(design, Qt::LeftButton);
        QVERIFY2(d.messageBar()->text().startsWith(
                     QStringLiteral("Gains designed for the arm carrying 2.5 kg on panda_link7")),
                 qPrintable(d.messageBar()->text()));
        const Scenario after = *d.form()->scenario();
        // Stiffer where the payload's weight acts (the shoulder and the wrist), the baseline
        // trials on the bare arm's own gains, everything else as it was.
        QVERIFY(after.controller.kp[1] > s.controller.kp[1]);
        QVERIFY(after.controller.kp[5] > s.controller.kp[5]);
        QCOMPARE(after.payload.baselineKp, s.controller.kp);
        QCOMPARE(after.path.waypoints, s.path.waypoints);
        QCOMPARE(after.simulation.payload.mass, 3.0);
        QCOMPARE(after.payload.mass, 2.5);
        QCOMPARE(after.iterations, 3);
        QVERIFY(preview.wait(20000)); // planned again with the new gains
        QVERIFY2(d.previewText().contains(QStringLiteral("The first trial passes its check")),
                 qPrintable(d.previewText()));

        // And the payload it was designed for is learned.
        QSignalSpy finished(&d, &PayloadDialog::runFinished);
        QTest::mouseClick(d.findChild<QPushButton *>(QStringLiteral("runPayloadButton")),
                          Qt::LeftButton);
        QVERIFY(finished.wait(120000));
        QVERIFY2(finished.constFirst().at(0).toBool(), qPrintable(d.messageBar()->text()));
        const PayloadBody &b = d.result()->fit.estimate.body;
        QVERIFY2(std::abs(b.mass - 3.0) < 0.03, qPrintable(QString::number(b.mass)));
        QVERIFY2((b.com - Eigen::Vector3d(0.05, 0.0, 0.08)).norm() < 3e-3,
                 qPrintable(QString::number(b.com.z())));

        // On a slower clock (a CAN bus at 4 ms) the robot's period stays, and the gains are
        // designed for it: the 2 ms ones are unstable there, these pass the check.
        s.controller.samplePeriod = 0.004;
        d.setScenario(s);
        QVERIFY(preview.wait(20000));
        preview.clear();
        QTest::mouseClick(design, Qt::LeftButton);
        QCOMPARE(d.form()->scenario()->controller.samplePeriod, 0.004);
        QVERIFY(preview.wait(20000));
        QVERIFY2(d.previewText().contains(QStringLiteral("The first trial passes its check")),
                 qPrintable(d.previewText()));
    }

    void saveScenario_keepsTheStepsEdits_andNotWhileAFieldIsWrong()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        PayloadDialog d(nullptr);
        d.setScenario(test::pandaWithPayload());
        const QString file = dir.filePath(QStringLiteral("edited.json"));
        d.setPathChooser([&file](PayloadDialog::ExportKind kind, const QString &) {
            return kind == PayloadDialog::ExportKind::Scenario ? file : QString();
        });
        auto *save = d.findChild<QPushButton *>(QStringLiteral("savePayloadScenarioButton"));
        QVERIFY(save && save->isEnabled());
        PayloadForm *form = d.form();
        typeInto(form->field(QStringLiteral("payload.prior.mass")), QStringLiteral("1.35"));
        typeInto(form->field(QStringLiteral("payload.baselineTrials")), QStringLiteral("2"));
        QVERIFY(form->isValid());
        QTest::mouseClick(save, Qt::LeftButton);
        QVERIFY2(d.messageBar()->text().startsWith(QStringLiteral("Scenario saved")),
                 qPrintable(d.messageBar()->text()));
        // Read back as the window and learnid-cli read it: the edits, and the form's scenario.
        const Scenario read = readScenarioFile(file);
        QCOMPARE(read.payload.mass, 1.35);
        QCOMPARE(read.payload.baselineTrials, 2);
        QCOMPARE(read.payload.link, QStringLiteral("panda_link7"));
        QCOMPARE(scenarioToJson(read), scenarioToJson(*form->scenario()));

        // A wrong field: nothing to save, and the file keeps what was saved.
        typeInto(form->field(QStringLiteral("payload.prior.mass")), QStringLiteral("-1"));
        QVERIFY(!save->isEnabled());
        QCOMPARE(readScenarioFile(file).payload.mass, 1.35);
    }

    void badInput_isShownAtItsField()
    {
        PayloadDialog d(nullptr);
        d.setScenario(test::pandaWithPayload());
        PayloadForm *form = d.form();
        auto *run = d.findChild<QPushButton *>(QStringLiteral("runPayloadButton"));
        QVERIFY(form->isValid() && run->isEnabled());
        const QString massKey = QStringLiteral("payload.prior.mass");
        const struct
        {
            const char *key;
            const char *text;
        } cases[] = {{"payload.prior.mass", "-1"},
                     {"payload.prior.mass", "0"},
                     {"payload.prior.mass", "nan"},
                     {"payload.prior.mass", "heavy"},
                     {"payload.prior.com", "0, 0"},
                     {"payload.bound.radius", "0.01"},
                     {"payload.prior.inertia", "1, 0, 1, 0, 0, 5"},
                     {"payload.baselineTrials", "1.5"}};
        for (const auto &c : cases) {
            const QString key = QLatin1String(c.key);
            QLineEdit *edit = form->field(key);
            QVERIFY(edit);
            const QString before = edit->text();
            typeInto(edit, QLatin1String(c.text));
            QVERIFY2(!form->isValid(), c.text);
            QVERIFY2(!form->reasonFor(key).isEmpty(),
                     qPrintable(key + QLatin1Char(' ') + form->firstError()));
            QVERIFY2(form->firstError().startsWith(key), qPrintable(form->firstError()));
            QVERIFY(!run->isEnabled());
            typeInto(edit, before);
            QVERIFY2(form->isValid(), qPrintable(form->firstError()));
        }
        // The prior outside its own bound: the box that does not contain it is named.
        typeInto(form->field(QStringLiteral("payload.bound.box")),
                 QStringLiteral("0.1, 0.1, 0.1, 0.2, 0.2, 0.2"));
        QVERIFY(!form->isValid());
        QVERIFY2(form->firstError().startsWith(QStringLiteral("payload.")),
                 qPrintable(form->firstError()));
        // An unknown link from a scenario file is shown at the link.
        Scenario s = test::pandaWithPayload();
        s.payload.link = QStringLiteral("panda_gripper");
        d.setScenario(s);
        QVERIFY(!form->isValid());
        QVERIFY2(!form->reasonFor(QStringLiteral("payload.link")).isEmpty(),
                 qPrintable(form->firstError()));
        QVERIFY(form->reasonFor(massKey).isEmpty());
        QVERIFY(form->linkChoice()->currentText() == QStringLiteral("panda_gripper"));
        form->linkChoice()->setCurrentIndex(0); // the tip
        emit form->linkChoice()->activated(0);
        QVERIFY2(form->isValid(), qPrintable(form->firstError()));
        QCOMPARE(form->scenario()->payload.link, QString());
        // The flange, fixed to link 7, is offered beside the moving links and can be chosen.
        const int flange = form->linkChoice()->findData(QStringLiteral("panda_link8"));
        QVERIFY(flange > 0);
        QCOMPARE(form->linkChoice()->itemText(flange),
                 QStringLiteral("panda_link8 (on panda_link7)"));
        form->linkChoice()->setCurrentIndex(flange);
        emit form->linkChoice()->activated(flange);
        QVERIFY2(form->isValid(), qPrintable(form->firstError()));
        QCOMPARE(form->scenario()->payload.link, QStringLiteral("panda_link8"));
    }

    void window_routesAPayloadScenarioToThePayloadStep()
    {
        test::WindowFixture f;
        const QString path = f.dir.filePath(QStringLiteral("panda-payload.json"));
        writeScenarioFile(path, test::pandaWithPayload());
        QSignalSpy openFailed(f.window->controller(), &SessionController::openFailed);
        f.window->files()->openScenarioFrom(path);
        QVERIFY(f.window->payloadDialog());
        QTRY_VERIFY(f.window->payloadDialog()->isVisible());
        const auto s = f.window->payloadDialog()->form()->scenario();
        QVERIFY(s);
        QCOMPARE(s->payload.mass, 1.2);
        QCOMPARE(s->payload.link, QStringLiteral("panda_link7"));
        const QString note = f.window->payloadDialog()->messageBar()->text();
        QVERIFY2(note.contains(QStringLiteral("payload step")), qPrintable(note));
        // The arm's session was not opened with it (it would refuse it).
        QTest::qWait(200);
        QVERIFY(openFailed.isEmpty());
        QVERIFY(!f.window->controller()->isOpen());
        f.window->payloadDialog()->close();

        // Robot > Learn a payload opens the step with the form's scenario.
        f.window->actions()->learnPayload->trigger();
        QVERIFY(f.window->payloadDialog()->isVisible());
        QCOMPARE(f.window->payloadDialog()->form()->scenario()->payload.mass, 1.2);
    }
};

QTEST_MAIN(TestUiPayload)
#include "tst_ui_payload.moc"
