// Session ▸ Filters and math channels…: a device's signal setup
// (core/signal/SignalSetup.h), the window's first; with several devices a
// chooser at the top opens it on another, each device having its own. A row per channel sets its filter: a mains
// notch at the site's frequency (a station setting, kept between runs,
// which the program can find from the signal), a Butterworth high- and/or low-pass of one order, a moving
// average; each row shows the delay the live filter adds. Math channels
// are typed one per line ("diff[µε]=a - b"), and a tick has the mode
// analyse the filtered channels. Apply sets it on the device
// (LiveSession::setSignal); a refusal is shown in the dialog's words.
#pragma once

#include "core/ChannelDescriptor.h"
#include "core/signal/SignalSetup.h"

#include <QDialog>

#include <functional>
#include <optional>
#include <string>
#include <vector>

class QCheckBox;
class QComboBox;
class QLabel;
class QPlainTextEdit;
class QTableWidget;

namespace tactiscope::ui {

class SignalDialog : public QDialog {
    Q_OBJECT

public:
    struct Session {
        std::vector<core::ChannelDescriptor> channels;
        double rate_hz = 0.0;
        core::signal::SignalSetup setup;  // the one running now
        // Sets a setup; the refusal, or none.
        std::function<std::optional<std::string>(const core::signal::SignalSetup&)> apply;
        // The mains hum found in the signal now, in words ("50 Hz: 12.3 µε on a"),
        // with its frequency; none when the signal shows none.
        std::function<std::optional<std::pair<double, QString>>()> findMains;
        // With several devices: their names, which one this is, and how to
        // open the dialog on another (this one closes). Empty with one.
        std::vector<std::string> devices;
        std::size_t device = 0;
        std::function<void(std::size_t)> showDevice;
    };
    explicit SignalDialog(Session session, QWidget* parent = nullptr);

    // What the rows and lines say now; the problem with them in `problem`.
    core::signal::SignalSetup typed(QString& problem) const;

private:
    void refreshDelays();
    void applyTyped();
    void findMains();

    Session m_session;
    QTableWidget* m_filters;
    QComboBox* m_mains;
    QLabel* m_mainsFound;
    QCheckBox* m_analyseFiltered;
    QPlainTextEdit* m_math;
    QLabel* m_problem;
};

}  // namespace tactiscope::ui
