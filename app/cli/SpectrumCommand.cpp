// spectrum FILE.csv --channel NAME [--window hann|flattop] [--averages N] [--json]
#include "SpectrumCommand.h"

#include "CliSupport.h"
#include "SignalInput.h"
#include "core/dsp/MainsHum.h"
#include "core/dsp/WelchSpectrum.h"
#include "core/signal/SignalColumns.h"
#include "core/text/JsonWriter.h"
#include "core/text/NumberFormat.h"

#include <QTextStream>

#include <algorithm>
#include <cmath>
#include <iostream>

namespace tactiscope::cli {
namespace {

using core::dsp::Spectrum;

QString number(double value, int digits = 4)
{
    return QString::number(value, 'g', digits);
}

// What the reader must know of how the samples were cut.
QString segmentsNote(const Spectrum& spectrum, std::size_t asked)
{
    QString fewer;
    if (spectrum.averages < asked)
        fewer = QStringLiteral("%1 averages asked, %2 fit in segments of %3 samples, the shortest")
                    .arg(asked)
                    .arg(spectrum.averages)
                    .arg(spectrum.segmentLength);
    if (spectrum.stretches <= 1 && spectrum.stretchesTooShort == 0) return fewer;
    QString note = QStringLiteral("the recording has gaps: analysed in %1 gap-free %2, never across a gap")
                       .arg(spectrum.stretches)
                       .arg(spectrum.stretches == 1 ? QStringLiteral("stretch") : QStringLiteral("stretches"));
    if (spectrum.stretchesTooShort > 0)
        note += QStringLiteral("; %1 shorter than a %2-sample segment left out")
                    .arg(spectrum.stretchesTooShort)
                    .arg(spectrum.segmentLength);
    return fewer.isEmpty() ? note : note + "; " + fewer;
}

std::string spectrumJson(const Spectrum& spectrum, const ShownUnit& unit, const QString& note)
{
    core::text::JsonWriter json;
    json.beginObject().key("unit").value(unit.unit);
    json.key("sample_rate_hz").value(spectrum.sampleRate_hz);
    json.key("window").value(core::dsp::toString(spectrum.window));
    json.key("averages").value(static_cast<long long>(spectrum.averages));
    json.key("segment_samples").value(static_cast<long long>(spectrum.segmentLength));
    json.key("resolution_hz").value(spectrum.resolution_hz());
    json.key("stretches").value(static_cast<long long>(spectrum.stretches));
    json.key("stretches_too_short").value(static_cast<long long>(spectrum.stretchesTooShort));
    json.key("noise_floor").value(core::dsp::noiseFloor(spectrum) * unit.scale);
    json.key("frequency_hz").beginArray();
    for (const double f : spectrum.frequency_hz) json.value(f);
    json.endArray().key("psd_per_sqrt_hz").beginArray();
    for (const double p : spectrum.psd) json.value(std::sqrt(p) * unit.scale);
    json.endArray().key("peaks").beginArray();
    for (const auto& peak : spectrum.peaks)
        json.beginObject()
            .key("frequency_hz")
            .value(peak.frequency_hz)
            .key("amplitude")
            .value(peak.amplitude * unit.scale)
            .endObject();
    json.endArray();
    if (!note.isEmpty()) json.key("note").value(note.toStdString());
    return json.endObject().str();
}

void printSpectrum(const SignalInput& input, const QString& channel, const Spectrum& spectrum, const ShownUnit& unit,
                   const QString& note)
{
    QTextStream out(stdout);
    const QString shown = toQString(unit.unit);
    out << input.name << ": channel " << channel << (shown.isEmpty() ? QString() : " (" + shown + ")") << ", "
        << number(input.sampleRate_hz, 6) << " Hz, "
        << number(static_cast<double>(input.sampleCount) / input.sampleRate_hz) << " s\n";
    out << "Welch: " << toQString(core::dsp::toString(spectrum.window)) << " window, " << spectrum.averages
        << (spectrum.averages == 1 ? " segment" : " averages") << " of " << spectrum.segmentLength << " samples ("
        << number(spectrum.resolution_hz()) << " Hz resolution)\n";
    if (!note.isEmpty()) out << "note: " << note << '\n';
    out << "noise floor: " << number(core::dsp::noiseFloor(spectrum) * unit.scale) << ' ' << shown << "/√Hz\n";
    if (spectrum.peaks.empty()) {
        out << "no line stands 20 dB above the spectrum\n";
        return;
    }
    out << "lines (flat-top amplitude):\n";
    for (const auto& peak : spectrum.peaks)
        out << "  " << QString::number(peak.frequency_hz, 'f', 2).rightJustified(10) << " Hz  "
            << number(peak.amplitude * unit.scale) << ' ' << shown << '\n';
}

}  // namespace

int runSpectrum(const QStringList& arguments)
{
    const QString name = QStringLiteral("spectrum");
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "The spectrum of one channel: Welch's spectral density as an amplitude (unit/√Hz, the square root of the "
        "one-sided power spectral density; psd_per_sqrt_hz in the JSON) over half-overlapping segments, "
        "each within one gap-free stretch (a gap is never bridged), and the strongest lines with their amplitude "
        "read through a flat-top window. FILE.csv is read as import reads it; --db and --session read a stored "
        "session instead."));
    parser.addPositionalArgument(QStringLiteral("FILE.csv"), QStringLiteral("The recording."));
    parser.addOptions({
        {QStringLiteral("channel"), QStringLiteral("The channel (required)."), QStringLiteral("NAME")},
        {QStringLiteral("window"),
         QStringLiteral("The density's window: hann (default) or flattop. Lines are always read through a "
                        "flat-top window."),
         QStringLiteral("hann|flattop"), QStringLiteral("hann")},
        {QStringLiteral("averages"),
         QStringLiteral("Segments to average at least (default 16): more is smoother, fewer is finer."),
         QStringLiteral("N"), QStringLiteral("16")},
        {QStringLiteral("json"), QStringLiteral("Print JSON: unit, frequency_hz, psd_per_sqrt_hz, peaks.")},
    });
    addSignalInputOptions(parser);
    if (const auto exit = parseCommandLine(parser, name, arguments)) return *exit;
    const QString usage = commandUsage(parser, name);
    const QString channelName = parser.value(QStringLiteral("channel"));
    if (channelName.isEmpty()) return usageError(QStringLiteral("spectrum: --channel is required"), usage);
    core::dsp::SpectrumSettings settings;
    const auto window = core::dsp::spectralWindowFromString(parser.value(QStringLiteral("window")).toStdString());
    if (!window)
        return usageError(
            QStringLiteral("--window is hann or flattop, not %1").arg(quoted(parser.value(QStringLiteral("window")))),
            usage);
    settings.window = *window;
    QString error;
    const auto averages = numberInRange(parser, "averages", core::kSpectrumAveragesRange, 16.0, error);
    if (!averages || *averages != std::floor(*averages)) {
        if (error.isEmpty()) error = QStringLiteral("--averages is a whole number");
        return usageError(error, usage);
    }
    settings.averages = static_cast<std::size_t>(*averages);

    SignalInput input;
    if (const auto exit = openSignalInput(parser, name, usage, input)) return *exit;
    Spectrum spectrum;
    ShownUnit unit;
    try {
        // A filtered or math channel the session was recorded with, computed
        // again as it was live; else a stored one.
        std::string problem;
        auto computed = core::signal::withRecordedSignal(*input.store, input.session, nullptr, problem);
        const auto columns = computed ? computed->channels() : std::vector<core::ChannelDescriptor>{};
        const auto column = std::ranges::find(columns, channelName.toStdString(), &core::ChannelDescriptor::name);
        std::vector<double> values;
        if (column != columns.end()) {
            values =
                std::move(computed->read(0, input.sampleCount)[static_cast<std::size_t>(column - columns.begin())]);
            unit = shownUnit(*column);
        } else {
            const auto channel = findSignalChannel(input, channelName, name, columns);
            if (!channel) return kExitUsage;
            values = input.store->readChannel(input.session, *channel, 0, input.sampleCount);
            unit = shownUnit(input.channels[*channel].descriptor);
        }
        spectrum = core::dsp::welchSpectrum(values, input.sampleRate_hz, settings);
    } catch (const core::storage::StorageError& e) {
        return storageFailure(e, QStringLiteral("spectrum: "));
    }
    if (spectrum.averages == 0) {
        printError(QStringLiteral("spectrum: %1 has no gap-free stretch of %2 samples or more, the shortest segment")
                       .arg(input.name)
                       .arg(core::dsp::kShortestSegment));
        return kExitUsage;
    }
    const QString note = segmentsNote(spectrum, settings.averages);
    if (parser.isSet(QStringLiteral("json")))
        std::cout << spectrumJson(spectrum, unit, note) << '\n';
    else
        printSpectrum(input, channelName, spectrum, unit, note);
    return kExitOk;
}

}  // namespace tactiscope::cli
