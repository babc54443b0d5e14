#include "identify/TaskThreads.h"

#include <utility>

namespace learnid {

TaskThreads::TaskThreads(int threads)
{
    try {
        for (int t = 1; t < threads; ++t)
            m_helpers.emplace_back([this, t] { serve(t); });
    } catch (...) {
        stop(); // the helpers started so far; the destructor does not run
        throw;
    }
}

TaskThreads::~TaskThreads()
{
    stop();
}

void TaskThreads::stop()
{
    {
        const std::lock_guard<std::mutex> lock(m_mutex);
        m_stop = true;
    }
    m_start.notify_all();
    for (std::thread &helper : m_helpers)
        helper.join();
}

int TaskThreads::available()
{
    return std::thread::hardware_concurrency() >= 2 ? 2 : 1;
}

void TaskThreads::run(const std::function<void(int)> &task)
{
    {
        const std::lock_guard<std::mutex> lock(m_mutex);
        m_task = &task;
        m_pending = int(m_helpers.size());
        ++m_generation;
    }
    m_start.notify_all();
    std::exception_ptr own;
    try {
        task(0);
    } catch (...) {
        own = std::current_exception();
    }
    std::exception_ptr helpers;
    {
        std::unique_lock<std::mutex> lock(m_mutex);
        m_done.wait(lock, [this] { return m_pending == 0; });
        m_task = nullptr;
        std::swap(helpers, m_error);
    }
    if (own)
        std::rethrow_exception(own);
    if (helpers)
        std::rethrow_exception(helpers);
}

void TaskThreads::serve(int index)
{
    unsigned seen = 0;
    std::unique_lock<std::mutex> lock(m_mutex);
    for (;;) {
        m_start.wait(lock, [&] { return m_stop || m_generation != seen; });
        if (m_stop)
            return;
        seen = m_generation;
        const std::function<void(int)> *task = m_task;
        lock.unlock();
        std::exception_ptr error;
        try {
            (*task)(index);
        } catch (...) {
            error = std::current_exception();
        }
        lock.lock();
        if (error && !m_error)
            m_error = error;
        if (--m_pending == 0)
            m_done.notify_one();
    }
}

} // namespace learnid
