// The per-sample part of palpation (seed 001), one implementation for the
// live sink (LivePalpation) and for a stored session's review and export
// (core/derived/PalpationChannels): each beam's raw value through its zero
// to a force, Q = F_H/F_L while both beams touch, and k_o (eq. 2) where Q is
// in range. What depends on history is only the zero, which a recording
// stores whenever it changes (SessionStore::addZero).
//
// Channels: the first Position channel is the displacement; the first two
// other channels are the high- and the low-stiffness beam, in the device's
// order. A channel in ADC counts goes through the profile's scale for it
// (core/sensors/ChannelScale.h) when it gives one, else through the
// strain-gauge chain (counts → strain); a strain channel through the beam
// model (F = ε / (root strain per newton)), a force channel is used as it
// is. Every one of these is an increasing function of the raw value, so the
// force of a stretch's raw minimum and maximum are the stretch's force
// extremes.
#pragma once

#include "core/ChannelDescriptor.h"
#include "core/calibration/CalibrationRecord.h"
#include "core/compliance/StiffnessReadings.h"
#include "core/sensors/SensorProfile.h"
#include "core/straingauge/StrainGaugeChain.h"

#include <limits>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace tactiscope::core::compliance {

// How a beam's raw values become a force.
enum class BeamInput {
    GaugeChain,    // ADC counts through the bridge and its gauge factor
    ProfileScale,  // ADC counts through the profile's scale for the channel
    Strain,        // the device's strain, through the beam model
    Force,         // the device's force, as it is
};

struct LivePalpationSettings {
    sensors::CantileverGeometry high;
    sensors::CantileverGeometry low;
    straingauge::AdcSettings adc;  // for channels in counts
    straingauge::BridgeSettings bridge;
    PressSettings press;
    sensors::ChannelScales scales;  // the profile's, for beams in counts
    BeamInput highInput = BeamInput::GaugeChain, lowInput = BeamInput::GaugeChain;
    // Each beam's calibrated gauge factor, for a beam read through the
    // gauge chain only; bridge.gaugeFactor (nominal) when none.
    std::optional<double> highGaugeFactor, lowGaugeFactor;
};

// A probe's settings at a stream's rate for its beams on `channels`, with
// each beam read through the gauge chain getting its gauge factor from the
// newest usable "gauge_factor" record among `calibrations` for that beam
// (calibration::beamSensorName), the nominal one otherwise. The records
// used are returned in `used` when given: a beam read otherwise (its
// device's strain or force, the profile's scale) uses none.
LivePalpationSettings palpationSettings(const sensors::CompliancePairProfile& probe, double sampleRate_hz,
                                        std::span<const ChannelDescriptor> channels,
                                        std::span<const calibration::CalibrationRecord> calibrations,
                                        std::vector<std::size_t>* used = nullptr);

// What forces are computed with, in words: the profile and how each beam
// is read (its gauge factor, calibrated or nominal; the profile's scale;
// the device's strain or force).
std::string basisText(const sensors::CompliancePairProfile& probe, const LivePalpationSettings& settings);

// kₒ needs only the ratio of the forces, so nominal factors on both beams
// cancel; one beam calibrated and the other nominal does not: the ratio
// then carries the nominal beam's whole gauge-factor error. What to say
// then ("only the stiff beam is calibrated: …"); none otherwise.
std::optional<std::string> mixedCalibration(const LivePalpationSettings& settings);

// A zero: each beam's raw value with nothing pressed (the mean of a
// window), and the standard uncertainty of that mean, σ/√n of the window
// (white noise), in the same units; none when not known (older sessions).
struct RawZero {
    double high = 0.0;
    double low = 0.0;
    std::optional<std::pair<double, double>> uncertainty;  // high, low
};

// A zero as a session stores it (storage::SessionZero): {"high": …, "low": …,
// "high_u": …, "low_u": …}, raw values in the beams' channel units; and back
// (none when unreadable).
std::string zeroJson(const RawZero& zero);
std::optional<RawZero> zeroFromJson(const std::string& json);

class PalpationForces {
public:
    // Throws std::invalid_argument when the channels lack a displacement or
    // two beams, for a displacement in counts the profile gives no length
    // scale for, or for a non-physical probe.
    PalpationForces(const std::vector<ChannelDescriptor>& channels, const LivePalpationSettings& settings);

    const sensors::CompliancePair& pair() const { return m_pair; }
    std::size_t highChannel() const { return m_high.channel; }
    std::size_t lowChannel() const { return m_low.channel; }
    std::size_t displacementChannel() const { return m_displacement; }
    // A raw displacement value in metres: a length channel's is; one in
    // counts goes through the profile's scale for it.
    double displacement_m(double raw) const { return (raw - m_displacementOffset) * m_metresPerCount; }
    double contactThreshold_n() const { return m_contactThreshold_n; }
    // The gauge factor that turns a beam's counts into strain; none when
    // the device sends strain or force itself.
    std::optional<double> gaugeFactor(bool highBeam) const;

    // The zero: each beam's raw value with nothing pressed. No force before one is set.
    void setZero(const RawZero& zero);
    const std::optional<RawZero>& zero() const { return m_zero; }
    // The zero's uncertainty in each beam's force; none when not known.
    std::optional<ZeroUncertainty> zeroUncertainty() const;

    // Whether a beam's raw value is at its ADC's limit (within kNearLimit
    // of full scale: the probe's converter's, or the one the profile's
    // scale declares): its force is then clipped. Always false for
    // channels not in counts, or in counts of no declared range.
    bool atLimit(bool highBeam, double raw) const;
    compliance::BeamLimits limitsOf(double rawHigh, double rawLow) const
    {
        return {atLimit(true, rawHigh) ? 1u : 0u, atLimit(false, rawLow) ? 1u : 0u};
    }
    static constexpr double kNearLimit = 0.01;

    // In N on the zero; NaN before there is one.
    double forceHigh(double raw) const { return m_zero ? m_high.force(m_pair.high(), raw) : kNaN; }
    double forceLow(double raw) const { return m_zero ? m_low.force(m_pair.low(), raw) : kNaN; }
    // A beam whose counts the profile scales with no "full_scale": where
    // it clips is not known, so a clipped press is read as any other. What
    // to say of it; none when every beam's range is known or the device's.
    std::optional<std::string> unjudgedClipping() const;
    // The force a change of a beam's raw value by `rawChange` makes (its
    // size), with or without a zero.
    double forceOfChange(bool highBeam, double rawChange) const;
    // A beam in counts of a known range: one count's force and its full
    // scale's; none otherwise (the probe's usable range, usableRange).
    std::optional<BeamResolution> resolution(bool highBeam) const;
    // F_H/F_L while both exceed the contact threshold, else NaN.
    double q(double forceHigh_n, double forceLow_n) const;
    // k_o in N/m for a Q in range (1 < Q < k_h/k_l), else NaN.
    double stiffness(double q) const;

    static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

private:
    // One beam's channel and how its values become a force.
    struct Input {
        std::size_t channel = 0;
        ChannelKind kind = ChannelKind::Other;
        std::optional<straingauge::StrainGaugeChain> chain;  // a channel in counts; holds its zero
        double unitsPerCount = 1.0;                          // the scale's, in N or strain
        double zero = 0.0;                                   // channels without a chain
        double offset = 0.0;                                 // the count of zero, its clipping's centre
        std::optional<double> fullScale;                     // where its counts clip, that far from it
        bool profileScaled = false;                          // counts the profile scales
        std::string name;                                    // its channel's
        void setZero(double value);
        double force(const sensors::CantileverBeam& beam, double value) const;
    };

    sensors::CompliancePair m_pair;
    double m_contactThreshold_n;
    Input m_high, m_low;
    std::size_t m_displacement = 0;
    double m_metresPerCount = 1.0;
    double m_displacementOffset = 0.0;  // in counts
    std::optional<RawZero> m_zero;
};

}  // namespace tactiscope::core::compliance
