// Text lines → SampleBlocks. Text carries no rate: it is the one given
// (checked against the arrivals once they settle), or it is measured
// (LineRate: by the board's own clock when its lines carry one, else from
// their arrival times), and the lines are held back until it has settled.
// With a board clock, a step of several periods in it is samples lost.
// Each block holds consecutive lines that arrived together; a line that
// could not be read is a lost sample (a gap of one), so the lines after it
// keep their time.
#pragma once

#include "core/ChannelDescriptor.h"
#include "core/SampleBlock.h"
#include "devices/protocol/LineRate.h"
#include "devices/protocol/TextDecoder.h"

#include <map>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace tactiscope::devices::protocol {

class TextStream {
public:
    // A given rate must be positive. Throws std::invalid_argument otherwise.
    // `units`: a unit for channels by name, over the one its label gives.
    explicit TextStream(std::optional<double> sampleRate_hz = std::nullopt,
                        std::map<std::string, std::string> units = {});

    // hostTime_s: when the bytes arrived (seconds on a steady clock).
    // `arrivals`, when given, receives the arrival of each block put out.
    void push(std::span<const std::uint8_t> bytes, double hostTime_s, std::vector<core::SampleBlock>& out,
              std::vector<double>* arrivals = nullptr);

    std::optional<double> sampleRate_hz() const { return m_rate_hz; }
    // How the rate was measured; none when it was given.
    const std::optional<LineRateEstimate>& measuredRate() const { return m_measured; }
    // A given rate the arrivals contradict (by more than kGivenRateTolerance
    // and three of the measurement's uncertainty), said once.
    std::optional<std::string> takeRateWarning() { return std::exchange(m_rateWarning, std::nullopt); }
    // Each channel's unit is its label's, or the one given; a unit of the
    // table (core/UnitScale.h) gives its kind, and its values are stored
    // in SI ("force[mN]:1.5" is 0.0015 N), any other is kept as it is.
    std::vector<core::ChannelDescriptor> channels() const;
    // The names a unit was given for that the board does not print.
    std::vector<std::string> unknownUnitNames() const;
    // Where the board's layout changed (protocol/TextDecoder.h): from the
    // sample at `sampleIndex` on, blocks hold the channels() then known.
    struct LayoutChange {
        std::uint64_t sampleIndex = 0;
        std::string what;
    };
    std::vector<LayoutChange> takeLayoutChanges() { return std::exchange(m_layoutChanges, {}); }
    DecoderCounters counters() const;
    bool heardNumbers() const { return m_decoder.heardNumbers(); }

    static constexpr double kGivenRateTolerance = 1e-3;

private:
    // The channels, and each one's factor to its stored unit when asked.
    std::vector<core::ChannelDescriptor> described(std::vector<double>* toStored) const;
    void publish(std::vector<TextSample>& samples, std::vector<core::SampleBlock>& out, std::vector<double>* arrivals);
    std::uint64_t indexOf(const TextSample& sample) const;
    std::optional<double> boardSeconds(const TextSample& sample) const;  // its board time, when that is the clock
    void accept(const TextSample& sample, std::uint64_t index);
    void checkGivenRate();

    TextDecoder m_decoder;
    std::map<std::string, std::string> m_givenUnits;
    std::vector<double> m_toStored;  // each channel's factor to its stored unit, once the channels are known
    std::vector<LayoutChange> m_layoutChanges;
    std::optional<double> m_rate_hz;
    std::optional<LineRateEstimate> m_measured;
    LineRate m_lineRate;               // until it settles
    bool m_checkingGivenRate = false;  // a given rate, until the arrivals have said whether they agree
    std::optional<std::string> m_rateWarning;
    std::vector<TextSample> m_held;  // until the rate is known
    std::vector<TextSample> m_scratch;
    std::uint64_t m_nextSampleIndex = 0;
    std::optional<std::pair<double, std::uint64_t>> m_lastBoardTime;  // the last timed sample's stamp and index
    std::uint64_t m_samplesLost = 0;
    std::uint32_t m_blockSequence = 0;
};

}  // namespace tactiscope::devices::protocol
