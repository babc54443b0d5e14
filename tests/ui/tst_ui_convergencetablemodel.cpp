#include "model/ModelFactory.h"
#include "robot/SimulatedRobot.h"
#include "session/CommissioningSession.h"
#include "ui/ConvergenceTableModel.h"

#include <QtTest>

using namespace learnid;
using Column = ConvergenceTableModel::Column;

class TestConvergenceTableModel : public QObject
{
    Q_OBJECT

private:
    std::unique_ptr<CommissioningSession> m_session;

    QVariant cell(const ConvergenceTableModel &model, int row, Column kind, int p = 0,
                  int role = Qt::UserRole)
    {
        return model.index(row, model.columnOf(kind, p)).data(role);
    }

private slots:
    void initTestCase()
    {
        Scenario scenario;
        const auto model = makeRobotModel(scenario.model, scenario.urdf);
        auto robot = std::make_shared<SimulatedRobot>(model, scenario.simulation.trueParameters);
        m_session = std::make_unique<CommissioningSession>(scenario, model, robot);
        QVERIFY(m_session->runTrials(3));
    }

    void rows_matchTheSessionsEstimates()
    {
        ConvergenceTableModel model;
        model.setParameters(m_session->model().parameters(), m_session->robot().trueParameters());
        model.setHistory(m_session->history(), m_session->estimates());
        const auto &estimates = m_session->estimates();
        QCOMPARE(model.rowCount(), int(estimates.size()));
        QCOMPARE(model.rowCount(), 4);
        for (int k = 0; k < estimates.size(); ++k) {
            QCOMPARE(cell(model, k, Column::Estimate).toInt(), k);
            for (int p = 0; p < 3; ++p)
                QCOMPARE(cell(model, k, Column::Parameter, p).toDouble(), estimates[k][p]);
        }
        QCOMPARE(
            model.headerData(model.columnOf(Column::Parameter, 0), Qt::Horizontal, Qt::DisplayRole)
                .toString(),
            QStringLiteral("%1 [%2]").arg(m_session->model().parameters()[0].name,
                                          m_session->model().parameters()[0].unit));
    }

    void figures_comeFromTheTrialsThatRanAndProduced()
    {
        ConvergenceTableModel model;
        model.setParameters(m_session->model().parameters(), m_session->robot().trueParameters());
        model.setHistory(m_session->history(), m_session->estimates());
        const auto &history = m_session->history();
        const auto &estimates = m_session->estimates();
        QVERIFY(!cell(model, 0, Column::RelativeChange).isValid());
        QVERIFY(!cell(model, 0, Column::Condition).isValid());
        for (int k = 0; k < 3; ++k) // trial k ran with estimate k
            QCOMPARE(cell(model, k, Column::MaxError).toDouble(),
                     history[k].maxTrackingErrorDeg.maxCoeff());
        QVERIFY(!cell(model, 3, Column::MaxError).isValid()); // estimate 3 has not run yet
        for (int k = 1; k < 4; ++k) {
            QCOMPARE(cell(model, k, Column::Condition).toDouble(),
                     history[k - 1].update->condition);
            // The largest signed per-parameter change, as the CLI table shows it.
            double change = 0.0;
            for (int i = 0; i < 3; ++i) {
                const double r = 100.0 * (estimates[k][i] / estimates[k - 1][i] - 1.0);
                if (std::abs(r) > std::abs(change))
                    change = r;
            }
            QVERIFY(std::abs(cell(model, k, Column::RelativeChange).toDouble() - change) <
                    1e-9 * (1.0 + std::abs(change)));
            QVERIFY(cell(model, k, Column::Observable, 0, Qt::DisplayRole)
                        .toString()
                        .startsWith(QStringLiteral("all")));
        }
        const Eigen::VectorXd truth = *m_session->robot().trueParameters();
        for (int p = 0; p < 3; ++p)
            QCOMPARE(cell(model, 3, Column::TruthError, p).toDouble(),
                     100.0 * (estimates[3][p] - truth[p]) / truth[p]);
        QVERIFY(std::abs(cell(model, 3, Column::TruthError, 1).toDouble()) < 1.0); // converged
    }

    void keptDirections_areMarked()
    {
        QVector<TrialResult> history = m_session->history();
        history[1].update->observable = {true, false, true};
        ConvergenceTableModel model;
        model.setParameters(m_session->model().parameters(), std::nullopt);
        model.setHistory(history, m_session->estimates());
        const QString mark = cell(model, 2, Column::Observable, 0, Qt::DisplayRole).toString();
        QVERIFY2(mark.contains(m_session->model().parameters()[1].name), qPrintable(mark));
        QVERIFY(mark.startsWith(QChar(0x26a0)));
        QCOMPARE(model.columnOf(Column::TruthError), -1); // no truth, no truth columns
    }

    void failedTrial_isListedWithItsStatus()
    {
        QVector<TrialResult> history = m_session->history();
        QVector<Eigen::VectorXd> estimates = m_session->estimates();
        TrialResult cancelled = history.constLast();
        cancelled.index = 3;
        cancelled.update.reset();
        cancelled.record.status = TrialStatus::Cancelled;
        history.append(cancelled);
        ConvergenceTableModel model;
        model.setParameters(m_session->model().parameters(), std::nullopt);
        model.setHistory(history, estimates);
        QCOMPARE(model.rowCount(), 4);
        const QString trials = cell(model, 3, Column::Trials, 0, Qt::DisplayRole).toString();
        QVERIFY2(trials.contains(trialStatusName(TrialStatus::Cancelled)), qPrintable(trials));
    }

    void acceptedAndApplied_areShownInTheStateColumn()
    {
        ConvergenceTableModel model;
        model.setParameters(m_session->model().parameters(), std::nullopt);
        model.setHistory(m_session->history(), m_session->estimates());
        model.setAccepted(2);
        model.setApplied(2);
        const QString state = cell(model, 2, Column::State, 0, Qt::DisplayRole).toString();
        QVERIFY(!state.isEmpty());
        QVERIFY(cell(model, 1, Column::State, 0, Qt::DisplayRole).toString().isEmpty());
        QVERIFY(model.index(2, 0).data(Qt::FontRole).value<QFont>().bold());
    }
};

QTEST_MAIN(TestConvergenceTableModel)
#include "tst_ui_convergencetablemodel.moc"
