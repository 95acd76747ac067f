// Welch's method: segmenting within gap-free stretches, windows, scaling.
#include "core/dsp/WelchSpectrum.h"

#include "core/dsp/GapFreeStretches.h"
#include "core/dsp/Median.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace tactiscope::core::dsp {
namespace {

// A flat-top window's main lobe spans ±5 bins; its peak's neighbours
// within ±4 belong to the same line.
constexpr std::size_t kLobeBins = 4;
// The neighbourhood a line's floor is the median of: ±64 bins, its own lobe left out.
constexpr std::size_t kFloorBins = 64;
constexpr double kLineAboveFloor = 10.0;  // 20 dB in amplitude

double sumOf(const std::vector<double>& v)
{
    return std::accumulate(v.begin(), v.end(), 0.0);
}
double sumOfSquares(const std::vector<double>& v)
{
    return std::inner_product(v.begin(), v.end(), v.begin(), 0.0);
}

}  // namespace

std::vector<double> Spectrum::asd() const
{
    std::vector<double> result(psd.size());
    std::transform(psd.begin(), psd.end(), result.begin(), [](double p) { return std::sqrt(p); });
    return result;
}

WelchAccumulator::WelchAccumulator(double sampleRate_hz, std::size_t segmentLength, SpectralWindow window)
    : m_rate_hz(sampleRate_hz),
      m_length(segmentLength),
      m_window(window),
      m_psdWindow(windowCoefficients(window, segmentLength)),
      m_flatTop(windowCoefficients(SpectralWindow::FlatTop, segmentLength)),
      m_fft(std::make_unique<RealFft>(segmentLength)),
      m_work(segmentLength),
      m_psdSum(segmentLength / 2 + 1, 0.0),
      m_powerSum(segmentLength / 2 + 1, 0.0)
{
    if (!(sampleRate_hz > 0.0)) throw std::invalid_argument("a spectrum needs a sample rate");
    m_buffer.reserve(segmentLength);
}

void WelchAccumulator::push(std::span<const double> values)
{
    for (const double v : values) {
        if (!std::isfinite(v)) {
            endStretch();
            continue;
        }
        if (m_buffer.size() == m_length)
            m_buffer.erase(m_buffer.begin(), m_buffer.begin() + static_cast<std::ptrdiff_t>(m_length / 2));
        m_buffer.push_back(v);
        ++m_stretchSamples;
        // Full after a segment's samples, then after each half more: half overlap.
        if (m_buffer.size() == m_length) addSegment();
    }
}

void WelchAccumulator::breakStretch()
{
    endStretch();
}

void WelchAccumulator::reset()
{
    endStretch();
    std::fill(m_psdSum.begin(), m_psdSum.end(), 0.0);
    std::fill(m_powerSum.begin(), m_powerSum.end(), 0.0);
    m_averages = m_stretches = m_stretchesTooShort = 0;
}

void WelchAccumulator::endStretch()
{
    if (m_stretchSamples > 0) {
        if (m_stretchGaveSegment)
            ++m_stretches;
        else
            ++m_stretchesTooShort;
    }
    m_buffer.clear();
    m_stretchSamples = 0;
    m_stretchGaveSegment = false;
}

void WelchAccumulator::addSegment()
{
    const double mean = sumOf(m_buffer) / static_cast<double>(m_length);
    const auto transformWith = [&](const std::vector<double>& window, std::vector<double>& sum) {
        for (std::size_t i = 0; i < m_length; ++i) m_work[i] = (m_buffer[i] - mean) * window[i];
        const auto bins = m_fft->transform(m_work);
        for (std::size_t k = 0; k < bins.size(); ++k) sum[k] += std::norm(bins[k]);
    };
    transformWith(m_psdWindow, m_psdSum);
    transformWith(m_flatTop, m_powerSum);
    ++m_averages;
    m_stretchGaveSegment = true;
}

Spectrum WelchAccumulator::result() const
{
    Spectrum spectrum;
    spectrum.sampleRate_hz = m_rate_hz;
    spectrum.segmentLength = m_length;
    spectrum.averages = m_averages;
    spectrum.window = m_window;
    spectrum.stretches = m_stretches + (m_stretchGaveSegment ? 1 : 0);
    spectrum.stretchesTooShort = m_stretchesTooShort + (m_stretchSamples > 0 && !m_stretchGaveSegment ? 1 : 0);
    if (m_averages == 0) return spectrum;
    const std::size_t bins = m_length / 2 + 1;
    const double n = static_cast<double>(m_averages);
    // One-sided density: |X|² / (fs Σw²), doubled except at DC and Nyquist.
    const double densityScale = 1.0 / (m_rate_hz * sumOfSquares(m_psdWindow) * n);
    // A sine of amplitude A gives |X| = A Σw / 2 at its bin.
    const double amplitudeScale = 2.0 / sumOf(m_flatTop);
    spectrum.frequency_hz.resize(bins);
    spectrum.psd.resize(bins);
    spectrum.amplitude.resize(bins);
    for (std::size_t k = 0; k < bins; ++k) {
        const bool edge = k == 0 || (m_length % 2 == 0 && k == bins - 1);
        spectrum.frequency_hz[k] = static_cast<double>(k) * m_rate_hz / static_cast<double>(m_length);
        spectrum.psd[k] = m_psdSum[k] * densityScale * (edge ? 1.0 : 2.0);
        spectrum.amplitude[k] = std::sqrt(m_powerSum[k] / n) * amplitudeScale * (edge ? 0.5 : 1.0);
    }
    spectrum.peaks = spectrumPeaks(spectrum);
    return spectrum;
}

std::size_t segmentLengthFor(std::span<const std::size_t> stretchLengths, std::size_t averages)
{
    const std::size_t wanted = std::max<std::size_t>(averages, 1);
    for (std::size_t length = kLongestSegment; length >= kShortestSegment; length /= 2) {
        std::size_t segments = 0;
        for (const std::size_t stretch : stretchLengths)
            if (stretch >= length) segments += (stretch - length) / (length / 2) + 1;
        if (segments >= wanted) return length;
    }
    return kShortestSegment;
}

Spectrum welchSpectrum(std::span<const double> values, double sampleRate_hz, const SpectrumSettings& settings)
{
    std::unique_ptr<WelchAccumulator> once;
    return welchSpectrum(values, sampleRate_hz, settings, once);
}

Spectrum welchSpectrum(std::span<const double> values, double sampleRate_hz, const SpectrumSettings& settings,
                       std::unique_ptr<WelchAccumulator>& kept)
{
    std::vector<std::size_t> lengths;
    for (const Stretch& stretch : gapFreeStretches(values)) lengths.push_back(stretch.count);
    const std::size_t length = segmentLengthFor(lengths, settings.averages);
    if (kept && kept->makes(sampleRate_hz, length, settings.window))
        kept->reset();
    else
        kept = std::make_unique<WelchAccumulator>(sampleRate_hz, length, settings.window);
    kept->push(values);
    return kept->result();
}

std::vector<SpectrumPeak> spectrumPeaks(const Spectrum& spectrum, std::size_t most)
{
    const std::vector<double>& a = spectrum.amplitude;
    if (a.size() < 2 * kLobeBins + 2) return {};
    // A line stands above the spectrum around it, not above the whole
    // band's: behind a low-pass the band's median is the stop band's, and
    // the pass band's noise would stand 20 dB above it everywhere.
    const auto localFloor = [&a](std::size_t k) {
        std::vector<double> around;
        const std::size_t from = k > kFloorBins ? k - kFloorBins : 0;
        const std::size_t to = std::min(a.size() - 1, k + kFloorBins);
        for (std::size_t j = from; j <= to; ++j)
            if (j + kLobeBins < k || j > k + kLobeBins) around.push_back(a[j]);
        return median(std::move(around));
    };
    std::vector<SpectrumPeak> peaks;
    // Bins within a lobe of DC hold the removed mean's leakage, not a line.
    for (std::size_t k = kLobeBins + 1; k + 1 < a.size(); ++k) {
        const std::size_t from = k - kLobeBins;
        const std::size_t to = std::min(a.size() - 1, k + kLobeBins);
        bool highest = true;
        for (std::size_t j = from; j <= to && highest; ++j) highest = j == k || a[j] < a[k] || (a[j] == a[k] && j > k);
        if (!highest || !(a[k] > kLineAboveFloor * localFloor(k))) continue;
        double power = 0.0;
        double moment = 0.0;
        for (std::size_t j = from; j <= to; ++j) {
            power += a[j] * a[j];
            moment += a[j] * a[j] * spectrum.frequency_hz[j];
        }
        peaks.push_back({moment / power, a[k]});
    }
    std::sort(peaks.begin(), peaks.end(),
              [](const SpectrumPeak& x, const SpectrumPeak& y) { return x.amplitude > y.amplitude; });
    if (peaks.size() > most) peaks.resize(most);
    return peaks;
}

}  // namespace tactiscope::core::dsp
