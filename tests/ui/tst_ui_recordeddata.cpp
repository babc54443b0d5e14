// "Identify from recorded data" through the real dialog (offscreen): the double pendulum's logs
// (../shared/data, read in place) chosen with the dialog's own buttons, identified in the worker
// thread, the table and plots against identifyFromLogs() in this process, accept and both
// exports read back; a bad log and a cancelled run leave nothing to accept and nothing written.
#include "../support/NumericAssert.h"
#include "../support/SharedData.h"
#include "UiTestSupport.h"

#include "io/ParameterFile.h"
#include "model/UrdfChain.h"
#include "service/LogIdentification.h"
#include "service/LogIdentificationJob.h"
#include "ui/LogExportController.h"
#include "ui/LogValidationTableModel.h"
#include "ui/MainActions.h"
#include "ui/MessageBar.h"
#include "ui/RecordedDataDialog.h"
#include "ui/TorqueFitPlot.h"
#include "ui/UiSettings.h"

#include <QAction>
#include <QDir>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QSignalSpy>
#include <QtTest>

using namespace learnid;

namespace {

const QString kColumns = QStringLiteral("t=time,q=pos_meas%1,dq=vel_meas%1,tau=tau_meas%1");

/// A dialog with settings of its own, whose file choices come from `paths` by purpose.
struct DialogFixture
{
    QTemporaryDir dir;
    QSettings settings{dir.filePath(QStringLiteral("learnid.ini")), QSettings::IniFormat};
    UiSettings uiSettings{&settings};
    RecordedDataDialog dialog{&uiSettings};
    QHash<RecordedDataPath, QStringList> paths;

    DialogFixture()
    {
        dialog.setPathChooser(
            [this](RecordedDataPath purpose, const QString &) { return paths.value(purpose); });
        dialog.show();
    }

    QAbstractButton *button(const char *name) const
    {
        return dialog.findChild<QAbstractButton *>(QLatin1String(name));
    }

    bool click(const char *name) const
    {
        QAbstractButton *b = button(name);
        if (!b || !b->isEnabled())
            return false;
        QTest::mouseClick(b, Qt::LeftButton);
        return true;
    }

    /// The logs and columns entered with the dialog's buttons and keyboard.
    bool fill(const QStringList &training, const QStringList &validation, const QString &columns)
    {
        paths[RecordedDataPath::TrainingLogs] = training;
        paths[RecordedDataPath::ValidationLogs] = validation;
        auto *edit = dialog.findChild<QLineEdit *>(QStringLiteral("logColumns"));
        if (!edit || !click("addTrainingLogsButton") ||
            (!validation.isEmpty() && !click("addValidationLogsButton")))
            return false;
        edit->clear();
        QTest::keyClicks(edit, columns);
        return true;
    }

    /// Clicks Identify and waits for the run's end; its outcome.
    bool identify(bool *succeeded)
    {
        QSignalSpy finished(&dialog, &RecordedDataDialog::identificationFinished);
        if (!click("identifyButton") || !finished.wait(60000))
            return false;
        *succeeded = finished.constFirst().at(0).toBool();
        return true;
    }
};

QStringList pendulumLogs()
{
    QStringList files;
    for (int i = 0; i < 4; ++i) {
        files << test::sharedDataFile(
            QStringLiteral("double-pendulum/trajectory_%1.csv").arg(i, 2, 10, QLatin1Char('0')));
        if (files.constLast().isEmpty())
            return {};
    }
    return files;
}

} // namespace

class TestRecordedData : public QObject
{
    Q_OBJECT

private slots:
    void menuAction_opensTheDialog();
    void doublePendulum_showsTheLibrarysFiguresAndExportsWhatItShows();
    void textInANumber_namesLineAndColumnAndEnablesNothing();
    void cancelDuringARun_leavesNothingToAcceptOrWrite();
};

void TestRecordedData::menuAction_opensTheDialog()
{
    test::WindowFixture f;
    QVERIFY(!f.window->recordedDataDialog());
    f.window->actions()->identifyFromLogs->trigger();
    RecordedDataDialog *dialog = f.window->recordedDataDialog();
    QVERIFY(dialog);
    QVERIFY(dialog->isVisible());
    QVERIFY(!dialog->findChild<QAbstractButton *>(QStringLiteral("acceptIdentifiedButton"))
                 ->isEnabled());
    f.window->actions()->identifyFromLogs->trigger(); // the same dialog again
    QCOMPARE(f.window->findChildren<RecordedDataDialog *>().size(), 1);
}

void TestRecordedData::doublePendulum_showsTheLibrarysFiguresAndExportsWhatItShows()
{
    const QStringList logs = pendulumLogs();
    if (logs.isEmpty())
        QSKIP(qPrintable(test::sharedDataMissing()));
    DialogFixture f;
    QVERIFY(f.fill(logs.mid(0, 3), {logs[3]}, kColumns));
    bool succeeded = false;
    QVERIFY(f.identify(&succeeded));
    QVERIFY2(succeeded, qPrintable(f.dialog.messageBar()->text()));

    // The same request through the library in this process.
    LogIdentificationRequest request;
    request.robot = QStringLiteral("double-pendulum");
    request.trainingLogs = logs.mid(0, 3);
    request.validationLogs = {logs[3]};
    request.columns = parseLogColumns(kColumns);
    const LogIdentificationResult expected = identifyFromLogs(request);
    const LogValidation &v = expected.validation.front();

    const LogValidationTableModel *table = f.dialog.tableModel();
    QCOMPARE(table->rowCount(), 4); // 2 joints, overall, mean
    const auto cell = [table](int row, int column) {
        return table->index(row, column).data(Qt::UserRole).toDouble();
    };
    const int overall = table->overallRow();
    QCOMPARE(cell(overall, LogValidationTableModel::IdentifiedRatio), 100.0 * v.identified.overall);
    QCOMPARE(cell(overall, LogValidationTableModel::GivenRatio), 100.0 * v.given.overall);
    QVERIFY(cell(overall, LogValidationTableModel::IdentifiedRatio) <
            cell(overall, LogValidationTableModel::GivenRatio));
    QCOMPARE(table->index(overall, LogValidationTableModel::IdentifiedRatio).data().toString(),
             QString::number(100.0 * v.identified.overall, 'f', 3)); // as learnid-cli prints it
    for (int j = 0; j < 2; ++j)
        QCOMPARE(cell(j, LogValidationTableModel::RmsMeasured), v.given.rmsMeasured[j]);

    const TorqueFitPlot *plot = f.dialog.plot();
    QCOMPARE(plot->jointCount(), 2);
    for (int j = 0; j < 2; ++j) {
        QVERIFY(plot->isJointShown(j));
        for (const auto curve : {TorqueFitPlot::Curve::Measured, TorqueFitPlot::Curve::Identified,
                                 TorqueFitPlot::Curve::Given})
            QCOMPARE(plot->pointCount(j, curve), int(v.samples()));
        QCOMPARE(plot->timeRange(j), plot->timeRange(0)); // one time axis
    }
    const QString summary = f.dialog.findChild<QLabel *>(QStringLiteral("identifySummary"))->text();
    QVERIFY(summary.contains(QStringLiteral("physically consistent")));
    // The verdict per link, as checkPlausibility() found it: its smallest principal moment, the
    // CAD link's and (I1 + I2) / I3 in one row of the table.
    QCOMPARE(expected.verdict.plausibility.size(), size_t(2));
    for (const LinkPlausibility &p : expected.verdict.plausibility) {
        const QString cells = QStringLiteral("<td align=\"right\">%1</td><td align=\"right\">%2"
                                             "</td><td align=\"right\">%3</td>")
                                  .arg(QString::number(p.moments[0], 'g', 3),
                                       QString::number(p.cadSmallestMoment, 'g', 3),
                                       QString::number(p.triangleRatio, 'f', 3));
        QVERIFY2(summary.contains(cells), qPrintable(cells + QLatin1Char('\n') + summary));
    }

    // Nothing to export before Accept; then both files, read back.
    QVERIFY(!f.button("exportParameterFileButton")->isEnabled());
    QVERIFY(!f.button("exportUrdfButton")->isEnabled());
    QVERIFY(f.click("acceptIdentifiedButton"));
    QVERIFY(!f.button("acceptIdentifiedButton")->isEnabled());
    QTemporaryDir out;
    const QString json = out.filePath(QStringLiteral("pendulum.json"));
    const QString urdf = out.filePath(QStringLiteral("pendulum.urdf"));
    f.paths[RecordedDataPath::ParameterFile] = {json};
    f.paths[RecordedDataPath::IdentifiedUrdf] = {urdf};
    QSignalSpy exported(f.dialog.exports(), &LogExportController::finished);
    QVERIFY(f.click("exportParameterFileButton"));
    QVERIFY(f.click("exportUrdfButton"));
    QCOMPARE(exported.size(), 2);
    for (const QList<QVariant> &e : exported)
        QVERIFY2(e.at(1).toBool(), qPrintable(e.at(0).toString()));
    QCOMPARE(f.dialog.messageBar()->severity(), MessageBar::Severity::Success);

    const LogFit &fit = expected.fit;
    const ParameterFileContent params = readParameterFile(json);
    QCOMPARE(params.robotModel, QStringLiteral("double-pendulum"));
    QCOMPARE(params.controller.dof(), 2); // the default gains, as learnid-cli without --scenario
    LEARNID_COMPARE_MATRIX(params.values, fit.base, 1e-12 * fit.base.cwiseAbs().maxCoeff());
    QVERIFY(QFile::exists(out.filePath(QStringLiteral("pendulum.dcf"))));
    const SerialChain written = readUrdfChain(urdf);
    QCOMPARE(written.dof(), 2);
    for (int j = 0; j < 2; ++j) {
        const Eigen::VectorXd body = fit.standard.segment<10>(10 * j);
        LEARNID_COMPARE_MATRIX(written.joints[size_t(j)].inertial, body,
                               1e-12 * body.cwiseAbs().maxCoeff());
    }
}

void TestRecordedData::textInANumber_namesLineAndColumnAndEnablesNothing()
{
    DialogFixture f;
    const QString log = f.dir.filePath(QStringLiteral("log.csv"));
    QFile file(log);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("t,q1,q2,dq1,dq2,tau1,tau2\n0,0,0,0,0,0,0\n0.002,0,0,0,abc,0,0\n");
    file.close();
    QVERIFY(f.fill({log}, {}, QString()));
    bool succeeded = true;
    QVERIFY(f.identify(&succeeded));
    QVERIFY(!succeeded);
    const MessageBar *message = f.dialog.messageBar();
    QCOMPARE(message->severity(), MessageBar::Severity::Error);
    QVERIFY2(message->text().contains(QStringLiteral("log.csv: line 3, column 5 (dq2)")),
             qPrintable(message->text()));
    QVERIFY(!f.dialog.result());
    for (const char *name :
         {"acceptIdentifiedButton", "exportParameterFileButton", "exportUrdfButton"})
        QVERIFY2(!f.button(name)->isEnabled(), name);
    QVERIFY(f.button("identifyButton")->isEnabled()); // correct the log and try again
    QCOMPARE(f.dialog.plot()->jointCount(), 0);
    QCOMPARE(f.dialog.tableModel()->rowCount(), 0);
}

void TestRecordedData::cancelDuringARun_leavesNothingToAcceptOrWrite()
{
    const QStringList logs = pendulumLogs();
    if (logs.isEmpty())
        QSKIP(qPrintable(test::sharedDataMissing()));
    DialogFixture f;
    QVERIFY(f.fill(logs.mid(0, 3), {logs[3]}, kColumns));
    auto *job = f.dialog.findChild<LogIdentificationJob *>();
    QVERIFY(job);
    QSignalSpy progress(job, &LogIdentificationJob::progress);
    QSignalSpy finished(&f.dialog, &RecordedDataDialog::identificationFinished);
    QVERIFY(f.click("identifyButton"));
    QVERIFY(!f.button("identifyButton")->isEnabled()); // one run at a time
    QVERIFY(progress.wait(20000));
    QVERIFY(f.click("cancelIdentifyButton"));
    QVERIFY(finished.wait(60000));
    QCOMPARE(finished.constFirst().at(0).toBool(), false);
    QVERIFY2(f.dialog.messageBar()->text().contains(QStringLiteral("cancelled")),
             qPrintable(f.dialog.messageBar()->text()));
    QVERIFY(!f.dialog.result());
    QVERIFY(!f.dialog.isRunning());
    for (const char *name :
         {"acceptIdentifiedButton", "exportParameterFileButton", "exportUrdfButton"})
        QVERIFY2(!f.button(name)->isEnabled(), name);

    // Even asked directly, nothing is written.
    QTemporaryDir out;
    f.dialog.exports()->exportParameterFileTo(out.filePath(QStringLiteral("p.json")));
    f.dialog.exports()->exportUrdfTo(out.filePath(QStringLiteral("r.urdf")));
    QCOMPARE(QDir(out.path()).entryList(QDir::Files | QDir::NoDotAndDotDot), QStringList());
    QCOMPARE(f.dialog.messageBar()->severity(), MessageBar::Severity::Error);
}

QTEST_MAIN(TestRecordedData)
#include "tst_ui_recordeddata.moc"
