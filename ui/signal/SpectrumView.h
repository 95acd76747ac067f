// A channel's spectrum (issue 57), live and in review: Welch's amplitude
// spectral density in the channel's display unit per √Hz on log–log axes,
// with the window (Hann, or flat-top for lines), the averages wanted and
// the strongest lines' frequencies and amplitudes (flat-top) under it. It
// computes nothing itself: core/dsp/WelchSpectrum does, from the samples
// its feeder gives (the live buffer's last seconds, a review's range);
// a series with gaps is analysed stretch by stretch, which it says.
#pragma once

#include "core/ChannelDescriptor.h"
#include "core/dsp/WelchSpectrum.h"
#include "ui/common/DisplayUnits.h"

#include <QWidget>

#include <memory>
#include <span>
#include <vector>

class QComboBox;
class QCustomPlot;
class QLabel;
class QSpinBox;

namespace tactiscope::ui {

class SpectrumView : public QWidget {
    Q_OBJECT

public:
    explicit SpectrumView(QWidget* parent = nullptr);

    // The channels to choose from (keeps the choice when still there).
    void setChannels(const std::vector<core::ChannelDescriptor>& channels);
    // The chosen channel's index among them; -1 for none.
    int channel() const;
    core::dsp::SpectrumSettings settings() const;
    // Draws the spectrum of `values` (the chosen channel's, NaN where
    // missing) sampled at `rate_hz`; `span` says what they cover ("the
    // last 8.2 s", "12.0–20.0 s").
    void show(std::span<const double> values, double rate_hz, const QString& span);
    void clear(const QString& why);

    // What is drawn, for tests: the spectrum and its peaks' text.
    const core::dsp::Spectrum& spectrum() const { return m_spectrum; }
    QString peaksText() const;

signals:
    void settingsChanged();  // channel, window or averages

private:
    std::vector<core::ChannelDescriptor> m_channels;
    QComboBox* m_channel;
    QComboBox* m_window;
    QSpinBox* m_averages;
    QCustomPlot* m_plot;
    QLabel* m_peaks;
    core::dsp::Spectrum m_spectrum;
    // Kept from one spectrum to the next: a live frame costs its FFTs, not their plans.
    std::unique_ptr<core::dsp::WelchAccumulator> m_accumulator;
    DisplayUnit m_unit;
};

}  // namespace tactiscope::ui
