// A session's signal setup as columns of its CSV export: each filtered
// channel ("a.filtered") and each math channel the session recorded,
// computed by the same chain that ran live over the stored samples from
// the session's first (core/signal/SignalChain.h), so the export holds the
// series the operator saw, to the bit from the recording's first sample.
// The chain runs on from one window to the next; a window before where it
// stands starts it again from the session's first sample.
#pragma once

#include "core/signal/SignalChain.h"
#include "core/storage/SessionExport.h"
#include "core/storage/SessionSource.h"
#include "core/storage/TraceWindow.h"

#include <memory>

namespace tactiscope::core::signal {

class SignalColumns final : public storage::ComputedColumns {
public:
    static constexpr std::uint64_t kExactLimit = 200'000;  // samples per overview
    // `derived` (may be null) is written first; taken only when the setup
    // runs. Throws std::invalid_argument (math::MathError among them) for a
    // setup the session cannot run.
    SignalColumns(storage::SessionSource& store, std::int64_t session, SignalSetup setup,
                  std::unique_ptr<storage::ComputedColumns>&& derived);

    std::vector<ChannelDescriptor> channels() const override;
    std::string basis() const override;
    std::vector<std::vector<double>> read(std::uint64_t first, std::uint64_t count) override;
    // About `points` min/max stretches of one of its columns (a review
    // lane); empty for a range longer than kExactLimit.
    std::vector<storage::OverviewPoint> overview(std::size_t column, std::uint64_t first, std::uint64_t count,
                                                 std::size_t points);

private:
    // Runs the chain over stored samples [m_next, end), keeping what falls
    // in [keepFrom, end) into `kept`.
    void run(std::uint64_t end, std::uint64_t keepFrom, std::vector<std::vector<double>>& kept);

    storage::SessionSource& m_store;
    std::int64_t m_session;
    SignalSetup m_setup;
    std::vector<ChannelDescriptor> m_channels;  // the stored ones
    double m_rate_hz = 0.0;
    std::unique_ptr<SignalChain> m_chain;  // made before `derived` is taken
    std::unique_ptr<storage::ComputedColumns> m_derived;
    std::uint64_t m_next = 0;  // the stored sample the chain reads next
    LiveCursor m_cursor;
    // The last window read, which the lanes of one plot ask for in turn.
    std::uint64_t m_cachedFirst = 0, m_cachedCount = 0;
    std::vector<std::vector<double>> m_cached;
};

// The columns of a CSV export of `session`: `derived` (may be null), then
// the filtered and math channels of its recorded signal setup, if it has
// one. A setup this program cannot run is left out, and `problem` says why
// (the samples still go out); empty otherwise.
std::unique_ptr<storage::ComputedColumns> withRecordedSignal(storage::SessionSource& store, std::int64_t session,
                                                             std::unique_ptr<storage::ComputedColumns> derived,
                                                             std::string& problem);

// The same for each device's part of a session of several devices, as the
// export asks for them (storage::PartColumns). What cannot be run of a
// part's setup is added to `problems`, once, which must outlive it.
storage::PartColumns recordedSignalOfParts(storage::SessionSource& store, std::vector<std::string>& problems);

// The filtered and math channels `session` was recorded with, as review
// lanes after its own; none without a setup, and `problem` says why a
// setup this program cannot run is left out.
std::vector<std::unique_ptr<storage::LaneSource>> recordedSignalLanes(storage::SessionSource& store,
                                                                      std::int64_t session, std::string& problem);

}  // namespace tactiscope::core::signal
