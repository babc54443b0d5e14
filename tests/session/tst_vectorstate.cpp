// The numerical entry points leave the AVX upper halves clean after Qt code dirtied them (see
// model/VectorState.h): the processor itself reports it, through XGETBV with ECX = 1, whose
// bit 2 (XINUSE[AVX]) is 0 only when the upper halves of YMM0-15 are in their initial state.
#include "identify/LearningLaw.h"
#include "model/ModelFactory.h"
#include "model/VectorState.h"
#include "session/SafetyCheck.h"
#include "session/ScenarioRobot.h"
#include "session/TrialPlanner.h"

#include <QHash>
#include <QTest>

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <cpuid.h>
#define LEARNID_X86_64 1
#endif

using namespace learnid;

namespace {

#ifdef LEARNID_X86_64
bool canReportUpperState()
{
    unsigned a = 0, b = 0, c = 0, d = 0;
    if (!__get_cpuid(1, &a, &b, &c, &d) || !(c & bit_OSXSAVE) || !(c & bit_AVX))
        return false;
    return __get_cpuid_count(0xd, 1, &a, &b, &c, &d) && (a & (1u << 2)); // XGETBV ECX = 1
}

bool upperStateInUse()
{
    unsigned lo = 0, hi = 0;
    asm volatile("xgetbv" : "=a"(lo), "=d"(hi) : "c"(1));
    return lo & (1u << 2);
}
#endif

// What the application does all the time: a QHash insert (meta types, signals, logging).
void runQtHashCode()
{
    QHash<QString, int> table;
    table.insert(QStringLiteral("learnid::TrialResult"), 1);
    QVERIFY(table.contains(QStringLiteral("learnid::TrialResult")));
}

} // namespace

class TestVectorState : public QObject
{
    Q_OBJECT

private slots:
    void init();
    void clear_leavesTheUpperHalvesClean();
    void kernels_runAndReturnWithCleanState();

private:
    // Dirties the state as Qt does; skips where this CPU and Qt leave nothing to clear.
    void dirtyOrSkip();
};

void TestVectorState::init()
{
#ifndef LEARNID_X86_64
    QSKIP("only x86-64 processors have the SSE/AVX register state this guards");
#else
    if (!canReportUpperState())
        QSKIP("this processor cannot report whether the AVX upper halves are in use "
              "(no XGETBV with ECX = 1)");
#endif
}

void TestVectorState::dirtyOrSkip()
{
#ifdef LEARNID_X86_64
    runQtHashCode();
    if (!upperStateInUse())
        QSKIP("Qt's QHash leaves no AVX state behind on this processor (no 256-bit VAES "
              "hashing): there is nothing to clear");
#endif
}

void TestVectorState::clear_leavesTheUpperHalvesClean()
{
    dirtyOrSkip();
#ifdef LEARNID_X86_64
    QVERIFY(upperStateInUse());
    clearUpperVectorState();
    QVERIFY(!upperStateInUse());
#endif
}

void TestVectorState::kernels_runAndReturnWithCleanState()
{
#ifdef LEARNID_X86_64
    const Scenario s;
    const auto model = makeRobotModel(s.model, s.urdf);
    const TrialPlanner planner(s, model);

    dirtyOrSkip();
    const TrialPlan plan = planner.plan(s.initialParameters);
    QVERIFY2(!upperStateInUse(), "planning");

    dirtyOrSkip();
    const SafetyVerdict verdict = checkTrial(*model, s.initialParameters, plan, 0.0);
    QVERIFY2(!upperStateInUse(), "pre-trial check");
    QVERIFY(verdict.stable);

    // Each progress report runs Qt code again; the last comes after the last sample.
    const auto robot = makeSimulatedRobot(s, model);
    TrialMonitor monitor;
    int reports = 0;
    monitor.progress = [&reports](int, int) {
        runQtHashCode();
        ++reports;
    };
    dirtyOrSkip();
    const TrialRecord record = robot->runTrial(plan, monitor);
    QVERIFY2(!upperStateInUse(), "simulation with progress reports");
    QVERIFY(record.completed());
    QVERIFY(reports > 0);

    for (const QString &id : knownLearningLaws()) {
        const auto law = makeLearningLaw(id);
        std::shared_ptr<LawCache> cache;
        dirtyOrSkip();
        const ParameterUpdate up =
            law->update(*model, {{&plan, &record, &cache}}, s.initialParameters, s.estimator);
        QVERIFY2(!upperStateInUse(), qPrintable(id));
        QVERIFY(up.phi.allFinite());
    }
#endif
}

QTEST_GUILESS_MAIN(TestVectorState)
#include "tst_vectorstate.moc"
