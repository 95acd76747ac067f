// Limit alarms on the acquisition thread: a LimitWatch (core/trigger) per
// limit on its quantity's every sample, and the alarms raised and cleared
// since the owner last took them, with their stream times. The live
// session tells them, shows which are raised, and stores each as an
// `alarm` event naming its limit.
//
// Threading: consume() on the acquisition thread; the rest from the owner.
#pragma once

#include "core/BlockSink.h"
#include "core/trigger/LimitWatch.h"
#include "devices/session/LiveQuantity.h"

#include <mutex>
#include <vector>

namespace tactiscope::devices::session {

// An alarm raised or cleared, at a stream time, with the limit it belongs
// to and that limit's unit.
struct LimitAlarm {
    core::trigger::LimitSpec limit;
    std::string unit;
    core::trigger::LimitChange change;
    double time_s = 0.0;
};

class LimitAlarms final : public core::BlockSink {
public:
    struct Watched {
        core::trigger::LimitSpec limit;
        QuantityReader reader;
    };
    // Replaces the limits watched (none: no alarms); those raised are
    // forgotten. Throws std::invalid_argument for a limit LimitWatch refuses.
    void set(std::vector<Watched> watched, double sampleRate_hz);
    // Each limit's quantity from another processor (one rebuilt), in the
    // order they were set; the alarms' states kept.
    void replaceReaders(std::vector<QuantityReader> readers);

    void consume(const core::SampleBlock& block) override;

    // The changes since the last call, in time order per limit.
    std::vector<LimitAlarm> take();

private:
    struct Watch {
        core::trigger::LimitWatch watch;
        QuantityReader reader;
    };
    mutable std::mutex m_mutex;
    std::vector<Watch> m_watches;
    std::vector<LimitAlarm> m_changes;
    std::vector<double> m_values;
    std::vector<core::trigger::LimitChange> m_step;
};

}  // namespace tactiscope::devices::session
