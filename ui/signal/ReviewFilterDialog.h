// Signal ▸ Filter a channel in review… (issue 57): one stored channel's
// filter for the review plot — a mains notch with its harmonics, a
// Butterworth high- and/or low-pass of one order, a moving average —
// zero-phase by default (forward and backward: no delay, as review may
// be), or causal as it would run live. The line under the fields says the
// filter in words with its delay, or why it cannot filter the channel.
// The plot shows it as a lane of its own ("a.review"); the stored samples
// are not changed (core/signal/ReviewFilterLane.h).
#pragma once

#include "core/signal/ReviewFilterLane.h"

#include <QDialog>

#include <optional>
#include <vector>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QSpinBox;

namespace tactiscope::ui {

class ReviewFilterDialog : public QDialog {
    Q_OBJECT

public:
    struct Channel {
        std::string name;  // as the review names it (DEVICE/NAME in a session of several devices)
        double rate_hz = 0.0;
    };
    ReviewFilterDialog(std::vector<Channel> channels, QWidget* parent = nullptr);

    // What the fields say, when it can filter the chosen channel.
    std::optional<core::signal::ReviewFilter> filter() const;

private:
    core::dsp::FilterSettings settings() const;
    void refresh();

    std::vector<Channel> m_channels;
    QComboBox* m_channel;
    QComboBox* m_notch;
    QDoubleSpinBox* m_highpass;
    QDoubleSpinBox* m_lowpass;
    QSpinBox* m_order;
    QDoubleSpinBox* m_average;
    QCheckBox* m_zeroPhase;
    QLabel* m_said;
    QPushButton* m_add;
};

}  // namespace tactiscope::ui
