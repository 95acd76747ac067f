// Reading the filter and math-channel options.
#include "SignalOptions.h"

#include "CliSupport.h"
#include "core/NumberRanges.h"

#include <algorithm>
#include <cmath>

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
                        "the session keeps the filter."),
         QStringLiteral("NAME")},
        {QStringLiteral("analyze-filtered"),
         QStringLiteral("The mode's analysis (detector, presses, force) reads the filtered channels instead of the "
                        "samples as they came; the session records it, and analyze does the same.")},
        {QStringLiteral("math"),
         QStringLiteral("A math channel computed live over the channels (filtered ones as filtered), "
                        "NAME[UNIT]=EXPR, e.g. \"diff[µε]=a - b\" (repeatable; units are checked); watch it with "
                        "--limit or --trigger by NAME, in its UNIT. The session keeps it."),
         QStringLiteral("NAME[UNIT]=EXPR")},
    });
    return options;
}

std::optional<QString> readSignalSetup(const QCommandLineParser& parser, const std::vector<std::string>& channels,
                                       core::signal::SignalSetup& setup)
{
    core::dsp::FilterSettings settings;
    if (auto error = readFilterSettings(parser, settings)) return error;
    const QStringList named = parser.values(QStringLiteral("filter-channel"));
    if (settings.empty() && !named.isEmpty())
        return QStringLiteral("--filter-channel names what the filter options filter: give --notch, --lowpass, "
                              "--highpass or --moving-average");
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
    setup.analysisFiltered = parser.isSet(QStringLiteral("analyze-filtered"));
    if (setup.analysisFiltered && setup.filters.empty())
        return QStringLiteral("--analyze-filtered: give the filter to analyse through (--notch, --lowpass, …)");
    try {
        for (const QString& definition : parser.values(QStringLiteral("math")))
            setup.math.push_back(core::math::parseMathDefinition(definition.toStdString()));
    } catch (const core::math::MathError& e) {
        return QStringLiteral("--math: %1").arg(QString::fromStdString(e.what()));
    }
    return std::nullopt;
}

}  // namespace tactiscope::cli
