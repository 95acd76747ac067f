// Step and press readings of the compliance probe.
#include "core/compliance/StiffnessReadings.h"

#include "core/text/JsonWriter.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tactiscope::core::compliance {

StepReader::StepReader(const sensors::CompliancePair& pair, std::size_t readings)
    : m_pair(pair),
      m_readings(readings)
{
    if (readings < 2) throw std::invalid_argument("a step reading needs at least two readings");
    m_high.reserve(readings);
    m_low.reserve(readings);
}

std::optional<StepReading> StepReader::push(double forceHigh_n, double forceLow_n)
{
    m_high.push_back(forceHigh_n);
    m_low.push_back(forceLow_n);
    if (m_high.size() < m_readings) return std::nullopt;
    StepReading reading;
    reading.forceHigh = robustMean(m_high);
    reading.forceLow = robustMean(m_low);
    reading.q = reading.forceLow.mean != 0.0 ? reading.forceHigh.mean / reading.forceLow.mean : 0.0;
    reading.stiffness = m_pair.objectStiffness(reading.q);
    m_high.clear();
    m_low.clear();
    return reading;
}

namespace {

// Q = ΣF_H/ΣF_L over the samples marked, and its standard error from the
// residuals F_H − Q·F_L (the sums' noise over ΣF_L).
struct ForceRatio {
    double q = 0.0;
    double standardError = 0.0;
    double residualSigma_n = 0.0;  // of one pair's F_H − Q·F_L
    double meanLow_n = 0.0;
    std::size_t count = 0;
};

ForceRatio forceRatio(double sumHigh, double sumLow, double sumSquaredResiduals, std::size_t count)
{
    ForceRatio ratio;
    ratio.count = count;
    if (count == 0 || !(sumLow > 0.0)) return ratio;
    const auto n = static_cast<double>(count);
    ratio.q = sumHigh / sumLow;
    ratio.meanLow_n = sumLow / n;
    if (count > 1) {
        ratio.residualSigma_n = std::sqrt(std::max(0.0, sumSquaredResiduals) / (n - 1.0));
        ratio.standardError = ratio.residualSigma_n * std::sqrt(n) / sumLow;
    }
    return ratio;
}

ForceRatio forceRatio(std::span<const double> high, std::span<const double> low, const std::vector<bool>& use)
{
    double sumHigh = 0.0, sumLow = 0.0;
    std::size_t count = 0;
    for (std::size_t i = 0; i < high.size(); ++i) {
        if (!use[i]) continue;
        sumHigh += high[i];
        sumLow += low[i];
        ++count;
    }
    if (count == 0 || !(sumLow > 0.0)) return forceRatio(sumHigh, sumLow, 0.0, count);
    const double q = sumHigh / sumLow;
    double squares = 0.0;
    for (std::size_t i = 0; i < high.size(); ++i) {
        if (use[i]) squares += (high[i] - q * low[i]) * (high[i] - q * low[i]);
    }
    return forceRatio(sumHigh, sumLow, squares, count);
}

// The reading of a force ratio: k_o, its standard error and what a force
// offset does to it (dk_o/dQ = 1/(dQ/dk_o), eq. 5).
void readRatio(const sensors::CompliancePair& pair, const ForceRatio& ratio, std::optional<ZeroUncertainty> zero,
               PressReading& r)
{
    r.q = ratio.q;
    r.stiffness = pair.objectStiffness(ratio.q);
    if (r.stiffness.range != sensors::ComplianceRange::InRange) return;
    const double dkDq = 1.0 / pair.sensitivity_m_per_n(r.stiffness.objectStiffness_n_per_m);
    r.standardError_n_per_m = dkDq * ratio.standardError;
    r.offsetSensitivityHigh_per_m = dkDq / ratio.meanLow_n;
    r.offsetSensitivityLow_per_m = -dkDq * ratio.q / ratio.meanLow_n;
    if (zero)
        r.zeroUncertainty_n_per_m =
            std::hypot(r.offsetSensitivityHigh_per_m * zero->high_n, r.offsetSensitivityLow_per_m * zero->low_n);
}

// How Q changes with depth over a press, from the residuals of the ratio:
// if Q_i = Q + q'·(d_i − d̄), then F_H,i − Q·F_L,i = a·F_L,i + q'·(d_i − d̄)·F_L,i
// plus the force noise, which is the same at every depth — so an ordinary
// least-squares fit of the residuals on F_L and (d − d̄)·F_L gives q' with
// an honest standard error, where a fit of per-sample k_o (noise ∝ 1/F_L)
// weighs the shallow samples' noise like the deep ones' signal. The
// residuals of neighbouring samples are correlated (tremor, the gauges'
// bandwidth): the standard error is widened by √((1 + ρ)/(1 − ρ)), ρ their
// lag-one correlation. An offset δ in F_H adds δ to every residual; its
// effect on q' (per newton) is returned so the zero's uncertainty can be
// carried (one of F_L acts as −Q·δ).
struct DepthSlope {
    double dqDx = 0.0;               // q', per metre
    double standardError = 0.0;      // of q', from the noise
    double dqDxPerHighOffset = 0.0;  // dq'/dδ_H, per metre per newton
};

DepthSlope depthSlope(std::span<const double> high, std::span<const double> low, std::span<const double> depth,
                      const std::vector<std::size_t>& kept, double q)
{
    double meanDepth = 0.0;
    for (const std::size_t i : kept) meanDepth += depth[i];
    meanDepth /= static_cast<double>(kept.size());
    // Normal equations of y = a·u + b·v, u = F_L, v = (d − d̄)·F_L.
    double uu = 0.0, uv = 0.0, vv = 0.0, uy = 0.0, vy = 0.0, u1 = 0.0, v1 = 0.0;
    for (const std::size_t i : kept) {
        const double u = low[i], v = (depth[i] - meanDepth) * low[i], y = high[i] - q * low[i];
        uu += u * u;
        uv += u * v;
        vv += v * v;
        uy += u * y;
        vy += v * y;
        u1 += u;
        v1 += v;
    }
    DepthSlope slope;
    const double det = uu * vv - uv * uv;
    if (!(det > 0.0)) return slope;
    const double a = (vv * uy - uv * vy) / det;
    slope.dqDx = (uu * vy - uv * uy) / det;
    slope.dqDxPerHighOffset = (uu * v1 - uv * u1) / det;  // the same fit of y = 1
    std::vector<double> residuals;
    for (const std::size_t i : kept) {
        const double u = low[i], v = (depth[i] - meanDepth) * low[i];
        residuals.push_back(high[i] - q * low[i] - a * u - slope.dqDx * v);
    }
    double squares = 0.0, lagged = 0.0;
    for (std::size_t k = 0; k < residuals.size(); ++k) {
        squares += residuals[k] * residuals[k];
        if (k > 0) lagged += residuals[k] * residuals[k - 1];
    }
    const double n = static_cast<double>(residuals.size());
    if (n <= 2.0 || !(squares > 0.0)) return slope;
    const double rho = std::clamp(lagged / squares, 0.0, 0.95);
    const double sigma2 = squares / (n - 2.0);
    slope.standardError = std::sqrt(sigma2 * uu / det) * std::sqrt((1.0 + rho) / (1.0 - rho));
    return slope;
}

// A ratio within 2u of a limit of the probe is out of its range: the
// bound is k_o at 2u from the ratio, towards the inside (none when that is
// outside too).
void classifyRange(const sensors::CompliancePair& pair, double q, double uQ, PressReading& r)
{
    const double qMax = pair.qMax();
    const auto inside = [&](double ratio) -> std::optional<double> {
        const auto k = pair.objectStiffness(ratio);
        if (k.range != sensors::ComplianceRange::InRange) return std::nullopt;
        return k.objectStiffness_n_per_m;
    };
    if (q - 2.0 * uQ <= 1.0) {
        r.status = PressStatus::BelowRange;
        r.bound_n_per_m = inside(q + 2.0 * uQ);
        r.stiffness.range = sensors::ComplianceRange::Below;
    } else if (q + 2.0 * uQ >= qMax) {
        r.status = PressStatus::AboveRange;
        r.bound_n_per_m = inside(q - 2.0 * uQ);
        r.stiffness.range = sensors::ComplianceRange::Above;
    }
}

}  // namespace

double PressReading::uncertainty_n_per_m() const
{
    return std::hypot(standardError_n_per_m, zeroUncertainty_n_per_m.value_or(0.0));
}

const char* statusName(PressStatus status)
{
    switch (status) {
    case PressStatus::Ok:
        return "ok";
    case PressStatus::Clipped:
        return "clipped";
    case PressStatus::BelowRange:
        return "below-range";
    case PressStatus::AboveRange:
        return "above-range";
    }
    return "ok";
}

PressReading readPress(const sensors::CompliancePair& pair, std::span<const double> displacement,
                       std::span<const double> forceHigh, std::span<const double> forceLow,
                       std::optional<ZeroUncertainty> zero, BeamLimits atLimit)
{
    if (displacement.empty() || displacement.size() != forceHigh.size() || forceHigh.size() != forceLow.size())
        throw std::invalid_argument("a press needs equal, non-empty series of displacement and forces");
    PressReading r;
    r.atLimit = atLimit;
    // Every sample in contact: a cut by each sample's own Q would keep the
    // noise on one side only and bias the ratio (soft objects high).
    std::vector<bool> use(displacement.size(), true);
    for (std::size_t i = 0; i < displacement.size(); ++i)
        if (pair.objectStiffness(forceHigh[i] / forceLow[i]).range != sensors::ComplianceRange::InRange)
            ++r.samplesOutOfRange;
    // One 3σ rejection on the residuals, then the ratio of the kept pairs.
    const ForceRatio first = forceRatio(forceHigh, forceLow, use);
    const double sigma = first.residualSigma_n;
    for (std::size_t i = 0; i < use.size() && sigma > 0.0; ++i) {
        if (use[i] && std::abs(forceHigh[i] - first.q * forceLow[i]) > 3.0 * sigma) {
            use[i] = false;
            ++r.samplesRejected;
        }
    }
    const ForceRatio kept = forceRatio(forceHigh, forceLow, use);
    r.samplesUsed = kept.count;
    readRatio(pair, kept, zero, r);
    // The ratio's own uncertainty (noise and zero) decides whether it is in
    // range: an offset δ in F_H moves Q by δ/F̄_L, one in F_L by −Q·δ/F̄_L.
    r.ratioStandardError = r.ratioUncertainty = kept.standardError;
    if (zero && kept.meanLow_n > 0.0)
        r.ratioUncertainty =
            std::hypot(kept.standardError, std::hypot(zero->high_n, kept.q * zero->low_n) / kept.meanLow_n);
    classifyRange(pair, kept.q, r.ratioUncertainty, r);
    if (r.status == PressStatus::Ok) {
        r.lowerLimit_n_per_m = pair.objectStiffness(kept.q - 2.0 * r.ratioUncertainty).objectStiffness_n_per_m;
        r.upperLimit_n_per_m = pair.objectStiffness(kept.q + 2.0 * r.ratioUncertainty).objectStiffness_n_per_m;
    }
    if (atLimit.high + atLimit.low > 0) r.status = PressStatus::Clipped;  // whatever the ratio says
    if (r.status != PressStatus::Ok) return r;

    // Range and slope over the kept samples only: a rejected spike must not
    // tilt the displacement check either.
    std::vector<std::size_t> used;
    for (std::size_t i = 0; i < use.size(); ++i)
        if (use[i]) used.push_back(i);
    if (used.empty()) return r;
    r.displacementMin_m = r.displacementMax_m = displacement[used.front()];
    for (const std::size_t i : used) {
        r.displacementMin_m = std::min(r.displacementMin_m, displacement[i]);
        r.displacementMax_m = std::max(r.displacementMax_m, displacement[i]);
    }
    if (r.displacementMax_m > r.displacementMin_m && used.size() >= 3) {
        const auto slope = depthSlope(forceHigh, forceLow, displacement, used, r.q);
        const double dkDq = 1.0 / pair.sensitivity_m_per_n(r.stiffness.objectStiffness_n_per_m);
        r.displacementSlope_n_per_m_per_m = dkDq * slope.dqDx;
        // The zero's offsets tilt the ratio against depth too (k_o error ∝ 1/force).
        const double zeroPart =
            zero ? std::abs(slope.dqDxPerHighOffset) * std::hypot(zero->high_n, r.q * zero->low_n) : 0.0;
        r.displacementSlopeStandardError = dkDq * std::hypot(slope.standardError, zeroPart);
    }
    return r;
}

PressReader::PressReader(const sensors::CompliancePair& pair, PressSettings settings)
    : m_pair(pair),
      m_settings(settings)
{
    if (!(settings.contactThreshold_n > 0.0)) throw std::invalid_argument("contact threshold must be positive");
}

std::optional<PressReading> PressReader::push(double t_s, double displacement_m, double forceHigh_n, double forceLow_n,
                                              BeamLimits atLimit)
{
    const double threshold = m_settings.contactThreshold_n;
    std::optional<PressReading> ended;
    if (m_pressing && (forceHigh_n < 0.5 * threshold || forceLow_n < 0.5 * threshold)) ended = close();
    if (!m_pressing && forceHigh_n > threshold && forceLow_n > threshold) {
        m_pressing = true;
        m_start_s = t_s;
    }
    if (m_pressing) {
        m_last_s = t_s;
        m_atLimit.high += atLimit.high;
        m_atLimit.low += atLimit.low;
        m_displacement.push_back(displacement_m);
        m_forceHigh.push_back(forceHigh_n);
        m_forceLow.push_back(forceLow_n);
        ++m_count;
        m_sumHigh += forceHigh_n;
        m_sumLow += forceLow_n;
        m_sumHighHigh += forceHigh_n * forceHigh_n;
        m_sumHighLow += forceHigh_n * forceLow_n;
        m_sumLowLow += forceLow_n * forceLow_n;
    }
    return ended;
}

std::optional<std::pair<double, double>> PressReader::current() const
{
    if (!m_pressing || m_count < 2 || !(m_sumLow > 0.0)) return std::nullopt;
    const double q = m_sumHigh / m_sumLow;
    // Σ(F_H − Q·F_L)² from the running sums.
    const double residuals = m_sumHighHigh - 2.0 * q * m_sumHighLow + q * q * m_sumLowLow;
    PressReading r;
    readRatio(m_pair, forceRatio(m_sumHigh, m_sumLow, residuals, m_count), std::nullopt, r);
    if (r.stiffness.range != sensors::ComplianceRange::InRange) return std::nullopt;
    return std::pair{r.stiffness.objectStiffness_n_per_m, r.standardError_n_per_m};
}

std::optional<PressReading> PressReader::finish()
{
    return m_pressing ? close() : std::nullopt;
}

std::optional<PressReading> PressReader::close()
{
    m_pressing = false;
    std::optional<PressReading> result;
    if (m_displacement.size() >= m_settings.minimumSamples) {
        result = readPress(m_pair, m_displacement, m_forceHigh, m_forceLow, m_zero, m_atLimit);
        result->start_s = m_start_s;
        result->end_s = m_last_s;
    }
    dropPress();
    return result;
}

void PressReader::dropPress()
{
    m_pressing = false;
    m_displacement.clear();
    m_forceHigh.clear();
    m_forceLow.clear();
    m_atLimit = {};
    m_count = 0;
    m_sumHigh = m_sumLow = m_sumHighHigh = m_sumHighLow = m_sumLowLow = 0.0;
}

std::string pressDetailsJson(const PressReading& reading)
{
    text::JsonWriter json;
    json.beginObject();
    json.key("q").value(reading.q);
    json.key("noise_standard_error_n_per_m").value(reading.standardError_n_per_m);
    if (reading.zeroUncertainty_n_per_m) json.key("zero_uncertainty_n_per_m").value(*reading.zeroUncertainty_n_per_m);
    json.key("displacement_min_m").value(reading.displacementMin_m);
    json.key("displacement_max_m").value(reading.displacementMax_m);
    json.key("displacement_slope_n_per_m_per_m").value(reading.displacementSlope_n_per_m_per_m);
    json.key("displacement_slope_standard_error_n_per_m_per_m").value(reading.displacementSlopeStandardError);
    json.key("samples_used").value(static_cast<long long>(reading.samplesUsed));
    json.key("samples_rejected").value(static_cast<long long>(reading.samplesRejected));
    json.key("samples_out_of_range").value(static_cast<long long>(reading.samplesOutOfRange));
    json.endObject();
    return json.str();
}

bool lopsidedLimits(double value, double lower, double upper)
{
    const double below = value - lower, above = upper - value;
    return below > 0.0 && above > 0.0 && std::max(below, above) >= 1.5 * std::min(below, above);
}

std::optional<std::pair<double, double>>
usableRange(const sensors::CompliancePair& pair, std::optional<BeamResolution> high, std::optional<BeamResolution> low)
{
    if (!high || !low || !(high->step_n > 0.0) || !(low->step_n > 0.0) || !(high->fullScale_n > 0.0) ||
        !(low->fullScale_n > 0.0))
        return std::nullopt;
    // u of Q = F_H/F_L at its deepest press, quantization alone.
    const auto u = [&](double q) {
        const double forceLow = std::min(low->fullScale_n, high->fullScale_n / q);
        return std::hypot(high->step_n, q * low->step_n) / std::sqrt(12.0) / forceLow;
    };
    const double lowest = 1.0 + 2.0 * u(1.0), highest = pair.qMax() - 2.0 * u(pair.qMax());
    if (!(highest > lowest)) return std::nullopt;
    return std::pair{pair.objectStiffness(lowest).objectStiffness_n_per_m,
                     pair.objectStiffness(highest).objectStiffness_n_per_m};
}

PressSettings pressSettingsAt(double sampleRate_hz)
{
    PressSettings settings;
    settings.minimumSamples = std::max<std::size_t>(20, static_cast<std::size_t>(0.1 * sampleRate_hz));
    return settings;
}

}  // namespace tactiscope::core::compliance
