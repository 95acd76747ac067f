// The analyze subcommand: a stored session's cantilever channels through
// the offline detector, stretch by stretch between lost samples.
#include "AnalyzeCommand.h"

#include "CliSupport.h"
#include "DetectorOptions.h"
#include "SessionArgument.h"
#include "core/derived/StoredDetection.h"
#include "core/detector/HumRisk.h"
#include "core/modes/ModeDefinition.h"
#include "core/report/DetectorHum.h"
#include "core/signal/SignalSetup.h"
#include "core/storage/DefectRecords.h"
#include "core/storage/StoredSites.h"

#include <algorithm>
#include <chrono>
#include <iostream>

namespace tactiscope::cli {
namespace {

// The cantilever channels: named with --channels, else every strain channel.
std::optional<QString> pickChannels(const std::vector<core::storage::StoredChannel>& channels, const QString& names,
                                    std::vector<std::size_t>& picked)
{
    if (names.isEmpty()) {
        for (std::size_t c = 0; c < channels.size(); ++c)
            if (channels[c].descriptor.kind == core::ChannelKind::Strain) picked.push_back(c);
        if (picked.size() < 2)
            return QStringLiteral("the session has fewer than two strain channels; name the cantilevers with "
                                  "--channels A,B");
        return std::nullopt;
    }
    for (const QString& name : names.split(QLatin1Char(','))) {
        std::optional<std::size_t> found;
        for (std::size_t c = 0; c < channels.size(); ++c)
            if (toQString(channels[c].descriptor.name) == name.trimmed()) found = c;
        if (!found) return QStringLiteral("the session has no channel %1").arg(quoted(name.trimmed()));
        picked.push_back(*found);
    }
    if (picked.size() < 2) return QStringLiteral("--channels needs at least two cantilevers, e.g. a,b");
    return std::nullopt;
}

// The filters the cantilevers go through: --notch on every one, else the
// session's own when its mode analysed the filtered channels (unless
// --unfiltered); what they are, in a line, or empty for none.
QString cantileverFilters(const core::storage::SessionSummary& session,
                          const std::vector<core::storage::StoredChannel>& channels,
                          const std::vector<std::size_t>& picked, std::optional<double> notch_hz, bool unfiltered,
                          std::vector<core::dsp::FilterSettings>& filters,
                          std::vector<std::optional<std::vector<double>>>& startStates)
{
    if (notch_hz) {
        core::dsp::FilterSettings notch;
        notch.notch_hz = notch_hz;
        filters = {notch};
        return QStringLiteral("(every cantilever through a %1)").arg(toQString(notch.text()));
    }
    core::signal::SignalSetup setup;
    try {
        setup = core::signal::signalSetupFromJson(session.metadata.signalSetup);
    } catch (const std::invalid_argument& e) {
        printError(QStringLiteral("the session's filters cannot be read (%1): the cantilevers are read as stored")
                       .arg(toQString(e.what())));
        return {};
    }
    std::vector<std::string> names;
    for (const std::size_t c : picked) names.push_back(channels[c].descriptor.name);
    const auto analysis = core::signal::analysisFilters(setup, names);
    if (!analysis) return {};
    if (unfiltered) return QStringLiteral("(the cantilevers as stored: --unfiltered)");
    filters = analysis->filters;
    startStates = analysis->startStates;
    return QStringLiteral("(the cantilevers through the session's filters, as its mode read them live: %1)")
        .arg(toQString(analysis->text));
}

// A hum the detector read the cantilevers through (core/report/DetectorHum.h),
// judged over the session's first seconds: said, with what takes it out.
void tellHum(core::storage::SessionSource& store, std::int64_t session, double rate_hz,
             const std::vector<core::storage::StoredChannel>& channels, const std::vector<std::size_t>& picked,
             const std::vector<core::dsp::FilterSettings>& filters)
{
    const auto judged = static_cast<std::uint64_t>(core::detector::kHumJudged_s * rate_hz);
    const auto quality = core::report::channelQuality(store, session, 0, std::min(store.sampleCount(session), judged));
    std::vector<std::string> cantilevers;
    for (const std::size_t c : picked) cantilevers.push_back(channels[c].descriptor.name);
    // One filter for every cantilever (--notch), or each its own (the session's).
    const auto notchOf = [&](const std::string& channel) -> std::optional<double> {
        const auto i = static_cast<std::size_t>(std::ranges::find(cantilevers, channel) - cantilevers.begin());
        const auto* filter = filters.size() == 1 ? &filters[0] : i < filters.size() ? &filters[i] : nullptr;
        return filter ? filter->notch_hz : std::nullopt;
    };
    if (const auto hum = core::report::detectorHumNote(quality, cantilevers, rate_hz, notchOf))
        printError(QStringLiteral("note: %1; --notch %2 takes it out").arg(toQString(hum->text)).arg(hum->mains_hz));
}

}  // namespace

int runAnalyze(const QStringList& arguments)
{
    const QString name = QStringLiteral("analyze");
    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("Re-run the surface-deflection detector (seed 000) on a stored panel-scan session and print "
                       "its events.\nThe detector restarts after lost samples. The recorded events are kept; "
                       "--save stores the new ones beside them under a name. Without --spacing-mm the paper's "
                       "prototype's 15 mm gives each event its scan speed, as in a live recording."));
    parser.addOptions({
        {QStringLiteral("db"),
         QStringLiteral("The session store (required): a station's file, or a central store's connection string "
                        "(postgresql://… or key=value with host= or dbname=)."),
         QStringLiteral("FILE|CONNINFO")},
        {QStringLiteral("session"), QStringLiteral("The session: its id, its uuid, or 'last' (required)."),
         QStringLiteral("ID|UUID|last")},
        {QStringLiteral("channels"), QStringLiteral("Cantilever channels in probe order (default: the strain ones)."),
         QStringLiteral("A,B")},
        {QStringLiteral("save"), QStringLiteral("Store the events as a re-analysis named NAME."),
         QStringLiteral("NAME")},
        {QStringLiteral("notch"),
         QStringLiteral("Run every cantilever through a mains notch first (50 or 60 Hz and harmonics, causal, as "
                        "live), whatever the session's own filters."),
         QStringLiteral("50|60")},
        {QStringLiteral("unfiltered"),
         QStringLiteral("Read the cantilevers as stored, though the session's mode analysed them filtered.")},
    });
    addDetectorOptions(parser);
    if (const auto exit = parseCommandLine(parser, name, arguments)) return *exit;
    const QString usage = commandUsage(parser, name);
    if (!parser.positionalArguments().isEmpty())
        return usageError(QStringLiteral("unexpected %1").arg(quoted(parser.positionalArguments().front())), usage);
    if (!parser.isSet(QStringLiteral("db"))) return usageError(QStringLiteral("--db FILE is required"), usage);
    if (!parser.isSet(QStringLiteral("session")))
        return usageError(QStringLiteral("--session ID|UUID|last is required"), usage);
    DetectorOptions options;
    options.spacing_m = core::detector::kPrototypeSpacing_m;
    if (const auto error = readDetectorOptions(parser, options)) return usageError(*error, usage);
    std::optional<double> notch_hz;
    if (parser.isSet(QStringLiteral("notch"))) {
        QString error;
        notch_hz = parseMainsFrequency(QStringLiteral("notch"), parser.value(QStringLiteral("notch")), error);
        if (!notch_hz) return usageError(error, usage);
        if (parser.isSet(QStringLiteral("unfiltered")))
            return usageError(QStringLiteral("--notch and --unfiltered ask for opposite things; give one"), usage);
    }
    const QString save = parser.value(QStringLiteral("save"));
    if (parser.isSet(QStringLiteral("save")) && (save.isEmpty() || save == QLatin1String(core::storage::kLiveAnalysis)))
        return usageError(QStringLiteral("--save needs a name other than 'live'"), usage);

    try {
        const auto opened = openStoreArgument(parser.value(QStringLiteral("db")),
                                              save.isEmpty() ? core::storage::Database::Access::ReadOnly
                                                             : core::storage::Database::Access::ReadWrite);
        core::storage::SessionSource& store = *opened;
        // Refused before the detector runs, with the store's reason (a
        // central store's login, a read replica).
        if (!save.isEmpty() && !store.rights().noAnalyses.empty()) {
            printError(toQString(store.rights().noAnalyses));
            return kExitFailure;
        }
        const auto id = resolveSession(store, parser.value(QStringLiteral("session")));
        if (!id)
            return usageError(
                QStringLiteral("no session %1 in the store").arg(quoted(parser.value(QStringLiteral("session")))),
                usage);
        if (const auto refusal = core::storage::oneDeviceRefusal(store, *id, "analyze"))
            return usageError(toQString(*refusal), usage);
        const auto summary = *store.session(*id);
        // The detector's defects are the analysis of a mode that detects them.
        if (!core::definitionOf(summary.metadata.mode).detectsDefects)
            return usageError(QStringLiteral("session %1 is a %2 session; analyze runs the panel-scan detector")
                                  .arg(*id)
                                  .arg(toQString(core::toString(summary.metadata.mode))),
                              usage);
        const auto channels = store.channels(*id);
        std::vector<std::size_t> picked;
        if (const auto error = pickChannels(channels, parser.value(QStringLiteral("channels")), picked))
            return usageError(*error, usage);
        const double dt_s = 1.0 / channels.front().sampleRate_hz;
        options.parameters.sampleInterval_s = dt_s;
        std::size_t lags = 0;
        try {
            lags = core::detector::resolve(options.parameters).lags.size();
        } catch (const std::invalid_argument& e) {
            return usageError(toQString(e.what()), usage);
        }
        // A probe that sent its own decisions: they are compared with this analysis's.
        std::vector<core::ChannelDescriptor> descriptors;
        for (const auto& c : channels) descriptors.push_back(c.descriptor);
        const auto probe = core::detector::probeDecisionChannels(descriptors);
        core::detector::StretchSettings settings{options.parameters, options.hold_s, options.spacing_m,
                                                 options.threads};
        const auto filtered =
            cantileverFilters(summary, channels, picked, notch_hz, parser.isSet(QStringLiteral("unfiltered")),
                              settings.filters, settings.filterStartStates);
        // Read and detection together: the store streams into the detector.
        const auto started = std::chrono::steady_clock::now();
        const auto [events, analysed, agreement] = *core::derived::detectStoredSession(
            store, *id, picked, settings, {}, probe ? std::optional(probe->out) : std::nullopt);
        const double elapsed_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
        tellHum(store, *id, 1.0 / dt_s, channels, picked, settings.filters);
        if (!save.isEmpty()) store.addEvents(*id, core::storage::defectRecords(events, save.toStdString()));
        const auto sites = core::storage::storedSites(store, *id, events);
        const DetectionOutput output{analysed, lags, elapsed_s, events, sites};
        if (options.json) {
            std::cout << eventsJson(output, options, agreement) << '\n';
        } else {
            printDetection(QStringLiteral("session %1").arg(*id), dt_s, output, options);
            if (!filtered.isEmpty()) std::cout << filtered.toStdString() << '\n';
            if (agreement)
                std::cout << core::detector::agreementText(*agreement)
                          << " (the probe's recorded decisions against this analysis)\n";
        }
    } catch (const core::storage::StorageError& e) {
        return storageFailure(e);
    }
    return kExitOk;
}

}  // namespace tactiscope::cli
