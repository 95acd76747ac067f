// Reading the filter and math-channel options.
#include "SignalOptions.h"

#include "CliSupport.h"
#include "DeviceValues.h"
#include "core/NumberRanges.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

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

namespace {

// The filter options' names, and their values as given, by name.
constexpr std::array<const char*, 5> kFilterOptionNames = {"notch", "lowpass", "highpass", "order", "moving-average"};
using FilterValues = std::map<QString, QString>;

// One filter from its options' values.
std::optional<QString> settingsOf(const FilterValues& values, core::dsp::FilterSettings& s)
{
    const auto text = [&values](const char* option) {
        const auto value = values.find(QLatin1String(option));
        return value == values.end() ? std::optional<QString>() : value->second;
    };
    QString error;
    if (const auto notch = text("notch")) {
        s.notch_hz = parseMainsFrequency(QStringLiteral("notch"), *notch, error);
        if (!s.notch_hz) return error;
    }
    for (const auto& [option, cutoff] : {std::pair{"lowpass", &s.lowpass_hz}, std::pair{"highpass", &s.highpass_hz}}) {
        const auto given = text(option);
        if (!given) continue;
        *cutoff = numberInRange(QLatin1String(option), *given, core::kFilterCutoffRange, error);
        if (!*cutoff) return error;
    }
    if (const auto given = text("order")) {
        const auto order = numberInRange(QStringLiteral("order"), *given, core::kFilterOrderRange, error);
        if (!order || *order != std::floor(*order))
            return error.isEmpty() ? QStringLiteral("--order is a whole number, 2 to 8, not %1").arg(*given) : error;
        s.order = static_cast<int>(*order);
    }
    if (const auto given = text("moving-average")) {
        const auto average = numberInRange(QStringLiteral("moving-average"), *given, core::kMovingAverageRange, error);
        if (!average) return error;
        s.movingAverage_s = *average;
    }
    return std::nullopt;
}

bool butterworth(const core::dsp::FilterSettings& settings)
{
    return settings.lowpass_hz || settings.highpass_hz;
}

const QString kOrderAlone = QStringLiteral("--order is the Butterworth filters': give --lowpass or --highpass with it");

}  // namespace

std::optional<QString> readFilterSettings(const QCommandLineParser& parser, core::dsp::FilterSettings& s)
{
    FilterValues values;
    for (const char* option : kFilterOptionNames)
        if (parser.isSet(QLatin1String(option))) values[QLatin1String(option)] = parser.value(QLatin1String(option));
    if (auto error = settingsOf(values, s)) return error;
    if (values.contains(QStringLiteral("order")) && !butterworth(s)) return kOrderAlone;
    return std::nullopt;
}

QList<QCommandLineOption> signalOptions()
{
    QList<QCommandLineOption> options = filterOptions();
    options.append({
        {QStringLiteral("filter-channel"),
         QStringLiteral("The channel the filter options filter, live (repeatable; default: every channel). Its "
                        "filtered values are watched as NAME.filtered; the stored samples stay as they came, and "
                        "the session keeps the filter. With several devices: DEVICE/NAME; and a filter option given as "
                        "DEVICE=VALUE is that device's own (--notch a=50 --lowpass b=20)."),
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

const QString kAnalyzeWithoutFilter =
    QStringLiteral("--analyze-filtered: give the filter to analyse through (--notch, --lowpass, …)");

}  // namespace

std::optional<QString> readSignalSetup(const QCommandLineParser& parser, const std::vector<std::string>& channels,
                                       core::signal::SignalSetup& setup)
{
    core::dsp::FilterSettings settings;
    if (auto error = readFilterSettings(parser, settings)) return error;
    if (settings.empty() && parser.isSet(QStringLiteral("filter-channel")))
        return QStringLiteral("--filter-channel names what the filter options filter: give --notch, --lowpass, "
                              "--highpass or --moving-average");
    if (parser.isSet(QStringLiteral("analyze-filtered")) && settings.empty()) return kAnalyzeWithoutFilter;
    return readSetup(settings, parser.values(QStringLiteral("filter-channel")), parser.values(QStringLiteral("math")),
                     parser.isSet(QStringLiteral("analyze-filtered")), channels, setup);
}

std::optional<QString> readSignalSetups(const QCommandLineParser& parser, const std::vector<std::string>& devices,
                                        const std::vector<std::vector<std::string>>& channels,
                                        std::vector<core::signal::SignalSetup>& setups)
{
    // Each filter option's value for each device: DEVICE=VALUE, else the
    // one given for every device.
    std::vector<FilterValues> values(devices.size());
    QString error;
    for (const char* option : kFilterOptionNames) {
        const auto byDevice = valuesByName(QLatin1String(option), parser.values(QLatin1String(option)), devices,
                                           QStringLiteral("device"), devicesText(devices), error);
        if (!byDevice) return error;
        for (std::size_t i = 0; i < devices.size(); ++i)
            if (const auto& value = (*byDevice)[i]) values[i][QLatin1String(option)] = *value;
    }
    std::vector<core::dsp::FilterSettings> settings(devices.size());
    for (std::size_t i = 0; i < devices.size(); ++i)
        if (auto refusal = settingsOf(values[i], settings[i])) return refusal;
    // Whether filter option --OPTION (any, when null) has a value named for device i.
    const auto namedFor = [&](std::size_t i, const char* option) {
        const QString own = toQString(devices[i]) + QLatin1Char('=');
        return std::ranges::any_of(kFilterOptionNames, [&](const char* name) {
            return (!option || qstrcmp(name, option) == 0) &&
                   std::ranges::any_of(parser.values(QLatin1String(name)),
                                       [&own](const QString& value) { return value.startsWith(own); });
        });
    };
    // An --order for every device orders the Butterworth filters of those
    // that have one; one named for a device, that device's.
    if (parser.isSet(QStringLiteral("order")) && std::ranges::none_of(settings, butterworth)) return kOrderAlone;
    for (std::size_t i = 0; i < devices.size(); ++i)
        if (!butterworth(settings[i]) && namedFor(i, "order"))
            return QStringLiteral("%1: %2").arg(toQString(devices[i]), kOrderAlone);
    const bool anyFilter = std::ranges::any_of(settings, [](const auto& one) { return !one.empty(); });
    if (parser.isSet(QStringLiteral("analyze-filtered")) && !anyFilter) return kAnalyzeWithoutFilter;

    // Each --filter-channel and --math value goes to the device named
    // before its first '/', without it.
    const auto named = valuesByDevice(QStringLiteral("filter-channel"), QStringLiteral("DEVICE/CHANNEL"),
                                      parser.values(QStringLiteral("filter-channel")), devices, error);
    if (!named) return error;
    const auto math = valuesByDevice(QStringLiteral("math"), QStringLiteral("DEVICE/NAME[UNIT]=EXPR"),
                                     parser.values(QStringLiteral("math")), devices, error);
    if (!math) return error;
    for (std::size_t i = 0; i < devices.size(); ++i)
        if (!(*named)[i].isEmpty() && settings[i].empty())
            return QStringLiteral("--filter-channel %1/%2: %1 has no filter (give one for every device, or as "
                                  "--notch %1=50, --lowpass %1=HZ, …)")
                .arg(toQString(devices[i]), (*named)[i].front());
    setups.assign(devices.size(), {});
    const bool someNamed = parser.isSet(QStringLiteral("filter-channel"));
    for (std::size_t i = 0; i < devices.size(); ++i) {
        // Channels named, none of this device's, and no filter of its own:
        // the filter for every device is not for it.
        const bool notForIt = someNamed && (*named)[i].isEmpty() && !namedFor(i, nullptr);
        const core::dsp::FilterSettings own = notForIt ? core::dsp::FilterSettings{} : settings[i];
        if (auto refusal = readSetup(own, (*named)[i], (*math)[i], parser.isSet(QStringLiteral("analyze-filtered")),
                                     channels[i], setups[i]))
            return QStringLiteral("%1: %2").arg(toQString(devices[i]), *refusal);
    }
    return std::nullopt;
}

}  // namespace tactiscope::cli
