// CapacitiveCalibrationOutput: the calibration as text or JSON.
#include "CapacitiveCalibrationOutput.h"

#include "CliSupport.h"
#include "core/text/JsonWriter.h"
#include "core/text/UncertaintyFormat.h"

#include <QTextStream>

#include <algorithm>
#include <cmath>
#include <iostream>

namespace tactiscope::cli {

using namespace core;

namespace {

// What the sensitivity's ± rests on, in the JSON's words.
const char* uncertaintyBasis(const calibration::CapacitiveCalibrationResult& result)
{
    if (!result.sensitivityUncertainty) return "scatter";
    return result.sensitivityUncertainty->widened ? "propagated-widened" : "propagated";
}

}  // namespace

void writeCapacitiveJson(const calibration::CapacitiveCalibrationResult& result,
                         const calibration::CapacitiveSteps& steps, bool timed, const SweepReport* sweep)
{
    text::JsonWriter json;
    json.beginObject();
    if (sweep) {
        json.key("reference").value(sweep->reference);
        json.key("capacitance").value(sweep->capacitance);
        json.key("reference_zero_n").value(sweep->zero_n);
        json.key("sweep_span_n").value(sweep->span_n);
        json.key("sweep_turns").value(static_cast<long long>(sweep->turns));
        json.key("beam_lag_s").value(sweep->lag_s);
        json.key("paired_samples").value(static_cast<long long>(sweep->paired));
        json.key("unpaired_samples").value(static_cast<long long>(sweep->outside));
        json.key("clock_u_s");
        if (sweep->clockUncertainty_s) {
            json.value(*sweep->clockUncertainty_s);
            json.key("timing_force_u_n").value(*sweep->clockUncertainty_s * sweep->steepest_n_per_s);
        } else {
            json.null();
        }
    }
    for (const auto& [key, value] : result.record.values) {
        if (key == "drift_pf_per_s" && !timed) continue;  // no time base: no drift
        json.key(key).value(value);
    }
    json.key("sensitivity_standard_error_pf_per_mn").value(result.forceFit->slopeStandardError * 1e9);
    json.key("sensitivity_uncertainty").value(uncertaintyBasis(result));
    json.key("baseline_wander_pf_per_sqrt_s");
    if (steps.input.baselineWander_f_per_sqrt_s)
        json.value(*steps.input.baselineWander_f_per_sqrt_s * 1e12);
    else
        json.null();
    if (result.hysteresisNoise) json.key("hysteresis_noise_fraction").value(*result.hysteresisNoise);
    json.key("detection_limit_mgf").value(*result.detectionLimit_n / calibration::kMilligramForce_n);
    json.key("baseline_samples").value(static_cast<long long>(steps.input.baseline.count));
    if (steps.finalShift_f) json.key("final_baseline_shift_pf").value(*steps.finalShift_f * 1e12);
    json.key("points").value(static_cast<long long>(result.forceFit->points));
    json.key("steps_unsettled").value(static_cast<long long>(steps.unsettled));
    json.key("cautions").beginArray();
    for (const std::string& caution : result.cautions) json.value(caution);
    json.endArray();
    json.key("steps").beginArray();
    for (const auto& step : steps.steps) {
        json.beginObject();
        json.key("force_n").value(step.force_n);
        json.key("loading").value(step.loading);
        json.key("capacitance_pf").value(step.window.mean * 1e12);
        json.key("samples").value(static_cast<long long>(step.window.count));
        if (timed) {
            json.key("start_s").value(step.window.start_s);
            json.key("end_s").value(step.window.end_s);
        }
        json.endObject();
    }
    json.endArray();
    json.endObject();
    std::cout << json.str() << '\n';
}

void writeCapacitiveText(const calibration::CapacitiveCalibrationResult& result,
                         const calibration::CapacitiveSteps& steps, bool timed, const SweepReport* sweep)
{
    QTextStream out(stdout);
    if (sweep) {
        out << "reference: " << toQString(sweep->reference) << " (its zero "
            << QString::number(sweep->zero_n * 1e6, 'f', 2) << " µN, taken off), against "
            << toQString(sweep->capacitance) << "; sweep to " << QString::number(sweep->span_n * 1e3, 'f', 4) << " mN, "
            << sweep->turns << (sweep->turns == 1 ? " turn; " : " turns; ") << sweep->paired << " samples paired";
        if (sweep->outside > 0) out << ", " << sweep->outside << " outside the reference's samples (left out)";
        out << "\nlag: the beam settles behind the reference with τ = " << QString::number(sweep->lag_s, 'f', 3)
            << " s (a first-order lag), taken out before the points are binned\n";
        if (sweep->clockUncertainty_s && *sweep->clockUncertainty_s > 0.0)  // two devices' clocks
            out << "timing: the two clocks agree within ±" << QString::number(*sweep->clockUncertainty_s * 1e3, 'f', 3)
                << " ms (standard), at most "
                << QString::number(*sweep->clockUncertainty_s * sweep->steepest_n_per_s * 1e6, 'f', 3)
                << " µN on the sweep's steepest part (" << QString::number(sweep->steepest_n_per_s * 1e6, 'f', 1)
                << " µN/s); an offset between the clocks acts as a lag, and goes out with the beam's\n";
    }
    out << "C0: " << QString::number(result.c0_f * 1e12, 'f', 4) << " pF (baseline σ "
        << QString::number(result.baselineSigma_f * 1e12, 'f', 4) << " pF over " << steps.input.baseline.count
        << (timed ? " samples of the first baseline)\n" : " rows of the first baseline)\n");
    if (steps.finalShift_f) {
        if (timed)
            out << "drift: " << QString::number(result.drift_f_per_s * 1e12, 'g', 3) << " pF/s (the final baseline is "
                << QString::number(*steps.finalShift_f * 1e12, 'f', 4)
                << " pF from C0), removed before ΔC and the hysteresis\n";
        else
            out << "final baseline " << QString::number(*steps.finalShift_f * 1e12, 'f', 4)
                << " pF from C0: not removed (no time column to spread it over)\n";
    }
    const auto& fit = *result.forceFit;
    out << "sensitivity: " << toQString(text::valueWithUncertainty(fit.slope * 1e9, fit.slopeStandardError * 1e9))
        << " pF/mN, intercept " << QString::number(fit.intercept * 1e12, 'f', 4) << " pF, R² "
        << QString::number(fit.rSquared, 'f', 5) << " (" << fit.points << " points)\n";
    if (result.sensitivityUncertainty)
        out << "  its ±: the steps' and the baselines' noise"
            << (steps.input.baselineWander_f_per_sqrt_s
                    ? QStringLiteral(" and the baseline's wander (%1 pF/√s given)")
                          .arg(*steps.input.baselineWander_f_per_sqrt_s * 1e12, 0, 'g', 3)
                    : QStringLiteral("; not the baseline's wander between its two baselines (give the beam's "
                                     "stability with --baseline-wander)"))
            << (result.sensitivityUncertainty->widened
                    ? QStringLiteral(", widened by %1 for the points' scatter beyond them")
                          .arg(std::sqrt(result.sensitivityUncertainty->chiSquarePerDegree), 0, 'f', 2)
                    : QString())
            << '\n';
    else if (!result.sensitivityUncertainty)
        out << "  its ±: the points' scatter about the line (the steps' own noise is not known)\n";
    if (sweep)
        out << "  a sweep reads the beam at its pace: a creep slower than the sweep is not followed, and reads the "
               "sensitivity low by up to its fraction × its time over the ramp's, outside the ± (weights held till "
               "settled read the crept-to-rest value)\n";
    out << "relative sensitivity: " << QString::number(*result.relativeSensitivity_per_n * 1e-3, 'f', 4) << " per mN";
    if (result.pressureSensitivity_per_pa)
        out << ", " << QString::number(*result.pressureSensitivity_per_pa * 1e3, 'f', 3) << " per kPa";
    out << "\ndetection limit: " << QString::number(*result.detectionLimit_n * 1e6, 'f', 1) << " µN ("
        << QString::number(*result.detectionLimit_n / calibration::kMilligramForce_n, 'f', 2) << " mgf, 3σ of C0)\n";
    if (result.hysteresis) {
        out << "hysteresis: " << QString::number(*result.hysteresis * 100.0, 'f', 2) << " % of full scale";
        // Noise alone reads up to twice a difference's u: below that, no hysteresis is shown.
        if (result.hysteresisNoise)
            out << (*result.hysteresis > *result.hysteresisNoise
                        ? QStringLiteral(", above the %1 % the steps' noise alone can read: the silicone's, at most")
                        : QStringLiteral(", within the %1 % the steps' noise alone can read: no hysteresis shown"))
                       .arg(*result.hysteresisNoise * 100.0, 0, 'f', 2);
        out << '\n';
    }
    const auto unloading = std::ranges::count_if(steps.steps, [](const auto& s) { return !s.loading; });
    out << (sweep ? "points: " : "steps: ") << steps.steps.size() - static_cast<std::size_t>(unloading) << " loading, "
        << unloading << " unloading";
    if (steps.unsettled > 0) out << ", " << steps.unsettled << " never settled (left out)";
    out << '\n';
    for (const std::string& caution : result.cautions) out << "caution: " << QString::fromStdString(caution) << '\n';
}

}  // namespace tactiscope::cli
