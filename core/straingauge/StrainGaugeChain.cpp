// StrainGaugeChain: ADC scaling and bridge equations.
#include "core/straingauge/StrainGaugeChain.h"

#include <cmath>
#include <stdexcept>

namespace tactiscope::core::straingauge {

StrainGaugeChain::StrainGaugeChain(const AdcSettings& adc, const BridgeSettings& bridge)
    : m_adc(adc),
      m_bridge(bridge)
{
    if (adc.bits < 2 || adc.bits > 32) throw std::invalid_argument("ADC resolution must be 2 to 32 bits");
    if (!(adc.reference_v > 0.0)) throw std::invalid_argument("ADC reference must be positive");
    if (!(adc.gain > 0.0)) throw std::invalid_argument("amplifier gain must be positive");
    if (!(bridge.excitation_v > 0.0)) throw std::invalid_argument("bridge excitation must be positive");
    if (!(bridge.gaugeFactor > 0.0)) throw std::invalid_argument("gauge factor must be positive");
}

double StrainGaugeChain::fullScaleCounts() const
{
    return std::ldexp(1.0, m_adc.bipolar ? m_adc.bits - 1 : m_adc.bits);
}

double StrainGaugeChain::bridgeVolts(double counts) const
{
    return counts / fullScaleCounts() * m_adc.reference_v / m_adc.gain;
}

double StrainGaugeChain::counts(double bridgeVolts) const
{
    return bridgeVolts * m_adc.gain / m_adc.reference_v * fullScaleCounts();
}

double StrainGaugeChain::bridgeRatio(double counts) const
{
    return bridgeVolts(counts - m_zeroCounts) / m_bridge.excitation_v;
}

double StrainGaugeChain::relativeChange(double r) const
{
    switch (m_bridge.type) {
    case BridgeType::Quarter:
        return 4.0 * r / (1.0 - 2.0 * r);
    case BridgeType::HalfBending:
        return 2.0 * r;
    case BridgeType::FullBending:
        return r;
    }
    return r;
}

double StrainGaugeChain::bridgeRatioForRelativeChange(double x) const
{
    switch (m_bridge.type) {
    case BridgeType::Quarter:
        return x / (4.0 + 2.0 * x);
    case BridgeType::HalfBending:
        return x / 2.0;
    case BridgeType::FullBending:
        return x;
    }
    return x;
}

double StrainGaugeChain::strain(double counts) const
{
    return relativeChange(bridgeRatio(counts)) / m_bridge.gaugeFactor;
}

double StrainGaugeChain::countsForStrain(double strain, double zeroCounts) const
{
    const double r = bridgeRatioForRelativeChange(m_bridge.gaugeFactor * strain);
    return zeroCounts + counts(r * m_bridge.excitation_v);
}

}  // namespace tactiscope::core::straingauge
