// One long-lived connection to a session store (a station's file or a
// central store, see openSessionSource) on a thread of its own, for a
// window that must never wait on it: jobs are queued, run in order on
// the worker with the same connection, and report back through callbacks
// the caller posts to its own thread. The connection is opened read-write
// on the first job (migrating the file once, not per action) and opened
// again on the next job when opening failed.
#pragma once

#include <condition_variable>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

namespace tactiscope::core::storage {

class SessionSource;

class StoreWorker {
public:
    using Job = std::function<void(SessionSource&)>;
    using Failure = std::function<void(const std::string& error)>;

    explicit StoreWorker(std::string path);
    ~StoreWorker();  // finishes the queued jobs, then closes the store
    StoreWorker(const StoreWorker&) = delete;
    StoreWorker& operator=(const StoreWorker&) = delete;

    const std::string& path() const { return m_path; }
    // Runs `job` after the jobs posted before it. `failed` gets the message
    // when the store cannot be opened or the job throws (StorageError or
    // another std::exception); both run on the worker thread.
    void post(Job job, Failure failed);

private:
    void run(const std::stop_token& stop);

    const std::string m_path;
    std::unique_ptr<SessionSource> m_store;  // the worker's only
    std::mutex m_mutex;
    std::condition_variable_any m_wake;
    std::deque<std::pair<Job, Failure>> m_jobs;
    std::jthread m_thread;  // last: started when the rest exists
};

}  // namespace tactiscope::core::storage
