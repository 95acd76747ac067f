// Acquisition: the per-device worker loop and its counters.
#include "devices/Acquisition.h"

#include "core/SampleBlock.h"
#include "devices/SteadyClock.h"

#include <chrono>
#include <exception>
#include <stdexcept>

namespace tactiscope::devices {
namespace {

// Bounds how long stop() can wait for a blocked read.
constexpr std::chrono::milliseconds kReadTimeout{100};
constexpr double kQueuedAtStart_s = 0.5;

}  // namespace

Acquisition::Acquisition(std::unique_ptr<BlockSource> source)
    : m_source(std::move(source))
{
    if (!m_source) throw std::invalid_argument("acquisition needs a source");
}

Acquisition::~Acquisition()
{
    stop();
}

void Acquisition::addSink(std::shared_ptr<core::BlockSink> sink)
{
    if (m_worker.joinable()) throw std::logic_error("sinks must be added before the acquisition starts");
    m_sinks.push_back(std::move(sink));
}

void Acquisition::start()
{
    if (m_worker.joinable()) return;
    {
        const std::lock_guard lock(m_statsMutex);
        m_stats = AcquisitionStats{};
        m_stats.state = AcquisitionState::Streaming;
        m_rateMeter.reset();
    }
    m_worker = std::jthread([this](const std::stop_token& token) { run(token); });
}

void Acquisition::stop()
{
    if (!m_worker.joinable()) return;
    m_worker.request_stop();
    m_worker.join();
    const std::lock_guard lock(m_statsMutex);
    if (m_stats.state == AcquisitionState::Streaming) m_stats.state = AcquisitionState::Idle;
}

AcquisitionStats Acquisition::stats() const
{
    const std::lock_guard lock(m_statsMutex);
    return m_stats;
}

void Acquisition::fail(const std::string& message)
{
    const std::lock_guard lock(m_statsMutex);
    m_stats.state = AcquisitionState::Failed;
    m_stats.error = message;
}

void Acquisition::run(const std::stop_token& stopToken)
{
    core::SampleBlock block;
    std::optional<std::uint64_t> previousEnd;
    std::optional<double> firstBlock_s;
    while (!stopToken.stop_requested()) {
        ReadStatus status = ReadStatus::Failed;
        try {
            status = m_source->readBlock(block, kReadTimeout);
        } catch (const std::exception& e) {
            fail(e.what());
            return;
        }
        if (status == ReadStatus::Timeout) continue;
        if (status == ReadStatus::Finished) {
            const std::lock_guard lock(m_statsMutex);
            m_stats.state = AcquisitionState::Finished;
            return;
        }
        if (status == ReadStatus::Failed) {
            fail(m_source->lastError());
            return;
        }

        try {
            if (auto grown = m_source->takeGrownChannels()) {
                for (const auto& sink : m_sinks) sink->channelsGrew(*grown);
                const std::lock_guard lock(m_statsMutex);
                m_grownChannels = std::move(grown);
            }
            for (const auto& sink : m_sinks) sink->consume(block);
        } catch (const std::exception& e) {
            fail(std::string("processing failed: ") + e.what());
            return;
        }

        const std::lock_guard lock(m_statsMutex);
        if (previousEnd) m_stats.samplesLost += block.samplesLostAfter(*previousEnd);
        m_stats.samples += block.sampleCount();
        ++m_stats.blocks;
        const double now = steadySeconds();
        // What the handshake queued (a text board's lines, held while its
        // rate was timed) comes at once: the rate is measured after it.
        if (!firstBlock_s) firstBlock_s = now;
        if (now - *firstBlock_s >= kQueuedAtStart_s) m_rateMeter.observe(now, m_stats.samples);
        m_stats.lastBlockHost_s = now;
        m_stats.measuredRate_hz = m_rateMeter.rate_hz();
        previousEnd = block.endSampleIndex();
    }
}

}  // namespace tactiscope::devices
