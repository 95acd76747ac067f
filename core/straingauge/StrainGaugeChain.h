// The strain-gauge measurement chain of a cantilever channel, from ADC
// counts to strain and back:
//   counts → volts at the ADC (bits, reference, bipolar or not)
//          → volts at the bridge (÷ amplifier gain)
//          → bridge ratio V_r = (V − V_zero)/V_excitation (tare removes V_zero)
//          → relative resistance change x = GF·ε of the active gauges
//          → strain ε = x/GF.
// Convention: the bridge output rises with tensile strain on the first
// active gauge. Bridge equations, with x = GF·ε:
//   quarter bridge (one active gauge):        V_r = x/(4 + 2x)  → x = 4V_r/(1 − 2V_r)
//   half bridge, bending (±ε, adjacent arms): V_r = x/2         → x = 2V_r
//   full bridge, bending (±ε, four gauges):   V_r = x           → x = V_r
// The quarter bridge is the nonlinear one; the others are exact.
#pragma once

#include <optional>

namespace tactiscope::core::straingauge {

enum class BridgeType { Quarter, HalfBending, FullBending };

struct AdcSettings {
    int bits = 16;
    double reference_v = 10.0;  // full-scale voltage (±reference when bipolar)
    bool bipolar = true;
    double gain = 200.0;  // amplifier gain between bridge and ADC
};

struct BridgeSettings {
    BridgeType type = BridgeType::HalfBending;
    double excitation_v = 5.0;
    double gaugeFactor = 2.0;
};

class StrainGaugeChain {
public:
    // Throws std::invalid_argument for non-physical settings.
    StrainGaugeChain(const AdcSettings& adc, const BridgeSettings& bridge);

    const AdcSettings& adc() const { return m_adc; }
    const BridgeSettings& bridge() const { return m_bridge; }

    // Bridge output in volts (before the amplifier) for a reading in counts.
    double bridgeVolts(double counts) const;
    double counts(double bridgeVolts) const;  // inverse, unrounded

    // Tare: the reading taken with no load becomes the zero.
    void tare(double zeroCounts) { m_zeroCounts = zeroCounts; }
    double zeroCounts() const { return m_zeroCounts; }

    // Bridge ratio V_r of a reading, relative to the tare.
    double bridgeRatio(double counts) const;
    // x = GF·ε from V_r (bridge type only: independent of the gauge factor).
    double relativeChange(double bridgeRatio) const;
    double strain(double counts) const;

    // Forward model, for simulation and calibration checks: the reading for
    // a strain with the given zero offset in counts (unrounded).
    double countsForStrain(double strain, double zeroCounts = 0.0) const;
    double bridgeRatioForRelativeChange(double x) const;

    // Largest |counts| the ADC can represent.
    double fullScaleCounts() const;

private:
    AdcSettings m_adc;
    BridgeSettings m_bridge;
    double m_zeroCounts = 0.0;
};

}  // namespace tactiscope::core::straingauge
