// StoreWorker: a job queue drained by one thread that owns the connection.
#include "core/storage/StoreWorker.h"

#include "core/storage/OpenSessionSource.h"

#include <exception>
#include <filesystem>

namespace tactiscope::core::storage {

StoreWorker::StoreWorker(std::string path)
    : m_path(std::move(path)),
      m_thread([this](const std::stop_token& stop) { run(stop); })
{
}

StoreWorker::~StoreWorker()
{
    m_thread.request_stop();
    m_wake.notify_all();
    m_thread.join();  // before the queue and the store go
}

void StoreWorker::post(Job job, Failure failed)
{
    {
        const std::scoped_lock lock(m_mutex);
        m_jobs.emplace_back(std::move(job), std::move(failed));
    }
    m_wake.notify_one();
}

void StoreWorker::run(const std::stop_token& stop)
{
    for (;;) {
        std::pair<Job, Failure> next;
        {
            std::unique_lock lock(m_mutex);
            // Stopping waits for the queue to drain: a verdict posted just
            // before the window closed is still written.
            m_wake.wait(lock, stop, [this] { return !m_jobs.empty(); });
            if (m_jobs.empty()) return;
            next = std::move(m_jobs.front());
            m_jobs.pop_front();
        }
        try {
            if (!m_store) {
                // A first write may come before any session: the folder too.
                if (!isCentralStoreAddress(m_path)) {
                    const auto folder = std::filesystem::absolute(m_path).parent_path();
                    std::error_code ignored;
                    std::filesystem::create_directories(folder, ignored);
                }
                m_store = openSessionSource(m_path);
            }
            next.first(*m_store);
        } catch (const std::exception& e) {
            if (next.second) next.second(e.what());
        }
    }
}

}  // namespace tactiscope::core::storage
