// The window with a 7-axis arm (the built-in Franka Emika Panda), through the real widgets:
// choosing the robot shows its model before any motion, waypoints are checked against the
// URDF's joint limits as they are typed, and a whole simulated session learns, accepts,
// applies and exports the parameter file, the identified URDF and the report. Expectations come
// from the model, the session and independent readers (urdfdom through readUrdfChain).

#include "UiTestSupport.h"

#include "io/AtomicFile.h"
#include "io/ParameterFile.h"
#include "io/PathCsv.h"
#include "model/ChainModel.h"
#include "model/ModelFactory.h"
#include "model/PhysicalConsistency.h"
#include "model/UrdfChain.h"
#include "service/SessionController.h"
#include "session/RobotScenario.h"
#include "ui/ApplyPanel.h"
#include "ui/ConvergenceTableModel.h"
#include "ui/FileController.h"
#include "ui/MainActions.h"
#include "ui/ParameterTableModel.h"
#include "ui/RobotChooser.h"
#include "ui/ScenarioForm.h"
#include "ui/TrackingErrorPlot.h"
#include "ui/WaypointEditor.h"

#include <QAction>
#include <QComboBox>
#include <QLabel>
#include <QLineEdit>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QTableWidget>
#include <QtTest>

using namespace learnid;
using namespace learnid::test;

namespace {

const QString kPanda = QStringLiteral("panda");

void choosePanda(WindowFixture &f)
{
    QComboBox *box = f.window->form()->robotChooser()->modelBox();
    const int i = box->findData(kPanda);
    QVERIFY(i >= 0);
    box->setCurrentIndex(i);
    emit box->activated(i); // as a click on the item does
}

const ChainModel &pandaModel()
{
    // The model of the Panda's starter scenario, which the window picks (rotor inertia in).
    static const auto model = makeRobotModel(kPanda, scenarioForRobot(kPanda, {}).urdf);
    return dynamic_cast<const ChainModel &>(*model);
}

} // namespace

class TestSerialArmWindow : public QObject
{
    Q_OBJECT

private slots:
    void choosingTheRobot_showsItsModelBeforeAnyMotion()
    {
        WindowFixture f;
        choosePanda(f);
        ScenarioForm *form = f.window->form();
        QVERIFY2(form->isValid(), qPrintable(form->firstError()));
        QCOMPARE(form->scenario()->model, kPanda);
        const SerialChain &chain = pandaModel().chain();
        const QTableWidget *joints = form->robotChooser()->jointTable();
        QCOMPARE(joints->rowCount(), 7);
        for (int j = 0; j < 7; ++j) {
            const ChainJoint &joint = chain.joints[size_t(j)];
            QCOMPARE(joints->item(j, 0)->text(), joint.name);
            QCOMPARE(joints->item(j, 2)->text().toDouble(),
                     std::round(joint.upper * 180.0 / M_PI * 10.0) / 10.0);
            QCOMPARE(joints->item(j, 3)->text().toDouble(), joint.effortLimit);
        }
        const QString summary = form->robotChooser()->summaryText();
        QVERIFY2(summary.startsWith(QStringLiteral("7 revolute joint")), qPrintable(summary));
        QVERIFY2(summary.contains(QStringLiteral("%1 base parameters (of %2 standard)")
                                      .arg(pandaModel().parameterCount())
                                      .arg(pandaModel().standardCount())),
                 qPrintable(summary));
        // The URDF's own values as a real robot's, under the summary (docs/robots.md §7): the
        // published Panda's link 2 is a flat plate.
        QVERIFY2(summary.contains(QStringLiteral("\nWarning: link 2 (panda_link2): its principal "
                                                 "moments")),
                 qPrintable(summary));
        // The default path: the waypoints of scenarioForRobot, in degrees, a column per joint.
        const Scenario expected = scenarioForRobot(kPanda);
        const QTableWidget *table = form->waypointEditor()->table();
        QCOMPARE(table->columnCount(), 7);
        QCOMPARE(table->rowCount(), int(expected.path.waypoints.size()));
        for (int i = 0; i < table->rowCount(); ++i)
            for (int j = 0; j < 7; ++j)
                QVERIFY(std::abs(table->item(i, j)->text().toDouble() -
                                 expected.path.waypoints[size_t(i)][j] * 180.0 / M_PI) < 1e-7);
        // The line's fields are for the paper's arm only.
        QVERIFY(!form->findChild<QLineEdit *>(QStringLiteral("path.length"))->isVisible());
    }

    void waypointBeyondAJointLimit_isRefusedAtItsCell()
    {
        WindowFixture f;
        choosePanda(f);
        ScenarioForm *form = f.window->form();
        QTableWidget *table = form->waypointEditor()->table();
        // Joint 4 of the Panda only bends one way: its upper limit is -0.0698 rad.
        table->item(1, 3)->setText(QStringLiteral("10"));
        QVERIFY(!form->isValid());
        Scenario s = scenarioForRobot(kPanda);
        s.path.waypoints[1][3] = 10.0 * M_PI / 180.0;
        const QString expected = waypointLimitError(pandaModel(), s.path.waypoints);
        QVERIFY(expected.startsWith(QStringLiteral("path.waypoints[1][3]: ")));
        QCOMPARE(form->firstError(), expected);
        const auto *reason = form->findChild<QLabel *>(QStringLiteral("path.waypoints.reason"));
        QVERIFY(reason && reason->isVisible());
        QCOMPARE(reason->text(), expected);
        QVERIFY(table->item(1, 3)->background() != table->item(1, 2)->background());
        QVERIFY(!form->scenario().has_value());
        // Not a number: named by waypoint and joint.
        table->item(1, 3)->setText(QStringLiteral("x"));
        QVERIFY(form->firstError().contains(QStringLiteral("waypoint 2, panda_joint4")));
        // Back within the limit: accepted, in radians.
        table->item(1, 3)->setText(QStringLiteral("-60"));
        QVERIFY2(form->isValid(), qPrintable(form->firstError()));
        QCOMPARE(form->scenario()->path.waypoints[1][3], -60.0 * M_PI / 180.0);
        QVERIFY(!reason->isVisible());
    }

    void pathCsv_replacesTheWaypoints_andABadOneIsNamed()
    {
        WindowFixture f;
        choosePanda(f);
        ScenarioForm *form = f.window->form();
        // A recorded path of the 7 joints: the default path's first waypoint and a slow swing.
        const Eigen::VectorXd start = scenarioForRobot(kPanda).path.waypoints.front();
        PathSamples samples;
        samples.t = Eigen::VectorXd::LinSpaced(201, 0.0, 2.0);
        samples.q.resize(7, 201);
        for (int k = 0; k < 201; ++k)
            samples.q.col(k) = start.array() + 0.2 * (1.0 - std::cos(M_PI * samples.t[k])) / 2.0;
        QTemporaryDir dir;
        const QString good = dir.filePath(QStringLiteral("path.csv"));
        writeFileAtomically(good, pathCsv(samples));
        form->usePathFile(good);
        QVERIFY2(form->isValid(), qPrintable(form->firstError()));
        QCOMPARE(form->scenario()->path.kind, PathKind::File);
        QCOMPARE(form->scenario()->path.fileAngles, samples.q);
        QVERIFY(!form->waypointEditor()->table()->isVisible());

        // A file for another robot: refused naming the file and line; the path stays.
        const QString bad = dir.filePath(QStringLiteral("six.csv"));
        samples.q.conservativeResize(6, Eigen::NoChange);
        writeFileAtomically(bad, pathCsv(samples));
        form->usePathFile(bad);
        QCOMPARE(form->scenario()->path.file, QFileInfo(good).absoluteFilePath());
        const QList<QLabel *> other = form->findChildren<QLabel *>();
        bool named = false;
        for (const QLabel *label : other)
            named = named || (label->isVisible() &&
                              label->text().startsWith(QStringLiteral("path.file: ") + bad +
                                                       QStringLiteral(": line 1")));
        QVERIFY(named);

        form->useWaypoints();
        QVERIFY(form->isValid());
        QCOMPARE(form->scenario()->path.kind, PathKind::Waypoints);
        QVERIFY(form->waypointEditor()->table()->isVisible());
    }

    void sevenAxisSession_learnsAcceptsAppliesAndExports()
    {
        WindowFixture f;
        choosePanda(f);
        auto *trials = f.window->findChild<QLineEdit *>(QStringLiteral("estimator.iterations"));
        trials->setText(QStringLiteral("3"));
        emit trials->textEdited(trials->text());
        QVERIFY2(f.window->form()->isValid(), qPrintable(f.window->form()->firstError()));
        SessionController *c = f.window->controller();
        QVERIFY(f.click("connectButton"));
        QTRY_VERIFY_WITH_TIMEOUT(c->lastCheck().has_value(), 20000);
        QVERIFY2(c->lastCheck()->passed(), qPrintable(c->lastCheck()->reason()));
        QSignalSpy finished(c, &SessionController::runFinished);
        f.window->actions()->runAll->trigger();
        QVERIFY(finished.wait(120000));
        QVERIFY(finished.constLast().at(0).toBool());
        QCOMPARE(c->estimates().size(), 4);
        const int m = pandaModel().parameterCount();

        // Estimates: no column per parameter but the path-torque error against the truth,
        // falling as the trials learn.
        const ConvergenceTableModel *table = f.window->tableModel();
        QCOMPARE(table->columnOf(ConvergenceTableModel::Column::Parameter, 0), -1);
        const int path = table->columnOf(ConvergenceTableModel::Column::PathTorque);
        QVERIFY(path > 0);
        const EstimateFigures &figures = c->estimateFigures();
        QCOMPARE(figures.vsTruth.size(), 4);
        for (int k = 0; k < 4; ++k)
            QCOMPARE(table->index(k, path).data(Qt::UserRole).toDouble(), figures.vsTruth[k]);
        QVERIFY2(
            figures.vsTruth[3] < figures.vsTruth[0] / 5.0,
            qPrintable(QStringLiteral("%1 -> %2").arg(figures.vsTruth[0]).arg(figures.vsTruth[3])));

        // Parameters: a row each, grouped by link, the estimates as columns.
        const ParameterTableModel *params = f.window->parameterModel();
        QCOMPARE(params->rowCount(), m);
        QCOMPARE(params->index(0, 0).data().toString(), QStringLiteral("link 1 (panda_link1)"));
        const QList<ParameterInfo> info = pandaModel().parameters();
        for (int i = 0; i < m; ++i) {
            QCOMPARE(params->index(i, 1).data().toString(), info[i].name);
            for (int k = 0; k < 4; ++k)
                QCOMPARE(
                    params->index(i, params->columnOf(ParameterTableModel::Column::Estimate, k))
                        .data(Qt::UserRole)
                        .toDouble(),
                    c->estimates()[k][i]);
        }
        QVERIFY(figures.consistencyChecked);
        // The Real body column: a link that is no real body, one that is not plausible, or one
        // that is both, as the newest estimate's verdict says.
        const int body = params->columnOf(ParameterTableModel::Column::Consistent);
        for (int i = 0; i < m; ++i) {
            const QString group = info[i].group, mark = params->index(i, body).data().toString();
            if (group.isEmpty())
                continue;
            const QString expected =
                figures.inconsistentGroups.contains(group)  ? QStringLiteral("\u2717 no")
                : figures.implausibleGroups.contains(group) ? QStringLiteral("\u26a0 not plausible")
                                                            : QStringLiteral("\u2713");
            QCOMPARE(mark, expected);
        }

        // The tracking plot: a joint each, selectable.
        TrackingErrorPlot *plot = f.window->plot();
        QCOMPARE(plot->jointCount(), 7);
        QCOMPARE(plot->trialCount(), 3);

        // Accept the last, apply, export the parameter file, the URDF and the report.
        // The accept queues behind the worker's check of the next trial, posted after the
        // series (a plan and the nearest consistent estimate: 0.4 s here on an idle core,
        // 6.7 s once in CI beside other tests), so wait as long as for the other worker calls.
        QVERIFY(f.click("acceptButton"));
        QTRY_COMPARE_WITH_TIMEOUT(c->acceptedIndex().value_or(-1), 3, 30000);
        f.window->setApplyConfirmation([](const ApplyPreview &) { return true; });
        QSignalSpy applied(c, &SessionController::applied);
        QTRY_VERIFY(f.button("applyButton")->isEnabled());
        QVERIFY(f.click("applyButton"));
        QVERIFY(applied.wait(20000));
        QCOMPARE(c->storedParameters(), c->estimates()[3]);

        QTemporaryDir out;
        QSignalSpy done(f.window->files(), &FileController::finished);
        f.window->files()->exportParameterFileTo(out.filePath(QStringLiteral("panda.json")));
        QVERIFY(done.wait(20000));
        QVERIFY2(done.constLast().at(1).toBool(), qPrintable(done.constLast().at(0).toString()));
        const ParameterFileContent content = parameterFileFromJson(
            readFile(out.filePath(QStringLiteral("panda.json"))), QStringLiteral("panda.json"));
        QCOMPARE(content.values, c->estimates()[3]);
        // The whole model: standard parameters with the estimate's base parameters, and what
        // the trials determined of each where the session knows it.
        QCOMPARE(int(content.standardParameters.size()), pandaModel().standardCount());
        const Eigen::VectorXd fromStandard = pandaModel().baseFromStandard(content.standardValues);
        QVERIFY2((fromStandard - c->estimates()[3]).norm() <= 1e-9 * c->estimates()[3].norm(),
                 qPrintable(QString::number((fromStandard - c->estimates()[3]).norm())));
        QVERIFY(content.standardDetermined.empty() ||
                int(content.standardDetermined.size()) == pandaModel().standardCount());

        QVERIFY(f.window->actions()->exportUrdf->isEnabled());
        const QString urdf = out.filePath(QStringLiteral("panda-identified.urdf"));
        f.window->files()->exportIdentifiedUrdfTo(urdf);
        QVERIFY(done.wait(20000));
        QVERIFY2(done.constLast().at(1).toBool(), qPrintable(done.constLast().at(0).toString()));
        // Read back by urdfdom: the same robot, every link a real body, and its torques those
        // of an estimate consistent with the accepted one (the same base parameters when the
        // accepted estimate is consistent, else its nearest consistent estimate's).
        const SerialChain identified = readUrdfChain(urdf);
        QCOMPARE(identified.dof(), 7);
        QCOMPARE(readFile(urdf).contains("What the data determined."),
                 !content.standardDetermined.empty());
        const Eigen::VectorXd standard = pandaModel().standardOf(identified);
        for (const LinkConsistency &l : checkConsistency(standard, 7, 1e-9))
            QVERIFY2(l.consistent, qPrintable(QString::number(l.link)));
        const Eigen::VectorXd written = pandaModel().baseFromStandard(standard);
        if (figures.inconsistentGroups.isEmpty()) {
            QVERIFY2((written - c->estimates()[3]).norm() <= 1e-9 * c->estimates()[3].norm(),
                     qPrintable(QString::number((written - c->estimates()[3]).norm())));
        } else {
            QVERIFY((written - c->estimates()[3]).norm() > 0.0);
        }

        f.window->files()->exportReportTo(out.filePath(QStringLiteral("report.pdf")));
        QVERIFY2(done.constLast().at(1).toBool(), qPrintable(done.constLast().at(0).toString()));
        const QByteArray pdf = readFile(out.filePath(QStringLiteral("report.pdf")));
        QVERIFY(pdf.startsWith("%PDF"));
        // The summary page, then the parameters on pages of their own.
        static const QRegularExpression pageObject(QStringLiteral("/Type\\s*/Page[^s]"));
        QVERIFY(QString::fromLatin1(pdf).count(pageObject) >= 2);
    }
};

QTEST_MAIN(TestSerialArmWindow)
#include "tst_ui_serialarm.moc"
