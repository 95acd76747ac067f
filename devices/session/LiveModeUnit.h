// One mode's live part, as the live session builds it for each mode the
// device's channels feed (Scopy's plugins and sigrok's decoders are the
// model: the host asks, the unit knows its mode): its processor on the
// acquisition thread, the zero it reads on, and what it moves from the
// processor into the session's lists and, while recording in its mode,
// into the store. LiveSession asks its units instead of switching on the
// mode. Each mode's unit is a file of devices/session/modes/, and
// LiveModeUnits.cpp is the one list of them, as core/modes/ModeRegistry is
// core's; a mode without a unit (general) records its channels as they come.
//
// Threading: every call from the session's owner thread; sink() is fed on
// the acquisition thread.
#pragma once

#include "core/BlockSink.h"
#include "core/ChannelDescriptor.h"
#include "core/Vocabulary.h"
#include "core/sensors/SensorProfile.h"
#include "core/storage/SessionStore.h"
#include "devices/session/LiveQuantity.h"
#include "devices/session/LiveRecords.h"

#include <algorithm>
#include <functional>
#include <iterator>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace tactiscope::core::storage {
class Recorder;
}

namespace tactiscope::devices::session {

class LiveModeUnit;

// What a unit is built from.
struct LiveUnitSetup {
    std::vector<core::ChannelDescriptor> channels;  // with their roles
    double rate_hz = 0.0;
    double displaySeconds = 0.0;
    std::string storePath;                                  // its calibrations
    const core::sensors::SensorProfile* profile = nullptr;  // the mode's, if it takes one
    double panelSpacing_m = 0.0;
    // The unit it replaces on the same channels (another profile or
    // calibration): its zero goes on. Null on new channels.
    const LiveModeUnit* previous = nullptr;
    // Problems met building (a calibration that cannot be read): one
    // sentence each, for the session to tell.
    std::vector<std::string>* problems = nullptr;
    // Why a unit that was built does not read through what it was asked to
    // (a calibration it refused), for the caller that asked.
    std::string* refused = nullptr;
};

// What a unit's take() may do with the session's state.
struct LiveTake {
    // A recording in the unit's mode; null when not recording, and while
    // another mode records (the unit then shows and stores nothing).
    core::storage::Recorder* recorder = nullptr;
    bool recordingOtherMode = false;
    // A stream time on the lists' clock (the recording's as stored, else
    // since connect).
    std::function<double(double)> listTime_s;
    // While recording, the stream time of the last sample recorded (before
    // the first: before everything): a result that ends after it was
    // completed from samples the recording does not have (the processors
    // run on past a stop) and waits for the lists after it.
    double recordedUntil_s = std::numeric_limits<double>::infinity();
    // While recording, the stream time of its first sample: a result that
    // ended before it (completed late, from samples before the record
    // press) belongs to no list and is not stored.
    double recordedFrom_s = -std::numeric_limits<double>::infinity();
    // Called before anything is added to a list: after a stop, the first
    // new entry starts the lists again.
    std::function<void()> adding;
    // Where on the subject the recording is taken (its metadata's site,
    // `record --site`); a unit with a finer place of its own (a phantom's
    // grid cell) uses that instead.
    std::string recordingSite;
    // Tells the operator what the unit saw about the device (a probe whose
    // own detector disagrees), at its stream time, as the link's notices
    // are told; the unit stores its own alarm while recording.
    using Tell = std::function<void(double, std::string)>;
    Tell tell;
    // The recording's last take: a result still under way (a press begun
    // in it) will not be in it, which the unit may say.
    bool recordingEnds = false;
};

class LiveModeUnit {
public:
    virtual ~LiveModeUnit() = default;

    // What the acquisition feeds; set once.
    virtual std::shared_ptr<core::BlockSink> sink() const = 0;
    // The calibrations it reads through (stored with a recording).
    virtual const std::vector<core::storage::StoredCalibration>& calibrations() const;
    // What its processor derives, sample for sample, by the names a trigger
    // or a limit gives them ("force"), in SI units.
    virtual std::vector<LiveQuantity> quantities() const { return {}; }

    // The zero: nothing when taken, else why not (the processor's rule).
    virtual std::optional<std::string> tare() = 0;
    // At the record press: the zero in use, into the recording of its mode.
    virtual void startRecording(core::storage::Recorder& recorder);
    // Each poll: completed results into the lists and the store; the zeros
    // taken since into take.recorder (a recording of its mode) or dropped.
    virtual void take(const LiveTake& take) = 0;
    virtual void takeZeros(const LiveTake& take);
    // The lists start again (a record press, other roles).
    virtual void clearLists() {}
    // At the end of a recording of its mode, after the last take():
    // its count in the summary and, for a whole recording (`whole`: not
    // cut by a lost probe), the automatic verdict decided.
    virtual std::optional<core::storage::VerdictDecision> finishRecording(RecordingSummary& summary, bool whole);
    // Then, the recording ended: what its analysis stored, in a line
    // (RecordingSummary::analysis).
    virtual std::string storedText(const RecordingSummary& summary) const = 0;
};

// For a unit's take(): what goes into its list now, on the lists' clock,
// from the results held back before (`later`) and the new ones, in order
// (results carry stream times in start_s and end_s). None while another
// mode records; those that ended before the recording's first sample are
// dropped, those that end after its last go back into `later`; when any
// are left, the lists are told (take.adding).
template <typename Result>
std::vector<Result> resultsForLists(std::vector<Result>& later, std::vector<Result> fresh, const LiveTake& take)
{
    std::vector<Result> found = std::exchange(later, {});
    if (take.recordingOtherMode) return {};
    found.insert(found.end(), std::make_move_iterator(fresh.begin()), std::make_move_iterator(fresh.end()));
    std::erase_if(found, [&](const Result& r) { return r.end_s < take.recordedFrom_s; });
    const auto after =
        std::find_if(found.begin(), found.end(), [&](const Result& r) { return r.end_s > take.recordedUntil_s; });
    later.assign(std::make_move_iterator(after), std::make_move_iterator(found.end()));
    found.erase(after, found.end());
    if (!found.empty()) take.adding();
    for (auto& result : found) {
        result.start_s = take.listTime_s(result.start_s);
        result.end_s = take.listTime_s(result.end_s);
    }
    return found;
}

// The unit of `mode` on the setup's channels; none for a mode without one
// (general). Throws std::invalid_argument when the probe or the channels
// cannot be used (a bad profile), saying why.
std::unique_ptr<LiveModeUnit> makeLiveUnit(core::Mode mode, const LiveUnitSetup& setup);

// A unit factory for a mode defined elsewhere (a test's, a plugin's).
using LiveUnitFactory = std::function<std::unique_ptr<LiveModeUnit>(const LiveUnitSetup&)>;
void registerLiveUnit(core::Mode mode, LiveUnitFactory factory);
void unregisterLiveUnit(core::Mode mode);

}  // namespace tactiscope::devices::session
