#include "UiTestSupport.h"

#include "io/AtomicFile.h"
#include "io/ParameterFile.h"
#include "io/TrialCsv.h"
#include "service/SessionController.h"
#include "ui/ApplyPanel.h"
#include "ui/ConvergenceTableModel.h"
#include "ui/FileController.h"
#include "ui/MainActions.h"
#include "ui/MessageBar.h"
#include "ui/PlotImage.h"
#include "ui/PreTrialCheckView.h"
#include "ui/TrackingErrorPlot.h"

#include <QAction>
#include <QLineEdit>
#include <QSignalSpy>
#include <QtTest>

using namespace learnid;
using namespace learnid::test;
using Column = ConvergenceTableModel::Column;

/// A whole commissioning session through the real window: connect, three trials by clicking,
/// the table against the session's history, accept, apply, revert, export and read back.
class TestMainWindow : public QObject
{
    Q_OBJECT

private slots:
    void wholeSession_byClicking()
    {
        WindowFixture f;
        SessionController *c = f.window->controller();
        QVERIFY(QTest::qWaitForWindowExposed(f.window.get()));
        QVERIFY(f.click("connectButton"));
        QTRY_VERIFY_WITH_TIMEOUT(c->lastCheck().has_value(), 20000);
        QVERIFY(c->lastCheck()->passed());
        QVERIFY(f.window->checkView()->verdictText().contains(QStringLiteral("passed")));

        QSignalSpy finished(c, &SessionController::runFinished);
        for (int i = 0; i < 3; ++i) {
            QTRY_VERIFY_WITH_TIMEOUT(f.button("runTrialButton")->isEnabled(), 20000);
            QVERIFY(f.click("runTrialButton"));
            QVERIFY(!f.button("runTrialButton")->isEnabled()); // busy: no second run
            QVERIFY(f.button("stopButton")->isEnabled());
            QVERIFY(finished.wait(20000));
            QCOMPARE(finished.constLast().at(0).toBool(), true);
        }
        QCOMPARE(c->history().size(), 3);
        QCOMPARE(c->estimates().size(), 4);

        // The table shows the session's history, row k = estimate k.
        const ConvergenceTableModel *table = f.window->tableModel();
        QCOMPARE(table->rowCount(), 4);
        for (int k = 0; k < 4; ++k)
            for (int p = 0; p < 3; ++p)
                QCOMPARE(table->index(k, table->columnOf(Column::Parameter, p))
                             .data(Qt::UserRole)
                             .toDouble(),
                         c->estimates()[k][p]);
        for (int k = 0; k < 3; ++k)
            QCOMPARE(
                table->index(k, table->columnOf(Column::MaxError)).data(Qt::UserRole).toDouble(),
                c->history()[k].maxTrackingErrorDeg.maxCoeff());
        QCOMPARE(f.window->plot()->trialCount(), 3);
        // The paper's trend: the tracking error shrinks trial by trial.
        QVERIFY(c->history()[2].maxTrackingErrorDeg.maxCoeff() <
                c->history()[0].maxTrackingErrorDeg.maxCoeff());

        // Accept (default: the last estimate), then apply with the confirmation answered.
        QCOMPARE(f.window->applyPanel()->chosenEstimate(), 3);
        QVERIFY(!f.button("applyButton")->isEnabled()); // nothing accepted, nothing to apply
        QVERIFY(f.click("acceptButton"));
        QTRY_COMPARE(c->acceptedIndex().value_or(-1), 3);
        std::optional<ApplyPreview> asked;
        f.window->setApplyConfirmation([&asked](const ApplyPreview &p) {
            asked = p;
            return true;
        });
        QSignalSpy applied(c, &SessionController::applied);
        QTRY_VERIFY(f.button("applyButton")->isEnabled());
        QVERIFY(f.click("applyButton"));
        QVERIFY(applied.wait(20000));
        QVERIFY(asked.has_value());
        QCOMPARE(asked->oldValues.size(), 0);
        QCOMPARE(asked->newValues, c->estimates()[3]);
        QCOMPARE(c->storedParameters(), c->estimates()[3]);
        QCOMPARE(f.window->messageBar()->severity(), MessageBar::Severity::Success);

        // A second apply of estimate 2, then revert restores estimate 3.
        f.window->applyPanel()->setChosenEstimate(2);
        QVERIFY(f.click("acceptButton"));
        QTRY_COMPARE(c->acceptedIndex().value_or(-1), 2);
        QTRY_VERIFY(f.button("applyButton")->isEnabled());
        QVERIFY(f.click("applyButton"));
        QVERIFY(applied.wait(20000));
        QCOMPARE(asked->oldValues, c->estimates()[3]);
        QCOMPARE(c->storedParameters(), c->estimates()[2]);
        QTRY_VERIFY(f.button("revertButton")->isEnabled());
        QVERIFY(f.click("revertButton"));
        QVERIFY(applied.wait(20000));
        QCOMPARE(c->storedParameters(), c->estimates()[3]);

        // Export through the menu actions with the path chooser answered.
        QTemporaryDir out;
        f.window->files()->setPathChooser([&out](FileController::Purpose purpose, const QString &) {
            switch (purpose) {
            case FileController::Purpose::ParameterFile:
                return out.filePath(QStringLiteral("params.json"));
            case FileController::Purpose::TrialCsvFolder:
                return out.filePath(QStringLiteral("trials"));
            case FileController::Purpose::Plot:
                return out.filePath(QStringLiteral("plot.png"));
            case FileController::Purpose::Report:
                return out.filePath(QStringLiteral("report.pdf"));
            default:
                return QString();
            }
        });
        QSignalSpy done(f.window->files(), &FileController::finished);
        f.window->actions()->exportParameters->trigger();
        QVERIFY(done.wait(20000));
        QVERIFY2(done.constLast().at(1).toBool(), qPrintable(done.constLast().at(0).toString()));
        const ParameterFileContent content = parameterFileFromJson(
            readFile(out.filePath(QStringLiteral("params.json"))), QStringLiteral("params.json"));
        QCOMPARE(content.values, c->estimates()[2]); // the accepted estimate
        QVERIFY(QFile::exists(out.filePath(QStringLiteral("params.dcf"))));

        f.window->actions()->exportTrialCsv->trigger(); // written in the session's thread
        QVERIFY(done.wait(20000));
        QVERIFY2(done.constLast().at(1).toBool(), qPrintable(done.constLast().at(0).toString()));
        const TrialRecordCsv csv =
            readTrialCsvFile(out.filePath(QStringLiteral("trials/trial-001.csv")));
        QCOMPARE(csv.samples(), c->history()[1].record.samples());

        f.window->actions()->exportPlot->trigger();
        QVERIFY2(done.constLast().at(1).toBool(), qPrintable(done.constLast().at(0).toString()));
        QImage png(out.filePath(QStringLiteral("plot.png")));
        QVERIFY(!png.isNull());
        if (svgExportAvailable()) {
            f.window->files()->exportPlotTo(out.filePath(QStringLiteral("plot.svg")));
            QVERIFY(done.constLast().at(1).toBool());
            QVERIFY(readFile(out.filePath(QStringLiteral("plot.svg"))).contains("<svg"));
        }
        f.window->actions()->exportReport->trigger();
        QVERIFY2(done.constLast().at(1).toBool(), qPrintable(done.constLast().at(0).toString()));
        QVERIFY(readFile(out.filePath(QStringLiteral("report.pdf"))).startsWith("%PDF"));
    }

    void settings_areRememberedBetweenWindows()
    {
        QTemporaryDir dir;
        QSettings settings(dir.filePath(QStringLiteral("s.ini")), QSettings::IniFormat);
        {
            MainWindow w(&settings);
            auto *edit = w.findChild<QLineEdit *>(QStringLiteral("controller.lambda"));
            edit->selectAll();
            QTest::keyClicks(edit, QStringLiteral("250"));
        }
        MainWindow again(&settings);
        auto *edit = again.findChild<QLineEdit *>(QStringLiteral("controller.lambda"));
        QCOMPARE(edit->text(), QStringLiteral("250"));
    }
};

QTEST_MAIN(TestMainWindow)
#include "tst_ui_mainwindow.moc"
