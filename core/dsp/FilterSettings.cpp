// Filter settings: their words and their checks.
#include "core/dsp/FilterSettings.h"

#include "core/NumberRanges.h"
#include "core/dsp/ButterworthDesign.h"
#include "core/dsp/MainsNotch.h"
#include "core/text/NumberFormat.h"

#include <cmath>
#include <stdexcept>

namespace tactiscope::core::dsp {
namespace {

std::string hertz(double value)
{
    return text::formatShortest(value) + " Hz";
}

}  // namespace

std::string FilterSettings::text() const
{
    if (empty()) return "none";
    std::vector<std::string> parts;
    if (notch_hz) parts.push_back("mains notch " + hertz(*notch_hz) + " and harmonics");
    const std::string butterworth = " (Butterworth, order " + std::to_string(order) + ")";
    if (highpass_hz && lowpass_hz)
        parts.push_back("band-pass " + text::formatShortest(*highpass_hz) + "–" + hertz(*lowpass_hz) + butterworth);
    else if (highpass_hz)
        parts.push_back("high-pass " + hertz(*highpass_hz) + butterworth);
    else if (lowpass_hz)
        parts.push_back("low-pass " + hertz(*lowpass_hz) + butterworth);
    if (movingAverage_s > 0.0) parts.push_back("moving average " + text::formatShortest(movingAverage_s * 1e3) + " ms");
    if (zeroPhase) parts.push_back("zero-phase");
    std::string joined;
    for (const std::string& part : parts) joined += (joined.empty() ? "" : ", ") + part;
    return joined;
}

std::optional<std::string> filterRefusal(const FilterSettings& settings, double sampleRate_hz)
{
    if (!(sampleRate_hz > 0.0) || !std::isfinite(sampleRate_hz)) return "the channel has no sample rate to filter at";
    if (settings.notch_hz && *settings.notch_hz != 50.0 && *settings.notch_hz != 60.0)
        return "the mains notch is at 50 or 60 Hz, not " + hertz(*settings.notch_hz);
    try {
        if (settings.notch_hz) mainsNotches(*settings.notch_hz, sampleRate_hz);
        if (settings.highpass_hz) butterworth(PassBand::High, settings.order, *settings.highpass_hz, sampleRate_hz);
        if (settings.lowpass_hz) butterworth(PassBand::Low, settings.order, *settings.lowpass_hz, sampleRate_hz);
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    if (settings.highpass_hz && settings.lowpass_hz && !(*settings.highpass_hz < *settings.lowpass_hz))
        return "a band-pass's high-pass cut-off (" + hertz(*settings.highpass_hz) +
               ") must lie below its low-pass's (" + hertz(*settings.lowpass_hz) + ")";
    if (!kMovingAverageRange.holds(settings.movingAverage_s))
        return "a moving average is " + kMovingAverageRange.text() + " long, not " +
               text::formatShortest(settings.movingAverage_s) + " s";
    // Rounded to whole samples, as the filter takes it: one sample averages nothing.
    if (settings.movingAverage_s > 0.0 && std::llround(settings.movingAverage_s * sampleRate_hz) < 2)
        return "a moving average of " + text::formatShortest(settings.movingAverage_s * 1e3) +
               " ms is shorter than two samples at " + hertz(sampleRate_hz) + ": it would average nothing";
    return std::nullopt;
}

}  // namespace tactiscope::core::dsp
