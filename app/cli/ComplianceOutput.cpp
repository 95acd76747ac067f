// ComplianceOutput: the JSON keys carry their SI units; the text states
// every uncertainty with the digits it supports.
#include "ComplianceOutput.h"

#include "CliSupport.h"
#include "core/compliance/CombinedPresses.h"
#include "core/text/JsonWriter.h"
#include "core/text/UncertaintyFormat.h"

#include <QTextStream>

#include <algorithm>
#include <cmath>
#include <iostream>

namespace tactiscope::cli {
namespace {

using namespace core;

const char* rangeName(sensors::ComplianceRange range)
{
    return range == sensors::ComplianceRange::Below ? "below" : "above";
}

QString withUncertainty(double value, double uncertainty, const char* unit = "N/m")
{
    return toQString(text::valueWithUncertainty(value, uncertainty, unit));
}

QString uncertaintyOnly(double uncertainty)
{
    // Two significant digits, as valueWithUncertainty writes them.
    if (uncertainty >= 1e4) return QString::number(uncertainty, 'g', 2);
    return QString::number(uncertainty, 'f', text::uncertaintyDecimals(uncertainty));
}

QString limitsText(double lower, double upper)
{
    return QString::number(lower, 'g', 3) + QStringLiteral("–") + QString::number(upper, 'g', 3);
}

// "limits_95_n_per_m": [lower, upper], an end beyond the probe's range null.
void writeLimits(text::JsonWriter& json, double lower, double upper)
{
    json.key("limits_95_n_per_m").beginArray();
    for (const double limit : {lower, upper})
        if (std::isfinite(limit))
            json.value(limit);
        else
            json.null();
    json.endArray();
}

QString millimetres(double metres)
{
    return QString::number(metres * 1e3, 'f', 2);
}

// No number: the presses taken together at the probe's edge (their bound),
// else (every press clipped, or none read) the presses' most common state,
// clipped first (it says what to do), with the tightest bound of that way.
struct SessionState {
    compliance::PressStatus status = compliance::PressStatus::BelowRange;
    sensors::ComplianceRange range = sensors::ComplianceRange::Below;
    std::optional<double> bound_n_per_m;
};
SessionState sessionOutOfRange(const std::optional<compliance::CombinedPresses>& combined,
                               const std::vector<compliance::PressReading>& presses)
{
    // Presses at the probe's edge, taken together: their bound.
    if (combined && combined->status != compliance::PressStatus::Ok)
        return {combined->status,
                combined->status == compliance::PressStatus::AboveRange ? sensors::ComplianceRange::Above
                                                                        : sensors::ComplianceRange::Below,
                combined->bound_n_per_m};
    const auto count = [&](compliance::PressStatus status) {
        return std::ranges::count_if(presses, [status](const auto& p) { return p.status == status; });
    };
    const auto clipped = count(compliance::PressStatus::Clipped);
    const auto above = count(compliance::PressStatus::AboveRange);
    const auto below = count(compliance::PressStatus::BelowRange);
    SessionState state;
    if (clipped >= above && clipped >= below) {
        state.status = compliance::PressStatus::Clipped;
        return state;
    }
    if (above >= below) {
        state.status = compliance::PressStatus::AboveRange;
        state.range = sensors::ComplianceRange::Above;
    }
    for (const auto& p : presses)
        if (p.status == state.status && p.bound_n_per_m)
            state.bound_n_per_m = state.bound_n_per_m ? (state.range == sensors::ComplianceRange::Above
                                                             ? std::max(*state.bound_n_per_m, *p.bound_n_per_m)
                                                             : std::min(*state.bound_n_per_m, *p.bound_n_per_m))
                                                      : *p.bound_n_per_m;
    return state;
}

QString pressStateText(const compliance::PressReading& p)
{
    if (p.status == compliance::PressStatus::Clipped)
        return QStringLiteral("clipped: the %1 beam's ADC at its limit (press less deep)")
            .arg(QLatin1String(p.atLimit.high > 0 ? "stiff" : "soft"));
    const QString bound =
        p.bound_n_per_m ? QStringLiteral(", %1 %2 N/m")
                              .arg(QLatin1String(p.status == compliance::PressStatus::BelowRange ? "below" : "above"))
                              .arg(QString::number(*p.bound_n_per_m, 'g', 3))
                        : QString();
    return QStringLiteral("%1 the probe's range%2").arg(QLatin1String(rangeName(p.stiffness.range)), bound);
}

void writePress(text::JsonWriter& json, const compliance::PressReading& p, bool withTimes)
{
    if (withTimes) {
        json.key("start_s").value(p.start_s);
        json.key("end_s").value(p.end_s);
    }
    json.key("status").value(compliance::statusName(p.status));
    if (p.status == compliance::PressStatus::Clipped) {
        json.key("samples_at_limit").beginObject();
        json.key("high").value(static_cast<long long>(p.atLimit.high));
        json.key("low").value(static_cast<long long>(p.atLimit.low));
        json.endObject();
        return;
    }
    if (p.status != compliance::PressStatus::Ok) {
        json.key("range").value(rangeName(p.stiffness.range));
        if (p.bound_n_per_m) json.key("bound_n_per_m").value(*p.bound_n_per_m);
        json.key("q").value(p.q);
        json.key("samples_out_of_range").value(static_cast<long long>(p.samplesOutOfRange));
        return;
    }
    json.key("object_stiffness_n_per_m").value(p.stiffness.objectStiffness_n_per_m);
    json.key("standard_error_n_per_m").value(p.standardError_n_per_m);
    if (p.zeroUncertainty_n_per_m) json.key("zero_uncertainty_n_per_m").value(*p.zeroUncertainty_n_per_m);
    json.key("uncertainty_n_per_m").value(p.uncertainty_n_per_m());
    writeLimits(json, p.lowerLimit_n_per_m, p.upperLimit_n_per_m);
    json.key("q").value(p.q);
    json.key("displacement_min_m").value(p.displacementMin_m);
    json.key("displacement_max_m").value(p.displacementMax_m);
    json.key("displacement_slope_n_per_m_per_m").value(p.displacementSlope_n_per_m_per_m);
    json.key("displacement_slope_standard_error_n_per_m_per_m").value(p.displacementSlopeStandardError);
}

void writeTissues(text::JsonWriter& json, const std::vector<compliance::TissuePlacement>& placed)
{
    if (placed.empty()) return;
    json.key("nearest_tissues").beginArray();
    for (std::size_t i = 0; i < std::min<std::size_t>(3, placed.size()); ++i) {
        json.beginObject();
        json.key("name").value(placed[i].tissue->name);
        json.key("distance_n_per_m").value(placed[i].distance_n_per_m);
        json.endObject();
    }
    json.endArray();
}

void printTissues(QTextStream& out, const std::vector<compliance::TissuePlacement>& placed)
{
    for (std::size_t i = 0; i < std::min<std::size_t>(3, placed.size()); ++i)
        out << "  near " << toQString(placed[i].tissue->name) << " ("
            << QString::number(placed[i].distance_n_per_m, 'f', 0) << " N/m away)\n";
}

}  // namespace

ComplianceOutput::ComplianceOutput(const sensors::CompliancePairProfile& probe)
    : m_pair(sensors::CantileverBeam(probe.high), sensors::CantileverBeam(probe.low))
{
}

int ComplianceOutput::print(bool asJson) const
{
    text::JsonWriter json;
    json.beginObject();
    QString textOut;
    QTextStream out(&textOut);
    std::optional<double> value;

    if (steps) {
        json.key("procedure").value("steps");
        if (steps->stiffness_n_per_m) {
            value = steps->stiffness_n_per_m;
            json.key("object_stiffness_n_per_m").value(*value);
            if (steps->standardError_n_per_m) json.key("standard_error_n_per_m").value(*steps->standardError_n_per_m);
        }
        json.key("steps_in_range").value(static_cast<long long>(steps->stepsInRange));
        json.key("steps").beginArray();
        for (const auto& step : steps->steps) {
            json.beginObject();
            json.key("displacement_m").value(step.displacement_m);
            json.key("readings_available").value(static_cast<long long>(step.available));
            if (!step.reading) {
                json.key("short").value(true);
            } else if (step.reading->stiffness.range != sensors::ComplianceRange::InRange) {
                json.key("range").value(rangeName(step.reading->stiffness.range));
            } else {
                json.key("object_stiffness_n_per_m").value(step.reading->stiffness.objectStiffness_n_per_m);
                json.key("q").value(step.reading->q);
                json.key("rejected_high").value(static_cast<long long>(step.reading->forceHigh.rejected));
                json.key("rejected_low").value(static_cast<long long>(step.reading->forceLow.rejected));
            }
            json.endObject();
        }
        json.endArray();
        if (value) {
            out << "object stiffness: "
                << (steps->standardError_n_per_m ? withUncertainty(*value, *steps->standardError_n_per_m)
                                                 : QString::number(*value, 'f', 1) + QStringLiteral(" N/m"))
                << " (mean of " << steps->stepsInRange << " steps; standard error from their scatter)\n";
        } else {
            out << "no step was read in range\n";
        }
        for (const auto& step : steps->steps) {
            out << "  step " << millimetres(step.displacement_m) << " mm: ";
            if (!step.reading)
                out << "short (" << step.available << " readings)\n";
            else if (step.reading->stiffness.range != sensors::ComplianceRange::InRange)
                out << rangeName(step.reading->stiffness.range) << " range\n";
            else
                out << QString::number(step.reading->stiffness.objectStiffness_n_per_m, 'f', 2) << " N/m, Q "
                    << QString::number(step.reading->q, 'f', 4) << ", rejected "
                    << step.reading->forceHigh.rejected + step.reading->forceLow.rejected << '\n';
        }
        if (!steps->stiffness_n_per_m && steps->steps.empty()) {
            printError(QStringLiteral("no reading in contact at any step"));
            return kExitUsage;
        }
    } else if (rows) {
        // The forces form: one press of every contact row.
        const auto& p = presses.front();
        const bool inRange = p.status == compliance::PressStatus::Ok;
        if (inRange) value = p.stiffness.objectStiffness_n_per_m;
        writePress(json, p, false);
        json.key("rows_used").value(static_cast<long long>(p.samplesUsed));
        json.key("rows_rejected").value(static_cast<long long>(p.samplesRejected + p.samplesOutOfRange));
        json.key("rows_skipped").value(static_cast<long long>(rows->skipped));
        if (inRange) {
            out << "object stiffness: " << withUncertainty(*value, p.standardError_n_per_m)
                << " (standard error of the noise; the zero's uncertainty is unknown: the forces were given "
                   "zeroed)\n";
            out << "rows: " << p.samplesUsed << " used, " << p.samplesRejected + p.samplesOutOfRange << " rejected, "
                << rows->skipped << " below contact\n";
            out << "displacement " << millimetres(p.displacementMin_m) << "–" << millimetres(p.displacementMax_m)
                << " mm, slope " << QString::number(p.displacementSlope_n_per_m_per_m * 1e-3, 'f', 2)
                << " N/m per mm\n";
        } else {
            out << "object stiffness out of range: " << rangeName(p.stiffness.range) << " the probe's range ("
                << p.samplesOutOfRange << " of " << p.samplesUsed + p.samplesRejected + p.samplesOutOfRange
                << " rows out of range)\n";
        }
    } else {
        if (presses.empty()) {
            printError(QStringLiteral("no press found: no stretch of a tenth of a second or more with both beams "
                                      "above the contact threshold"));
            return kExitUsage;
        }
        const auto found = compliance::combinePresses(pair(), presses);
        // A number only when the presses together are inside the probe's range.
        const auto combined = found && found->status == compliance::PressStatus::Ok ? found : std::nullopt;
        const auto read =
            std::ranges::count_if(presses, [](const auto& p) { return p.status == compliance::PressStatus::Ok; });
        const auto outOfRange = presses.size() - static_cast<std::size_t>(read);
        const auto clipped =
            std::ranges::count_if(presses, [](const auto& p) { return p.status == compliance::PressStatus::Clipped; });
        if (combined) {
            value = combined->stiffness_n_per_m;
            json.key("status").value("ok");
            json.key("object_stiffness_n_per_m").value(*value);
            json.key("standard_error_n_per_m").value(combined->standardError_n_per_m);
            if (combined->zeroUncertainty_n_per_m)
                json.key("zero_uncertainty_n_per_m").value(*combined->zeroUncertainty_n_per_m);
            json.key("uncertainty_n_per_m").value(combined->uncertainty_n_per_m());
            writeLimits(json, combined->lowerLimit_n_per_m, combined->upperLimit_n_per_m);
        } else {
            const auto state = sessionOutOfRange(found, presses);
            json.key("status").value(compliance::statusName(state.status));
            if (state.status != compliance::PressStatus::Clipped) json.key("range").value(rangeName(state.range));
            if (state.bound_n_per_m) json.key("bound_n_per_m").value(*state.bound_n_per_m);
        }
        json.key("usable_range_n_per_m");
        if (usableRange_n_per_m)
            json.beginArray().value(usableRange_n_per_m->first).value(usableRange_n_per_m->second).endArray();
        else
            json.null();
        json.key("consistency");
        if (combined && combined->birgeRatio)
            json.value(*combined->birgeRatio);
        else
            json.null();
        json.key("presses_clipped").value(static_cast<long long>(clipped));
        json.key("presses_read").value(static_cast<long long>(read));
        json.key("presses_out_of_range").value(static_cast<long long>(outOfRange));
        json.key("presses").beginArray();
        for (const auto& p : presses) {
            json.beginObject();
            writePress(json, p, true);
            json.endObject();
        }
        json.endArray();
        if (combined) {
            out << "object stiffness: " << withUncertainty(*value, combined->uncertainty_n_per_m()) << " from "
                << combined->presses << (combined->presses == 1 ? " press" : " presses");
            if (compliance::lopsidedLimits(*value, combined->lowerLimit_n_per_m, combined->upperLimit_n_per_m))
                out << " (95 % limits " << limitsText(combined->lowerLimit_n_per_m, combined->upperLimit_n_per_m)
                    << " N/m: near the probe's end a ± is lopsided)";
            if (combined->zeroUncertainty_n_per_m)
                out << " (standard uncertainty: noise " << uncertaintyOnly(combined->standardError_n_per_m) << ", zero "
                    << uncertaintyOnly(*combined->zeroUncertainty_n_per_m) << " N/m)";
            out << '\n';
        } else {
            const auto state = sessionOutOfRange(found, presses);
            if (state.status == compliance::PressStatus::Clipped)
                out << "no object stiffness: every press clipped at a beam's ADC limit (press less deep)\n";
            else
                out << "object stiffness out of range: " << rangeName(state.range) << " the probe's range"
                    << (state.bound_n_per_m
                            ? QStringLiteral(" (%1 %2 N/m)")
                                  .arg(QLatin1String(state.range == sensors::ComplianceRange::Above ? ">" : "<"))
                                  .arg(QString::number(*state.bound_n_per_m, 'g', 3))
                            : QString())
                    << '\n';
        }
        if (combined && combined->birgeRatio)
            out << "presses " << (combined->consistent ? "agree" : "DISAGREE") << ": Birge ratio "
                << QString::number(*combined->birgeRatio, 'f', 2)
                << (combined->consistent ? QString() : QStringLiteral(" (noise uncertainty scaled by it)")) << '\n';
        if (usableRange_n_per_m)
            out << "usable range of this probe at best (its beams and converters; noise and the zero narrow it "
                   "for each press): "
                << QString::number(usableRange_n_per_m->first, 'g', 3) << "–"
                << QString::number(usableRange_n_per_m->second, 'g', 3) << " N/m\n";
        else
            out << "usable range of this probe: not known (its beams' converter range is not: the device sends "
                   "strain or force, or the profile's scale gives no full scale)\n";
        if (outOfRange > 0) out << outOfRange << " presses not read (out of the probe's range or clipped)\n";
        for (const auto& p : presses) {
            out << "  press " << QString::number(p.start_s, 'f', 2) << "–" << QString::number(p.end_s, 'f', 2)
                << " s: ";
            if (p.status != compliance::PressStatus::Ok)
                out << pressStateText(p) << '\n';
            else
                out << withUncertainty(p.stiffness.objectStiffness_n_per_m, p.uncertainty_n_per_m())
                    << (compliance::lopsidedLimits(p.stiffness.objectStiffness_n_per_m, p.lowerLimit_n_per_m,
                                                   p.upperLimit_n_per_m)
                            ? QStringLiteral(" (95 %: %1)").arg(limitsText(p.lowerLimit_n_per_m, p.upperLimit_n_per_m))
                            : QString())
                    << ", depth " << millimetres(p.displacementMin_m) << "–" << millimetres(p.displacementMax_m)
                    << " mm\n";
        }
    }
    if (!basis.isEmpty()) {
        json.key("basis").value(basis.toStdString());
        out << "forces: " << basis << '\n';
    }
    if (!source.isEmpty()) {
        json.key("zero").value(recordedZeros ? "recorded" : "first_half_second");
        out << "zero: " << source << '\n';
    }
    if (sampleRate_hz) json.key("sample_rate_hz").value(*sampleRate_hz);
    const auto placed = value ? compliance::placeReading(tissues, *value) : std::vector<compliance::TissuePlacement>{};
    writeTissues(json, placed);
    printTissues(out, placed);
    json.endObject();
    if (asJson) {
        std::cout << json.str() << '\n';
    } else {
        out << "not included: the beam model's systematic terms (E, t³, L³; docs/compliance.md)\n";
        out.flush();
        QTextStream(stdout) << textOut;
    }
    return kExitOk;
}

}  // namespace tactiscope::cli
