#pragma once

#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace learnid {

/// A fixed number of threads for one long computation: the calling thread and count() - 1
/// helpers that wait between runs. The law's work on a long record (the regressor at every
/// sample, each joint's filtering and Gram matrices) splits into independent parts; a part's
/// result never depends on the thread that computes it, so one thread gives the same numbers.
class TaskThreads
{
public:
    /// threads >= 1 (fewer count as 1).
    explicit TaskThreads(int threads);
    ~TaskThreads();
    TaskThreads(const TaskThreads &) = delete;
    TaskThreads &operator=(const TaskThreads &) = delete;

    /// The threads worth using here: 2 when the machine has two cores or more, else 1.
    static int available();

    int count() const { return int(m_helpers.size()) + 1; }
    /// task(t) for t = 0 .. count() - 1, t = 0 on the calling thread; returns when all have
    /// returned, then rethrows the first exception any of them threw.
    void run(const std::function<void(int)> &task);

private:
    void serve(int index);
    void stop();

    std::vector<std::thread> m_helpers;
    std::mutex m_mutex;
    std::condition_variable m_start;
    std::condition_variable m_done;
    const std::function<void(int)> *m_task = nullptr;
    unsigned m_generation = 0;
    int m_pending = 0;
    bool m_stop = false;
    std::exception_ptr m_error;
};

} // namespace learnid
