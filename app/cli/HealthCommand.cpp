// health FILE.csv [--json]: one pass over every channel, read in windows.
#include "HealthCommand.h"

#include "CliSupport.h"
#include "SignalInput.h"
#include "core/dsp/SignalHealth.h"
#include "core/report/SignalQuality.h"
#include "core/text/JsonWriter.h"
#include "core/text/NumberFormat.h"
#include "core/text/UncertaintyFormat.h"

#include <QTextStream>

#include <cmath>
#include <iostream>
#include <optional>

namespace tactiscope::cli {
namespace {

using core::dsp::ChannelHealth;

constexpr double kSecondsPerHour = 3600.0;

struct Row {
    std::string channel;
    ShownUnit unit;
    ChannelHealth health;
    bool clippingJudged = true;  // not for a position (ChannelQuality::drifts)
    bool creepJudged = false;    // a capacitance channel's (ChannelQuality::creep)
    std::optional<core::dsp::StepCreep> creep;
};

// A capacitive beam's creep after its load steps; null where none was found
// or the channel is not a beam's.
void creepJson(core::text::JsonWriter& json, const Row& row)
{
    json.key("creep");
    if (!row.creep) {
        json.null();
        return;
    }
    const auto& c = *row.creep;
    json.beginObject()
        .key("steps")
        .value(static_cast<long long>(c.steps))
        .key("fraction")
        .value(c.fraction)
        .key("fraction_u");
    if (c.fractionU)
        json.value(*c.fractionU);
    else
        json.null();
    json.key("time_constant_s")
        .value(c.timeConstant_s)
        .key("time_constant_s_u")
        .value(c.timeConstantU_s)
        .key("settle_time_s")
        .value(c.settleTime_s)
        .endObject();
}

std::string healthJson(const std::vector<Row>& rows)
{
    core::text::JsonWriter json;
    json.beginArray();
    for (const Row& row : rows) {
        const ChannelHealth& h = row.health;
        const double scale = row.unit.scale;
        json.beginObject().key("channel").value(row.channel).key("unit").value(row.unit.unit);
        if (h.hum)
            json.key("hum_hz").value(h.hum->mains_hz).key("hum_amplitude").value(h.hum->amplitude * scale);
        else
            json.key("hum_hz").null().key("hum_amplitude").null();
        json.key("noise_floor").value(h.noiseFloor_per_sqrt_hz * scale);
        if (h.drift)
            json.key("drift_per_hour")
                .value(h.drift->rate_per_s * kSecondsPerHour * scale)
                .key("drift_per_hour_u")
                .value(h.drift->standardUncertainty_per_s * kSecondsPerHour * scale);
        else
            json.key("drift_per_hour").null().key("drift_per_hour_u").null();
        if (row.clippingJudged)
            json.key("clipped").value(static_cast<long long>(h.clipped));
        else
            json.key("clipped").null();
        json.key("samples").value(static_cast<long long>(h.samples));
        json.key("missing").value(static_cast<long long>(h.missing));
        if (h.hum) json.key("hum_line_hz").value(h.hum->line_hz);
        json.key("resolution_hz").value(h.resolution_hz);
        creepJson(json, row);
        json.endObject();
    }
    return json.endArray().str();
}

QString number(double value)
{
    return QString::number(value, 'g', 3);
}

void printHealth(const QString& name, const std::vector<Row>& rows)
{
    QTextStream out(stdout);
    out << name << ": signal health (noise floor in unit/√Hz; drift ± is its standard uncertainty, k = 1)\n";
    for (const Row& row : rows) {
        const ChannelHealth& h = row.health;
        const QString unit = toQString(row.unit.unit);
        const QString spaced = unit.isEmpty() ? QString() : " " + unit;  // a pure number has none
        const double scale = row.unit.scale;
        out << "  " << toQString(row.channel) << (unit.isEmpty() ? QString() : " [" + unit + "]") << ": ";
        out << (h.hum ? QStringLiteral("hum %1 Hz, %2%3")
                            .arg(h.hum->mains_hz)
                            .arg(number(h.hum->amplitude * scale), spaced)
                      : QStringLiteral("no hum"));
        if (std::isfinite(h.noiseFloor_per_sqrt_hz))
            out << ", noise floor " << number(h.noiseFloor_per_sqrt_hz * scale) << spaced << "/√Hz";
        else
            out << ", noise floor: no gap-free stretch long enough for a spectrum";
        if (h.drift)
            out << ", drift "
                << toQString(
                       core::text::valueWithUncertainty(h.drift->rate_per_s * kSecondsPerHour * scale,
                                                        h.drift->standardUncertainty_per_s * kSecondsPerHour * scale))
                << spaced << "/h";
        else if (h.span_s < core::dsp::kShortestDrift_s)
            out << ", drift: from " << core::dsp::kShortestDrift_s << " s on";
        else
            out << ", drift: too much lost";
        if (row.clippingJudged) out << ", " << h.clipped << " clipped";
        if (h.missing > 0) out << ", " << h.missing << " missing";
        if (row.creep) {
            const auto& c = *row.creep;
            const std::string share = c.fractionU
                                          ? core::text::valueWithUncertainty(c.fraction * 100.0, *c.fractionU * 100.0)
                                          : core::text::formatShortest(std::round(c.fraction * 1000.0) / 10.0);
            out << ", creep " << toQString(share) << " % of a step"
                << (c.fractionU ? QString() : QStringLiteral(" (a ± needs three steps)")) << ", τ "
                << toQString(core::text::valueWithUncertainty(c.timeConstant_s, c.timeConstantU_s)) << " s (" << c.steps
                << (c.steps == 1 ? " step" : " steps") << "; the beam's own swing τ " << number(c.settleTime_s)
                << " s)";
        } else if (row.creepJudged) {
            out << ", creep: none told from the noise";
        }
        out << '\n';
    }
}

}  // namespace

int runHealth(const QStringList& arguments)
{
    const QString name = QStringLiteral("health");
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "Each channel's signal health: mains hum (50 or 60 Hz, its amplitude in the channel's unit), noise floor "
        "(median amplitude spectral density above 1 Hz), drift per hour with its standard uncertainty (a line "
        "through 100 interval means), and clipped samples; for a capacitive beam, the creep after its load steps "
        "(its share of a step and its time constant, each with its standard uncertainty). FILE.csv is read as "
        "import reads it; --db and --session read a stored session instead, and the filtered and math channels "
        "it was recorded with after its own, computed again as they were live."));
    parser.addPositionalArgument(QStringLiteral("FILE.csv"), QStringLiteral("The recording."));
    parser.addOption({QStringLiteral("json"),
                      QStringLiteral("Print JSON: per channel channel, unit, hum_hz, hum_amplitude, noise_floor, "
                                     "drift_per_hour, drift_per_hour_u, clipped, creep (null but for a beam).")});
    addSignalInputOptions(parser);
    if (const auto exit = parseCommandLine(parser, name, arguments)) return *exit;
    const QString usage = commandUsage(parser, name);
    SignalInput input;
    if (const auto exit = openSignalInput(parser, name, usage, input)) return *exit;

    std::vector<Row> rows;
    try {
        for (const auto& q : core::report::channelQuality(*input.store, input.session, 0, input.sampleCount))
            rows.push_back({q.channel.name, shownUnit(q.channel), q.health, q.drifts, q.creepJudged, q.creep});
        // The filtered and math channels it was recorded with, computed
        // again as they were live, after them: a report's rows.
        std::string problem;
        for (const auto& q :
             core::report::recordedSignalQuality(*input.store, input.session, 0, input.sampleCount, SIZE_MAX, problem))
            rows.push_back({q.channel.name, shownUnit(q.channel), q.health, q.drifts, q.creepJudged, q.creep});
        if (!problem.empty()) printError(QStringLiteral("note: %1").arg(toQString(problem)));
    } catch (const core::storage::StorageError& e) {
        return storageFailure(e, QStringLiteral("health: "));
    }
    if (parser.isSet(QStringLiteral("json")))
        std::cout << healthJson(rows) << '\n';
    else
        printHealth(input.name, rows);
    return kExitOk;
}

}  // namespace tactiscope::cli
