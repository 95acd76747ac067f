// Reading the filter and math-channel options.
#include "SignalOptions.h"

#include "CliSupport.h"
#include "core/NumberRanges.h"

#include <algorithm>
#include <cmath>
#include <tuple>

namespace tactiscope::cli {

QList<QCommandLineOption> filterOptions()
{
    return {
        {QStringLiteral("notch"), QStringLiteral("Notch the mains: 50 or 60 Hz, with its 2nd and 3rd harmonics."),
         QStringLiteral("50|60")},
        {QStringLiteral("lowpass"), QStringLiteral("Butterworth low-pass, −3 dB at HZ."), QStringLiteral("HZ")},
        {QStringLiteral("highpass"), QStringLiteral("Butterworth high-pass, −3 dB at HZ (with --lowpass: band-pass)."),
         QStringLiteral("HZ")},
        {QStringLiteral("order"), QStringLiteral("The Butterworth filters' order, 2 to 8 (default 4)."),
         QStringLiteral("N")},
        {QStringLiteral("moving-average"), QStringLiteral("A moving average over S seconds, last."),
         QStringLiteral("S")},
    };
}

std::optional<QString> readFilterSettings(const QCommandLineParser& parser, core::dsp::FilterSettings& s)
{
    QString error;
    if (parser.isSet(QStringLiteral("notch"))) {
        s.notch_hz = parseMainsFrequency(QStringLiteral("notch"), parser.value(QStringLiteral("notch")), error);
        if (!s.notch_hz) return error;
    }
    for (const auto& [option, cutoff] : {std::pair{"lowpass", &s.lowpass_hz}, std::pair{"highpass", &s.highpass_hz}}) {
        if (!parser.isSet(QLatin1String(option))) continue;
        *cutoff = numberInRange(parser, option, core::kFilterCutoffRange, 0.0, error);
        if (!*cutoff) return error;
    }
    const auto order = numberInRange(parser, "order", core::kFilterOrderRange, 4.0, error);
    if (!order || *order != std::floor(*order))
        return error.isEmpty() ? QStringLiteral("--order is a whole number, 2 to 8, not %1")
                                     .arg(parser.value(QStringLiteral("order")))
                               : error;
    s.order = static_cast<int>(*order);
    const auto average = numberInRange(parser, "moving-average", core::kMovingAverageRange, 0.0, error);
    if (!average) return error;
    s.movingAverage_s = *average;
    if (parser.isSet(QStringLiteral("order")) && !s.lowpass_hz && !s.highpass_hz)
        return QStringLiteral("--order is the Butterworth filters': give --lowpass or --highpass with it");
    return std::nullopt;
}

QList<QCommandLineOption> signalOptions()
{
    QList<QCommandLineOption> options = filterOptions();
    options.append({
        {QStringLiteral("filter-channel"),
         QStringLiteral("The channel the filter options filter, live (repeatable; default: every channel). Its "
                        "filtered values are watched as NAME.filtered; the stored samples stay as they came, and "
                        "the session keeps the filter. With several devices: DEVICE/NAME."),
         QStringLiteral("NAME")},
        {QStringLiteral("analyze-filtered"),
         QStringLiteral("The mode's analysis (detector, presses, force) reads the filtered channels instead of the "
                        "samples as they came; the session records it, and analyze does the same.")},
        {QStringLiteral("math"),
         QStringLiteral("A math channel computed live over the channels (filtered ones as filtered), "
                        "NAME[UNIT]=EXPR, e.g. \"diff[µε]=a - b\" (repeatable; units are checked); watch it with "
                        "--limit or --trigger by NAME, in its UNIT. The session keeps it. With several devices, "
                        "each over one device's channels: DEVICE/NAME[UNIT]=EXPR."),
         QStringLiteral("NAME[UNIT]=EXPR")},
    });
    return options;
}

namespace {

// One device's setup from the options' values: `settings` on each of
// `named` (every channel of `channels` when none is named), the math
// definitions, and whether the analysis reads the filtered channels.
std::optional<QString> readSetup(const core::dsp::FilterSettings& settings, const QStringList& named,
                                 const QStringList& definitions, bool analysisFiltered,
                                 const std::vector<std::string>& channels, core::signal::SignalSetup& setup)
{
    if (!settings.empty()) {
        std::vector<std::string> filtered;
        for (const QString& channel : named) filtered.push_back(channel.toStdString());
        if (filtered.empty()) filtered = channels;
        for (const std::string& channel : filtered) {
            if (std::ranges::find(channels, channel) == channels.end())
                return QStringLiteral("--filter-channel: the device has no channel %1")
                    .arg(quoted(QString::fromStdString(channel)));
            if (!setup.filterOf(channel)) setup.filters.push_back({channel, settings});
        }
    }
    setup.analysisFiltered = analysisFiltered && !setup.filters.empty();
    try {
        for (const QString& definition : definitions)
            setup.math.push_back(core::math::parseMathDefinition(definition.toStdString()));
    } catch (const core::math::MathError& e) {
        return QStringLiteral("--math: %1").arg(QString::fromStdString(e.what()));
    }
    return std::nullopt;
}

// The filter settings and the checks every reading shares.
std::optional<QString> readSettings(const QCommandLineParser& parser, core::dsp::FilterSettings& settings)
{
    if (auto error = readFilterSettings(parser, settings)) return error;
    if (settings.empty() && parser.isSet(QStringLiteral("filter-channel")))
        return QStringLiteral("--filter-channel names what the filter options filter: give --notch, --lowpass, "
                              "--highpass or --moving-average");
    if (parser.isSet(QStringLiteral("analyze-filtered")) && settings.empty())
        return QStringLiteral("--analyze-filtered: give the filter to analyse through (--notch, --lowpass, …)");
    return std::nullopt;
}

}  // namespace

std::optional<QString> readSignalSetup(const QCommandLineParser& parser, const std::vector<std::string>& channels,
                                       core::signal::SignalSetup& setup)
{
    core::dsp::FilterSettings settings;
    if (auto error = readSettings(parser, settings)) return error;
    return readSetup(settings, parser.values(QStringLiteral("filter-channel")), parser.values(QStringLiteral("math")),
                     parser.isSet(QStringLiteral("analyze-filtered")), channels, setup);
}

std::optional<QString> readSignalSetups(const QCommandLineParser& parser, const std::vector<std::string>& devices,
                                        const std::vector<std::vector<std::string>>& channels,
                                        std::vector<core::signal::SignalSetup>& setups)
{
    core::dsp::FilterSettings settings;
    if (auto error = readSettings(parser, settings)) return error;
    // Each value goes to the device named before its first '/', without it.
    std::vector<QStringList> named(devices.size());
    std::vector<QStringList> math(devices.size());
    for (const auto& [option, form, byDevice] : {std::tuple{"filter-channel", "DEVICE/CHANNEL", &named},
                                                 std::tuple{"math", "DEVICE/NAME[UNIT]=EXPR", &math}}) {
        for (const QString& value : parser.values(QLatin1String(option))) {
            const auto split = deviceAndChannel(value.toStdString());
            const auto device = split ? std::ranges::find(devices, split->first) : devices.end();
            if (device == devices.end()) {
                QStringList names;
                for (const std::string& name : devices) names.append(QString::fromStdString(name));
                const QString why =
                    split ? QStringLiteral("no device is named %1").arg(quoted(toQString(split->first)))
                          : QStringLiteral("with several devices, say whose as %1").arg(QLatin1String(form));
                return QStringLiteral("--%1 %2: %3 (the devices: %4)")
                    .arg(QLatin1String(option), quoted(value), why, names.join(QStringLiteral(", ")));
            }
            (*byDevice)[static_cast<std::size_t>(device - devices.begin())].append(
                QString::fromStdString(split->second));
        }
    }
    setups.assign(devices.size(), {});
    const bool someNamed = parser.isSet(QStringLiteral("filter-channel"));
    for (std::size_t i = 0; i < devices.size(); ++i) {
        // Channels named, none of this device's: it is not filtered.
        const core::dsp::FilterSettings own = someNamed && named[i].isEmpty() ? core::dsp::FilterSettings{} : settings;
        if (auto error = readSetup(own, named[i], math[i], parser.isSet(QStringLiteral("analyze-filtered")),
                                   channels[i], setups[i]))
            return QStringLiteral("%1: %2").arg(QString::fromStdString(devices[i]), *error);
    }
    return std::nullopt;
}

}  // namespace tactiscope::cli
