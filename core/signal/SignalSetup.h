// A session's signal setup (issue 57): the filters on its channels, its
// math channels, and whether its mode analyses the filtered channels. It
// is a setting, never a change to the samples: it is recorded with the
// session (sessions.signal_setup, a JSON object) so that review, report,
// export and re-analysis compute from the stored samples what the
// operator saw live.
#pragma once

#include "core/dsp/FilterSettings.h"
#include "core/math/MathChannels.h"

#include <string>
#include <vector>

namespace tactiscope::core::signal {

struct ChannelFilterSetting {
    std::string channel;
    dsp::FilterSettings settings;

    friend bool operator==(const ChannelFilterSetting&, const ChannelFilterSetting&) = default;
};

struct SignalSetup {
    std::vector<ChannelFilterSetting> filters;  // one per channel at most
    std::vector<math::MathDefinition> math;     // in order: each may use those before it
    // The mode reads its channels through their filters (a detector on
    // notched cantilevers); otherwise it reads them as they came.
    bool analysisFiltered = false;
    // Where each filter's sections stood at a recording's first sample
    // (ChannelFilter::sectionsState(), none: afresh), so re-analysis goes on
    // from there, bit for bit, and without the ringing a restart would
    // start; empty: every filter afresh (a live setup, an older session).
    std::vector<std::optional<std::vector<double>>> startState;

    bool empty() const { return filters.empty() && math.empty(); }
    const dsp::FilterSettings* filterOf(const std::string& channel) const;
    // "a: mains notch 50 Hz and harmonics; diff[µε]=a - b", "none".
    std::string text() const;
};

// {"filters": [{"channel", "notch_hz", "highpass_hz", "lowpass_hz", "order",
// "moving_average_s", "zero_phase", "start_state": [numbers] or null}],
// "math": ["NAME[UNIT]=EXPR"], "analysis_filtered": bool}; "" for an empty
// setup. Numbers are written to round-trip exactly.
std::string signalSetupJson(const SignalSetup& setup);
// The setup a session recorded ("" reads as none). Throws
// std::invalid_argument saying what is wrong with it.
SignalSetup signalSetupFromJson(const std::string& json);

// A recorded setup in words (SignalSetup::text()); one it cannot read
// says so ("unreadable: …") rather than failing the page that shows it.
std::string signalSetupText(const std::string& json);

// The filters a mode's re-analysis reads `channels` (names, in the mode's
// order) through when the session's mode analysed its filtered channels:
// each one's filter (empty: as stored) and where it stood at the
// session's first sample; none when the mode read them as they came.
struct AnalysisFilters {
    std::vector<dsp::FilterSettings> filters;
    std::vector<std::optional<std::vector<double>>> startStates;
    std::string text;  // "a: mains notch 50 Hz and harmonics; b: …"
};
std::optional<AnalysisFilters> analysisFilters(const SignalSetup& setup, const std::vector<std::string>& channels);

// Why `setup` cannot run on `channels` (names) at `sampleRate_hz`: a filter
// on a channel not there or twice, one the rate refuses, a live filter
// asked zero-phase; none when it can. Math definitions are checked by
// MathChannels when they are built.
std::optional<std::string> signalSetupRefusal(const SignalSetup& setup, const std::vector<std::string>& channels,
                                              double sampleRate_hz);

}  // namespace tactiscope::core::signal
