// What every calibration wizard shares, around a fit its subclass supplies
// (GaugeFactorWizard, CapacitiveWizard):
// - the sensor page: the channel, the subclass's sensor rows, who calibrates;
// - the zero: the unloaded reading, taken from the first window the core's
//   StabilityMonitor judges stable after every load is off (the same rule
//   for the gauge's zero and the capacitive beam's C0);
// - the loads page: each known load read as the mean of the first stable
//   window after Capture, retake and remove, the table of loads with their
//   residuals as a fraction of full scale, and the linearity plot;
// - the result page: the limits a credible fit must meet and why it fails
//   them; Accept stores the record on the window's store worker, off the
//   GUI thread, and Cancel stores nothing.
// One vocabulary: the *zero* is the reading with nothing on the sensor, a
// *load* is each known weight or deflection captured, loading while the
// total grows and unloading while it shrinks.
#pragma once

#include "core/Vocabulary.h"
#include "core/calibration/CalibrationRecord.h"
#include "core/calibration/FitCredibility.h"
#include "core/calibration/LinearFit.h"
#include "core/calibration/StabilityMonitor.h"
#include "ui/calibration/CalibrationContext.h"
#include "ui/common/DisplayUnits.h"
#include "ui/profiles/ProfileLibrary.h"

#include <QWizard>

#include <cstdint>
#include <functional>
#include <optional>
#include <utility>
#include <variant>
#include <vector>

class QFormLayout;
class QLabel;
class QLineEdit;
class QComboBox;
class QVBoxLayout;

namespace tactiscope::ui {

class CapturePanel;
class CheckedPage;
class FitLimitsBox;
class StabilityCriteria;
class StabilityWatch;

class CalibrationWizard : public QWizard {
    Q_OBJECT

public:
    // SetupPage is the subclass's own, between the sensor and the zero.
    enum Page { SensorPage, SetupPage, ZeroPage, LoadsPage, ResultPage };

    bool credible() const;
    void accept() override;

    // What differs between the wizards in the shared pages.
    struct Words {
        QString zeroName;  // what the zero reading is called: "Zero", "C0"
        DisplayUnit signal;
        int signalDecimals = 1;  // a mean's decimals where its standard error is not known
        QString channelLabel;
        std::function<bool(const core::ChannelDescriptor&)> channelFits;
        QString noChannel;  // why the device cannot be calibrated here
        core::Mode mode{};  // whose profiles are offered (each wizard its own)
        std::function<bool(const core::sensors::SensorProfile&)> profileFits;
        QString zeroSubTitle;
        QString loadsSubTitle;
        std::vector<std::pair<QString, int>> loadUnits;
        std::pair<double, int> firstLoad;
        DisplayUnit plotX, plotY;  // the fitted x and y as plotted
        QString resultSubTitle;
        core::calibration::CredibilityLimits limits;
    };

signals:
    void calibrationStored(std::int64_t id, const QString& sensor);

protected:
    struct Load {
        double value = 0.0;  // in the unit the user chose
        int unit = 0;        // a Words::loadUnits id
        bool loading = true;
        core::calibration::WindowStatistics window;
    };
    // The fit of the zero and the loads so far, as the subclass made it:
    // the fitted points (the zero first, then one per load, in order) in
    // the fit's SI units, the line, and a sentence on it.
    struct Fit {
        std::vector<double> x, y;
        core::calibration::LinearFit line;
        QString summary;
    };

    CalibrationWizard(CalibrationContext context, Words words, QWidget* parent);

    // Adds the pages, the subclass's rows on the sensor page and its setup
    // page (if any) in between: called once by the subclass's constructor.
    void addPages(const std::vector<std::pair<QString, QWidget*>>& sensorRows, CheckedPage* setupPage = nullptr);

    // The subclass's fit of zero() and loads() (two loads at least); it
    // keeps its own result for resultHtml() and record(). Throws
    // std::invalid_argument when the points allow no fit.
    virtual Fit fitLoads() = 0;
    virtual bool sensorChosen() const = 0;
    virtual double forceOf(const Load& load) const = 0;  // newtons
    virtual QString loadText(const Load& load) const = 0;
    virtual core::calibration::StabilitySettings stabilityDefaults() const = 0;
    virtual QString resultHtml() const = 0;
    virtual core::calibration::CalibrationRecord record() const = 0;
    // Why a captured load is no point (not kept); none by default.
    virtual std::optional<QString> refusal(const Load& load) const;
    // Called when the result page is shown, after the shared parts.
    virtual void resultShown() {}

    const CalibrationContext& context() const { return m_context; }
    template <typename Profile>
    const Profile* chosenProfile() const
    {
        const auto* entry = chosenProfileEntry();
        return entry ? &std::get<Profile>(*entry->profile) : nullptr;
    }
    QComboBox* profileBox() const { return m_profile; }
    // The channel chosen on the sensor page (an index into context().channels).
    std::size_t chosenChannel() const;
    void setSensorSummary(const QString& text);
    QString operatorName() const;
    const std::optional<core::calibration::WindowStatistics>& zero() const { return m_zero; }
    // The decimals of a window's mean in the signal's display unit: its
    // standard error's, so the zero reads alike on every page ("120.056").
    int meanDecimals(const core::calibration::WindowStatistics& window) const;
    const std::vector<Load>& loads() const { return m_loads; }
    // Replaces every load at once (a sweep's points) and fits them.
    void setLoads(std::vector<Load> loads);
    CapturePanel* panel() const { return m_panel; }
    QVBoxLayout* resultLayout() const { return m_resultLayout; }
    // The next stable window goes to `use`, once; the loads page waits.
    void waitForWindow(const QString& status, std::function<void(const core::calibration::WindowStatistics&)> use);
    void refit();
    void recheck(int page);
    void initializePage(int id) override;

private:
    CheckedPage* createSensorPage(const std::vector<std::pair<QString, QWidget*>>& rows);
    CheckedPage* createZeroPage();
    CheckedPage* createLoadsPage();
    CheckedPage* createResultPage();
    void cleanupPage(int id) override;

    const ProfileEntry* chosenProfileEntry() const;
    void takeZero();
    void capture();
    void captured(Load load);
    void retake(int row);
    void remove(int row);
    QString pointName(std::size_t fitted) const;
    QString loadAndDirection(const Load& load) const;
    void showResult();
    void stored(std::int64_t id, const QString& sensor);

    CalibrationContext m_context;
    Words m_words;
    std::vector<ProfileEntry> m_profiles;
    StabilityWatch* m_watch;
    std::function<void(const core::calibration::WindowStatistics&)> m_onWindow;

    QComboBox* m_channel = nullptr;
    QComboBox* m_profile = nullptr;
    QLineEdit* m_operator = nullptr;
    QLabel* m_sensorSummary = nullptr;

    StabilityCriteria* m_criteria = nullptr;
    std::optional<core::calibration::StabilitySettings> m_defaultsShown;
    QLabel* m_zeroText = nullptr;
    std::optional<core::calibration::WindowStatistics> m_zero;

    CapturePanel* m_panel = nullptr;
    std::vector<Load> m_loads;
    std::optional<std::size_t> m_retakeIndex;  // the load a capture replaces
    std::optional<Fit> m_fit;

    QVBoxLayout* m_resultLayout = nullptr;
    QLabel* m_resultText = nullptr;
    QLabel* m_problems = nullptr;
    FitLimitsBox* m_limits = nullptr;
    bool m_storing = false;
};

}  // namespace tactiscope::ui
