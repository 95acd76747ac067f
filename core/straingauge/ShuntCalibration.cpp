// ShuntCalibration: the shunted arm's change through the bridge's own conversion.
#include "core/straingauge/ShuntCalibration.h"

#include <cmath>
#include <stdexcept>

namespace tactiscope::core::straingauge {

double shuntStrain(BridgeType type, double gaugeResistance_ohm, double shuntResistance_ohm, double gaugeFactor)
{
    const auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
    if (!positive(gaugeResistance_ohm) || !positive(shuntResistance_ohm) || !positive(gaugeFactor))
        throw std::invalid_argument("shunt check: the resistances and the gauge factor must be positive");
    const double y = -gaugeResistance_ohm / (gaugeResistance_ohm + shuntResistance_ohm);
    switch (type) {
    case BridgeType::Quarter:
        return y / gaugeFactor;
    case BridgeType::HalfBending:
        return y / ((2.0 + y) * gaugeFactor);
    case BridgeType::FullBending:
        return y / ((4.0 + 2.0 * y) * gaugeFactor);
    }
    throw std::invalid_argument("shunt check: unknown bridge type");
}

ShuntCheck checkShunt(double expected, double measured, double tolerance)
{
    if (!(std::isfinite(expected) && expected != 0.0) || !std::isfinite(measured) ||
        !(std::isfinite(tolerance) && tolerance >= 0.0))
        throw std::invalid_argument("shunt check: an expected step, a measured one and a tolerance of 0 or more");
    ShuntCheck check{expected, measured, (measured - expected) / expected, false};
    check.passed = std::abs(check.deviation) <= tolerance;
    return check;
}

namespace {

struct Moments {
    double mean = 0.0;
    double variance = 0.0;  // of one sample, n − 1 in the denominator
};

Moments momentsOf(std::span<const double> values)
{
    Moments m;
    for (const double v : values) m.mean += v;
    m.mean /= static_cast<double>(values.size());
    for (const double v : values) m.variance += (v - m.mean) * (v - m.mean);
    m.variance /= static_cast<double>(values.size() - 1);
    return m;
}

}  // namespace

ShuntStep measureShuntStep(std::span<const double> off, std::span<const double> on)
{
    if (off.size() < 2 || on.size() < 2)
        throw std::invalid_argument("shunt step: two samples at least with the shunt off and with it on");
    const Moments before = momentsOf(off), during = momentsOf(on);
    return {during.mean - before.mean, std::sqrt(during.variance / static_cast<double>(on.size()) +
                                                 before.variance / static_cast<double>(off.size()))};
}

int activeGauges(BridgeType type)
{
    switch (type) {
    case BridgeType::Quarter:
        return 1;
    case BridgeType::HalfBending:
        return 2;
    case BridgeType::FullBending:
        return 4;
    }
    return 1;
}

}  // namespace tactiscope::core::straingauge
