// A channel's filter chain: its design, causal run, delay and offline run.
#include "core/dsp/ChannelFilter.h"

#include "core/dsp/ButterworthDesign.h"
#include "core/dsp/GapFreeStretches.h"
#include "core/dsp/MainsNotch.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace tactiscope::core::dsp {
namespace {

std::vector<Biquad> sectionsOf(const FilterSettings& settings, double rate_hz)
{
    std::vector<Biquad> sections;
    const auto append = [&sections](const std::vector<Biquad>& more) {
        sections.insert(sections.end(), more.begin(), more.end());
    };
    if (settings.notch_hz) append(mainsNotches(*settings.notch_hz, rate_hz));
    if (settings.highpass_hz) append(butterworth(PassBand::High, settings.order, *settings.highpass_hz, rate_hz));
    if (settings.lowpass_hz) append(butterworth(PassBand::Low, settings.order, *settings.lowpass_hz, rate_hz));
    return sections;
}

std::size_t averageLength(const FilterSettings& settings, double rate_hz)
{
    return std::max<std::size_t>(1, static_cast<std::size_t>(std::llround(settings.movingAverage_s * rate_hz)));
}

}  // namespace

ChannelFilter::ChannelFilter(const FilterSettings& settings, double sampleRate_hz)
    : m_settings(settings),
      m_sampleRate_hz(sampleRate_hz)
{
    if (const auto refusal = filterRefusal(settings, sampleRate_hz)) throw std::invalid_argument(*refusal);
    m_cascade = BiquadCascade(sectionsOf(settings, sampleRate_hz));
    m_average = MovingAverage(averageLength(settings, sampleRate_hz));
    m_averaging = m_average.length() > 1;
}

double ChannelFilter::process(double x)
{
    if (!std::isfinite(x)) {
        reset();
        return std::numeric_limits<double>::quiet_NaN();
    }
    x = m_cascade.process(x);
    return m_averaging ? m_average.process(x) : x;
}

void ChannelFilter::process(std::span<double> values)
{
    for (double& v : values) v = process(v);
}

void ChannelFilter::startFrom(const std::optional<std::vector<double>>& sectionsState)
{
    m_cascade.setState(sectionsState);
    m_average.reset();
}

void ChannelFilter::reset()
{
    m_cascade.reset();
    m_average.reset();
}

std::complex<double> ChannelFilter::response(double frequency_hz) const
{
    const double cycles = frequency_hz / m_sampleRate_hz;
    std::complex<double> h = m_cascade.response(cycles);
    if (m_averaging) {
        // A moving average of N: the Dirichlet kernel with its (N − 1)/2 delay.
        const double n = static_cast<double>(m_average.length());
        const double x = std::numbers::pi * cycles;
        const double gain = std::abs(std::sin(x)) < 1e-300 ? 1.0 : std::sin(n * x) / (n * std::sin(x));
        h *= gain * std::polar(1.0, -2.0 * x * (n - 1.0) / 2.0);
    }
    return h;
}

double ChannelFilter::delayFrequency_hz() const
{
    if (m_settings.highpass_hz && m_settings.lowpass_hz)
        return std::sqrt(*m_settings.highpass_hz * *m_settings.lowpass_hz);
    if (m_settings.highpass_hz) return std::min(4.0 * *m_settings.highpass_hz, 0.25 * m_sampleRate_hz);
    return 0.0;
}

double ChannelFilter::delay_s() const
{
    if (m_settings.zeroPhase) return 0.0;
    const double cycles = delayFrequency_hz() / m_sampleRate_hz;
    double samples = m_cascade.groupDelay_samples(cycles);
    if (m_averaging) samples += (static_cast<double>(m_average.length()) - 1.0) / 2.0;
    return samples / m_sampleRate_hz;
}

std::vector<double> filterSeries(const FilterSettings& settings, double sampleRate_hz, std::span<const double> values)
{
    ChannelFilter filter(settings, sampleRate_hz);
    std::vector<double> out(values.begin(), values.end());
    if (!settings.zeroPhase) {
        filter.process(out);
        return out;
    }
    const BiquadCascade cascade(sectionsOf(settings, sampleRate_hz));
    const std::size_t averaged = averageLength(settings, sampleRate_hz);
    for (const Stretch& stretch : gapFreeStretches(out)) {
        std::span<double> part(out.data() + stretch.first, stretch.count);
        filterZeroPhase(cascade, part);
        if (averaged > 1) {
            MovingAverage forward(averaged);
            for (double& v : part) v = forward.process(v);
            MovingAverage backward(averaged);
            for (auto it = part.rbegin(); it != part.rend(); ++it) *it = backward.process(*it);
        }
    }
    return out;
}

}  // namespace tactiscope::core::dsp
