// "Identify from recorded data" on a 7-joint robot (offscreen): the built-in Panda identified
// from a synthetic 1 kHz log with gaps and stale rows (tests/support/SyntheticRobotLog.h), and
// its torque plot read back as drawn: every joint's torque axis must carry readable labels.
// LEARNID_SNAPSHOT_DIR=DIR saves what the test looked at as PNG files in DIR.
#include "../support/SyntheticRobotLog.h"

#include "service/LogIdentificationSummary.h"
#include "ui/LogIdentificationText.h"
#include "ui/MessageBar.h"
#include "ui/RecordedDataDialog.h"
#include "ui/TorqueFitPlot.h"
#include "ui/UiSettings.h"

#include <QAbstractButton>
#include <QComboBox>
#include <QDir>
#include <QFile>
#include <QGraphicsScene>
#include <QGraphicsTextItem>
#include <QLabel>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtCharts/QChart>
#include <QtCharts/QChartView>
#include <QtCharts/QValueAxis>
#include <QtTest>

using namespace learnid;

class TestTorqueFitPlot : public QObject
{
    Q_OBJECT

private slots:
    void pandaDialog_everyJointsAxesReadable_summaryAsTheCliWordsIt();
    void smallAndOffsetTorques_getTicksOfTheirOwn_data();
    void smallAndOffsetTorques_getTicksOfTheirOwn();
};

namespace {

QValueAxis *torqueAxis(const TorqueFitPlot &plot, int joint)
{
    const auto axes = plot.chartView(joint)->chart()->axes(Qt::Vertical);
    return axes.isEmpty() ? nullptr : qobject_cast<QValueAxis *>(axes.first());
}

// The torque axis' labels as the chart draws them, top to bottom: the visible text items left
// of the plot area (Qt Charts draws axis labels as QGraphicsTextItems in the view's scene).
QStringList drawnTorqueLabels(const QChartView *view)
{
    const QRectF plot = view->chart()->plotArea();
    QList<QPair<double, QString>> labels;
    for (QGraphicsItem *item : view->scene()->items()) {
        const auto *text = dynamic_cast<const QGraphicsTextItem *>(item);
        if (!text || !text->isVisible() || text->toPlainText().isEmpty())
            continue;
        const QRectF r = text->sceneBoundingRect();
        if (r.right() <= plot.left() + 2 && r.center().y() >= plot.top() - 1 &&
            r.center().y() <= plot.bottom() + 1)
            labels.append({r.center().y(), text->toPlainText()});
    }
    std::sort(labels.begin(), labels.end());
    QStringList texts;
    for (const auto &label : labels)
        texts << label.second;
    return texts;
}

// Readable: at least three labels, each a number (none cut to "…"), decreasing evenly from top
// to bottom, and the drawn ticks span most of the axis.
QString unreadable(const QChartView *view)
{
    const QStringList labels = drawnTorqueLabels(view);
    const QString all = labels.join(QLatin1Char(' '));
    if (labels.size() < 3)
        return QStringLiteral("labels: %1").arg(all);
    QList<double> values;
    for (const QString &label : labels) {
        bool ok = false;
        values << label.toDouble(&ok);
        if (!ok)
            return QStringLiteral("label \"%1\" (labels: %2)").arg(label, all);
    }
    const double step = values.first() - values.at(1);
    for (int i = 1; i < values.size(); ++i) {
        if (!(step > 0.0) || std::abs(values.at(i - 1) - values.at(i) - step) > 1e-6 * step)
            return QStringLiteral("uneven labels: %1").arg(all);
    }
    return {};
}

} // namespace

void TestTorqueFitPlot::pandaDialog_everyJointsAxesReadable_summaryAsTheCliWordsIt()
{
    QTemporaryDir dir;
    const ChainModel model = test::pandaLogModel();
    const Eigen::VectorXd truth = test::pandaLogTruth(model);
    test::SyntheticLogOptions options;
    options.seconds = 12.0;
    const test::SyntheticLog training = test::syntheticPandaLog(model, truth, options);
    options.seconds = 8.0;
    options.seed = 2;
    const test::SyntheticLog validation = test::syntheticPandaLog(model, truth, options);
    const QString trainingPath = dir.filePath(QStringLiteral("run1.csv"));
    const QString validationPath = dir.filePath(QStringLiteral("run2.csv"));
    for (const auto &[path, csv] :
         {std::pair{trainingPath,
                    test::syntheticLogCsv(training, true, test::pickStaleRows(training, 300, 5))},
          std::pair{validationPath, test::syntheticLogCsv(validation, true)}}) {
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly) && file.write(csv) == csv.size());
    }

    QSettings settings(dir.filePath(QStringLiteral("learnid.ini")), QSettings::IniFormat);
    UiSettings uiSettings(&settings);
    RecordedDataDialog dialog(&uiSettings);
    QHash<RecordedDataPath, QStringList> paths{
        {RecordedDataPath::TrainingLogs, {trainingPath}},
        {RecordedDataPath::ValidationLogs, {validationPath}}};
    dialog.setPathChooser(
        [&paths](RecordedDataPath purpose, const QString &) { return paths.value(purpose); });
    dialog.resize(1440, 940);
    dialog.show();
    auto *robot = dialog.findChild<QComboBox *>(QStringLiteral("recordedRobot"));
    QVERIFY(robot);
    robot->setCurrentIndex(robot->findData(QStringLiteral("panda")));
    for (const char *name : {"addTrainingLogsButton", "addValidationLogsButton", "identifyButton"})
        QTest::mouseClick(dialog.findChild<QAbstractButton *>(QLatin1String(name)), Qt::LeftButton);
    QSignalSpy finished(&dialog, &RecordedDataDialog::identificationFinished);
    QVERIFY(finished.wait(60000));
    QVERIFY2(finished.constFirst().at(0).toBool(), qPrintable(dialog.messageBar()->text()));
    QTest::qWait(50); // the layout of the plots settles

    const QString snapshots = qEnvironmentVariable("LEARNID_SNAPSHOT_DIR");

    const TorqueFitPlot *plot = dialog.plot();
    QCOMPARE(plot->jointCount(), 7);
    // As it opens on a 1920 x 1080 screen, and on a laptop's 1280 x 720 (95 % of it).
    for (const QSize size : {QSize(1440, 940), QSize(1216, 684)}) {
        dialog.resize(size);
        QTest::qWait(50);
        if (!snapshots.isEmpty())
            QVERIFY(dialog.grab().save(QDir(snapshots).filePath(
                QStringLiteral("recorded-data-panda-%1.png").arg(size.height()))));
        for (int j = 0; j < 7; ++j) {
            const QString problem = unreadable(plot->chartView(j));
            QVERIFY2(problem.isEmpty(), qPrintable(QStringLiteral("%1 x %2, joint %3: %4")
                                                       .arg(size.width())
                                                       .arg(size.height())
                                                       .arg(j + 1)
                                                       .arg(problem)));
        }
    }

    // The summary holds the sentences learnid-cli prints (LogIdentificationSummary), escaped.
    const LogIdentificationSummary s = summarizeLogIdentification(*dialog.result());
    const QString summary = dialog.findChild<QLabel *>(QStringLiteral("identifySummary"))->text();
    for (const QString &sentence :
         QStringList{s.robot, s.logs, s.directions, s.undetermined} + s.readings)
        QVERIFY2(summary.contains(sentence.toHtmlEscaped()), qPrintable(sentence));
    QVERIFY(s.readings.constFirst().startsWith(QStringLiteral("run1.csv: 300 stale row")));
    QCOMPARE(s.robot, QStringLiteral("panda (built-in), 7 moving joint(s)."));
}

void TestTorqueFitPlot::smallAndOffsetTorques_getTicksOfTheirOwn_data()
{
    QTest::addColumn<double>("offset");
    QTest::addColumn<double>("amplitude");
    QTest::newRow("tens of N m") << 0.0 << 40.0;
    QTest::newRow("a tenth of a N m") << 0.0 << 0.1;
    QTest::newRow("hundredths") << 0.0 << 0.02;
    QTest::newRow("small beside an offset") << 0.6 << 0.02;
    QTest::newRow("small beside a negative offset") << -1.5 << 0.003;
    QTest::newRow("all but zero") << 0.0 << 1e-6;
}

void TestTorqueFitPlot::smallAndOffsetTorques_getTicksOfTheirOwn()
{
    QFETCH(double, offset);
    QFETCH(double, amplitude);
    const int n = 7, samples = 400;
    Eigen::VectorXd time = Eigen::VectorXd::LinSpaced(samples, 0.0, 8.0);
    Eigen::MatrixXd measured(n, samples);
    for (int j = 0; j < n; ++j) // joints 1 to 6 move tens of N m, joint 7 as the row says
        measured.row(j) = (j == n - 1 ? offset : 10.0 * (j + 1)) +
                          (j == n - 1 ? amplitude : 30.0) * time.array().sin().transpose();
    const Eigen::MatrixXd identified = measured * 1.01, given = measured * 0.9;
    QStringList names;
    for (int j = 1; j <= n; ++j)
        names << QStringLiteral("panda_joint%1").arg(j);
    const QString snapshots = qEnvironmentVariable("LEARNID_SNAPSHOT_DIR");
    // Roomy, and as small as the plot gets in the dialog on a laptop (charts at their least).
    for (const QSize size : {QSize(800, 900), QSize(560, 420)}) {
        TorqueFitPlot plot;
        plot.resize(size);
        plot.show();
        plot.setData(names, time, measured, identified, given);
        QTest::qWait(20);
        if (!snapshots.isEmpty())
            plot.grab().save(
                QDir(snapshots).filePath(QStringLiteral("torque-plot-%1-%2.png")
                                             .arg(QString::fromLatin1(QTest::currentDataTag()))
                                             .arg(size.height())
                                             .replace(QLatin1Char(' '), QLatin1Char('-'))));
        for (int j = 0; j < n; ++j) {
            const QString problem = unreadable(plot.chartView(j));
            QVERIFY2(problem.isEmpty(), qPrintable(QStringLiteral("%1 px high, joint %2: %3")
                                                       .arg(size.height())
                                                       .arg(j + 1)
                                                       .arg(problem)));
        }
        // The axis spans the joint's own torques, not zero too: a small torque beside an offset
        // is drawn over a good part of the chart's height.
        const QValueAxis *axis = torqueAxis(plot, n - 1);
        QVERIFY(axis);
        const double low = std::min({given.row(n - 1).minCoeff(), measured.row(n - 1).minCoeff(),
                                     identified.row(n - 1).minCoeff()});
        const double high = std::max({given.row(n - 1).maxCoeff(), measured.row(n - 1).maxCoeff(),
                                      identified.row(n - 1).maxCoeff()});
        QVERIFY(axis->min() <= low && axis->max() >= high);
        QVERIFY2(high - low >= 0.3 * (axis->max() - axis->min()),
                 qPrintable(QStringLiteral("%1 to %2 on an axis from %3 to %4")
                                .arg(low)
                                .arg(high)
                                .arg(axis->min())
                                .arg(axis->max())));
    }
}

QTEST_MAIN(TestTorqueFitPlot)
#include "tst_ui_torquefitplot.moc"
