// TaskThreads: every index runs once per run, on its own thread, and errors reach the caller.
#include "identify/TaskThreads.h"

#include <QTest>
#include <atomic>
#include <stdexcept>

using namespace learnid;

class TestTaskThreads : public QObject
{
    Q_OBJECT

private slots:
    void everyIndexRunsOncePerRun();
    void anExceptionOfAnyThread_reachesTheCaller();
};

void TestTaskThreads::everyIndexRunsOncePerRun()
{
    for (const int count : {0, 1, 2, 3}) {
        TaskThreads threads(count);
        QCOMPARE(threads.count(), std::max(count, 1));
        for (int run = 0; run < 50; ++run) {
            std::vector<std::atomic<int>> calls(size_t(threads.count()));
            std::vector<std::thread::id> ids(size_t(threads.count()));
            threads.run([&](int t) {
                ++calls[size_t(t)];
                ids[size_t(t)] = std::this_thread::get_id();
            });
            for (int t = 0; t < threads.count(); ++t) {
                QCOMPARE(calls[size_t(t)].load(), 1);
                QCOMPARE(ids[size_t(t)] == std::this_thread::get_id(), t == 0);
            }
        }
    }
    QVERIFY(TaskThreads::available() >= 1 && TaskThreads::available() <= 2);
}

void TestTaskThreads::anExceptionOfAnyThread_reachesTheCaller()
{
    TaskThreads threads(2);
    for (const int failing : {0, 1}) {
        QVERIFY_THROWS_EXCEPTION(std::runtime_error, threads.run([&](int t) {
            if (t == failing)
                throw std::runtime_error("failed");
        }));
    }
    std::atomic<int> total{0}; // still usable after an error
    threads.run([&](int t) { total += t + 1; });
    QCOMPARE(total.load(), 3);
}

QTEST_GUILESS_MAIN(TestTaskThreads)
#include "tst_taskthreads.moc"
