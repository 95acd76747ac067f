// Second-order sections: response, group delay, and the cascade's run.
#include "core/dsp/Biquad.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace tactiscope::core::dsp {
namespace {

// The group delay of a polynomial c0 + c1 z⁻¹ + c2 z⁻² at ω: Re(Σ k cₖ z⁻ᵏ / Σ cₖ z⁻ᵏ).
double polynomialDelay(double c0, double c1, double c2, double omega)
{
    const std::complex<double> z1 = std::polar(1.0, -omega);
    const std::complex<double> z2 = z1 * z1;
    const std::complex<double> value = c0 + c1 * z1 + c2 * z2;
    const std::complex<double> weighted = c1 * z1 + 2.0 * c2 * z2;
    if (std::abs(value) == 0.0) return 0.0;  // on a zero: the phase jumps, its delay is not defined
    return (weighted / value).real();
}

}  // namespace

std::complex<double> Biquad::response(double cycles) const
{
    const double omega = 2.0 * std::numbers::pi * cycles;
    const std::complex<double> z1 = std::polar(1.0, -omega);
    const std::complex<double> z2 = z1 * z1;
    return (b0 + b1 * z1 + b2 * z2) / (1.0 + a1 * z1 + a2 * z2);
}

BiquadCascade::BiquadCascade(std::vector<Biquad> sections)
    : m_sections(std::move(sections)),
      m_state(m_sections.size())
{
}

void BiquadCascade::settle(double x)
{
    // For a constant input x each section's output is its DC gain times x;
    // its states are then what the difference equations leave.
    for (std::size_t i = 0; i < m_sections.size(); ++i) {
        const Biquad& q = m_sections[i];
        const double y = q.dcGain() * x;
        m_state[i].s2 = q.b2 * x - q.a2 * y;
        m_state[i].s1 = q.b1 * x - q.a1 * y + m_state[i].s2;
        x = y;
    }
    m_started = true;
}

std::optional<std::vector<double>> BiquadCascade::state() const
{
    if (!m_started) return std::nullopt;
    std::vector<double> values;
    for (const State& s : m_state) values.insert(values.end(), {s.s1, s.s2});
    return values;
}

void BiquadCascade::setState(const std::optional<std::vector<double>>& state)
{
    if (!state) return reset();
    if (state->size() != 2 * m_sections.size())
        throw std::invalid_argument("a filter's state holds " + std::to_string(state->size()) + " numbers, not " +
                                    std::to_string(2 * m_sections.size()));
    for (std::size_t i = 0; i < m_state.size(); ++i) m_state[i] = {(*state)[2 * i], (*state)[2 * i + 1]};
    m_started = true;
}

double BiquadCascade::process(double x)
{
    if (!m_started) settle(x);
    for (std::size_t i = 0; i < m_sections.size(); ++i) {
        const Biquad& q = m_sections[i];
        State& s = m_state[i];
        const double y = q.b0 * x + s.s1;
        s.s1 = q.b1 * x - q.a1 * y + s.s2;
        s.s2 = q.b2 * x - q.a2 * y;
        x = y;
    }
    return x;
}

std::complex<double> BiquadCascade::response(double cycles) const
{
    std::complex<double> h = 1.0;
    for (const Biquad& q : m_sections) h *= q.response(cycles);
    return h;
}

double BiquadCascade::groupDelay_samples(double cycles) const
{
    const double omega = 2.0 * std::numbers::pi * cycles;
    double delay = 0.0;
    for (const Biquad& q : m_sections)
        delay += polynomialDelay(q.b0, q.b1, q.b2, omega) - polynomialDelay(1.0, q.a1, q.a2, omega);
    return delay;
}

void filterZeroPhase(BiquadCascade cascade, std::span<double> values)
{
    cascade.reset();
    for (double& v : values) v = cascade.process(v);
    cascade.reset();
    for (auto it = values.rbegin(); it != values.rend(); ++it) *it = cascade.process(*it);
}

}  // namespace tactiscope::core::dsp
