// Welch's averaged spectrum of a channel: segments of one length, half
// overlapping, each taken within one gap-free stretch (a gap is never
// bridged or interpolated: a stretch shorter than a segment adds nothing,
// and the result says so), mean removed, through a window, and averaged.
// Two spectra come out of the same segments: the power spectral density
// (one-sided, unit²/Hz, through the chosen window), and the amplitude of
// each line (through a flat-top window, in the channel's unit), which is
// what the peaks report.
#pragma once

#include "core/dsp/RealFft.h"
#include "core/dsp/SpectralWindow.h"

#include <cstddef>
#include <memory>
#include <span>
#include <vector>

namespace tactiscope::core::dsp {

struct SpectrumPeak {
    double frequency_hz = 0.0;
    double amplitude = 0.0;  // of the sine, in the channel's unit (not RMS)
};

struct Spectrum {
    double sampleRate_hz = 0.0;
    std::size_t segmentLength = 0;
    std::size_t averages = 0;           // segments averaged
    std::size_t stretches = 0;          // gap-free stretches that gave segments
    std::size_t stretchesTooShort = 0;  // gap-free stretches shorter than a segment
    SpectralWindow window = SpectralWindow::Hann;
    std::vector<double> frequency_hz;  // bin k at k·fs/N, from 0 to fs/2
    std::vector<double> psd;           // unit²/Hz
    std::vector<double> amplitude;     // unit, flat-top
    std::vector<SpectrumPeak> peaks;   // the strongest lines, strongest first

    double resolution_hz() const { return segmentLength ? sampleRate_hz / static_cast<double>(segmentLength) : 0.0; }
    // The amplitude spectral density, unit/√Hz.
    std::vector<double> asd() const;
};

// Segments are fed as they come (a live stream, a stored session read in
// windows): push() takes consecutive samples, NaN where one is missing.
class WelchAccumulator {
public:
    WelchAccumulator(double sampleRate_hz, std::size_t segmentLength, SpectralWindow window);

    void push(std::span<const double> values);
    // Forgets every sample, keeping the plan and the windows: a live
    // spectrum takes its window afresh each frame at the cost of the FFTs alone.
    void reset();
    // Ends the current gap-free stretch (a gap known from elsewhere).
    void breakStretch();
    std::size_t averages() const { return m_averages; }
    // Whether it was made for these: a kept one is reused only then.
    bool makes(double sampleRate_hz, std::size_t segmentLength, SpectralWindow window) const
    {
        return m_rate_hz == sampleRate_hz && m_length == segmentLength && m_window == window;
    }
    // The spectrum of what was pushed (no averages: empty spectra).
    Spectrum result() const;

private:
    void addSegment();
    void endStretch();

    double m_rate_hz;
    std::size_t m_length;
    SpectralWindow m_window;
    std::vector<double> m_psdWindow;
    std::vector<double> m_flatTop;
    std::unique_ptr<RealFft> m_fft;
    std::vector<double> m_buffer;  // the current stretch's last samples, up to one segment
    std::vector<double> m_work;
    std::vector<double> m_psdSum;
    std::vector<double> m_powerSum;  // flat-top |X|²
    std::size_t m_stretchSamples = 0;
    bool m_stretchGaveSegment = false;
    std::size_t m_averages = 0;
    std::size_t m_stretches = 0;
    std::size_t m_stretchesTooShort = 0;
};

struct SpectrumSettings {
    SpectralWindow window = SpectralWindow::Hann;
    std::size_t averages = 16;  // wanted at least; the segment is made short enough to give them
};

inline constexpr std::size_t kShortestSegment = 64;
inline constexpr std::size_t kLongestSegment = 1u << 20;

// The longest power-of-two segment (kShortestSegment–kLongestSegment) that
// gives `averages` half-overlapping segments within stretches of these
// lengths; the shortest when none does.
std::size_t segmentLengthFor(std::span<const std::size_t> stretchLengths, std::size_t averages);

// The spectrum of a series held whole (NaN where missing).
Spectrum welchSpectrum(std::span<const double> values, double sampleRate_hz, const SpectrumSettings& settings);
// The same with the accumulator the caller keeps between calls (a live
// spectrum's frames): made again only when the rate, the segment length or
// the window changed, so a frame costs its FFTs, not their plans.
Spectrum welchSpectrum(std::span<const double> values, double sampleRate_hz, const SpectrumSettings& settings,
                       std::unique_ptr<WelchAccumulator>& kept);

// The strongest lines of an amplitude spectrum: local maxima over a
// flat-top main lobe that stand 20 dB above the median of the 64 bins on
// either side, at most `most`, each placed by the power centroid of its lobe.
std::vector<SpectrumPeak> spectrumPeaks(const Spectrum& spectrum, std::size_t most = 8);

}  // namespace tactiscope::core::dsp
