// CSV import: a first pass over the time column for the rate (when it must
// be measured), then one streaming pass that stores blocks as they fill.
#include "core/storage/CsvImport.h"

#include "core/NumberRanges.h"
#include "core/text/NumberFormat.h"

#include "core/ModeCapability.h"
#include "core/SampleBlock.h"
#include "core/io/CsvReader.h"
#include "core/io/CsvTimeBase.h"
#include "core/storage/Database.h"
#include "core/storage/RecorderLock.h"
#include "core/storage/SessionExport.h"
#include "core/text/NoNumber.h"
#include "core/text/TextChecks.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

namespace tactiscope::core::storage {
namespace {

using io::CsvError;
using io::CsvReader;

constexpr std::size_t kBlockRows = 4096;  // one chunk
constexpr std::size_t kBatchBlocks = 16;  // one transaction

// The side file of a Tactiscope export, when there is one: X.csv → X.meta.json.
std::optional<nlohmann::json> readSideFile(const std::string& csvPath)
{
    const std::string side = metadataSidePath(csvPath);
    std::ifstream in(side);
    if (!in) return std::nullopt;
    try {
        auto json = nlohmann::json::parse(in);
        // A session of several devices is exported on the session's clock,
        // each device in its own rows: not one device's grid to import.
        if (json.contains("devices"))
            throw CsvError(
                "'" + csvPath +
                "' is the export of a session of several devices; import each device's "
                "part from its own export (sessions export PART, PART being its session in `sessions show`)");
        if (json.contains("session") && json.contains("channels")) return json;
    } catch (const nlohmann::json::exception& e) {
        throw CsvError("'" + side + "' is not a Tactiscope metadata file: " + e.what());
    }
    return std::nullopt;
}

std::string textOf(const nlohmann::json& object, const char* key)
{
    return object.contains(key) && object[key].is_string() ? object[key].get<std::string>() : std::string();
}

std::optional<double> optionalOf(const nlohmann::json& object, const char* key)
{
    if (!object.contains(key) || !object[key].is_number()) return std::nullopt;
    return object[key].get<double>();
}

// Fills the metadata fields the user left empty from the side file.
void completeMetadata(SessionMetadata& m, const nlohmann::json& session)
{
    const auto fill = [&](std::string& field, const char* key) {
        if (field.empty()) field = textOf(session, key);
    };
    fill(m.subject, "subject");
    fill(m.operatorName, "operator");
    fill(m.site, "site");
    fill(m.notes, "notes");
    fill(m.deviceModel, "device_model");
    fill(m.deviceSerial, "device_serial");
    fill(m.deviceFirmware, "device_firmware");
    fill(m.profileJson, "profile_json");
    fill(m.calibrationsJson, "calibrations_json");
    fill(m.trigger, "trigger");
    fill(m.signalSetup, "signal_setup");
}

// Whether the side file's export holds the whole session (an export of a
// range chosen in review holds part of it: another session, so it is
// imported under a new identity).
bool holdsWholeSession(const nlohmann::json& side)
{
    if (!side.contains("exported_range")) return true;  // exports from before ranges existed
    const auto& range = side["exported_range"];
    const auto total = side["session"].value("samples_per_channel", std::int64_t{-1});
    return range.value("first_index", std::int64_t{0}) == 0 && range.value("count", std::int64_t{-1}) == total;
}

// The session as it was recorded, as docs/storage.md promises an export
// keeps it: its uuid, times, status, verdict and app version.
struct RecordedIdentity {
    SessionOrigin origin;
    SessionStatus status = SessionStatus::Complete;
    std::optional<std::string> endedUtc;  // none: ended by this import
    std::optional<Verdict> verdict;
    std::string unjudged;
    std::uint64_t samplesPerChannel = 0;  // lost ones at the end included
};

RecordedIdentity identityOf(const std::optional<nlohmann::json>& side)
{
    RecordedIdentity identity;
    if (!side || !holdsWholeSession(*side)) return identity;
    const auto& session = (*side)["session"];
    identity.origin = {textOf(session, "uuid"), textOf(session, "started_utc"), textOf(session, "app_version")};
    // A session exported while "recording" had lost its recorder (none
    // records an export): it was interrupted.
    if (textOf(session, "status") != "complete") identity.status = SessionStatus::Interrupted;
    identity.endedUtc = textOf(session, "ended_utc");
    identity.verdict = verdictFromString(textOf(session, "verdict"));
    identity.unjudged = textOf(session, "unjudged");
    identity.samplesPerChannel = session.value("samples_per_channel", std::uint64_t{0});
    return identity;
}

void importRecords(SessionStore& store, std::int64_t session, const nlohmann::json& side)
{
    std::vector<SessionEvent> events;
    for (const auto& e : side.value("events", nlohmann::json::array())) {
        const std::string kind = textOf(e, "kind");
        const auto eventKind = eventKindFromString(kind);
        if (!eventKind) throw CsvError("the metadata file has an event of unknown kind '" + kind + "'");
        events.push_back({0, textOf(e, "analysis"), *eventKind, e.value("start_s", 0.0), e.value("end_s", 0.0),
                          e.value("direction", 0), optionalOf(e, "peak_r"), optionalOf(e, "lag_s"),
                          optionalOf(e, "speed_m_per_s"), textOf(e, "note")});
    }
    store.addEvents(session, events);
    for (const auto& r : side.value("readings", nlohmann::json::array())) {
        const std::string kind = textOf(r, "kind");
        const auto readingKind = readingKindFromString(kind);
        if (!readingKind) throw CsvError("the metadata file has a reading of unknown kind '" + kind + "'");
        store.addReading(session, {0, *readingKind, r.value("start_s", 0.0), r.value("end_s", 0.0),
                                   textOf(r, "quantity"), r.value("value", 0.0), textOf(r, "unit"),
                                   optionalOf(r, "standard_error"), textOf(r, "site"), textOf(r, "details_json"),
                                   r.contains("analysis") ? textOf(r, "analysis") : std::string(kLiveAnalysis)});
    }
    for (const auto& a : side.value("annotations", nlohmann::json::array()))
        store.addAnnotation(session, {0, a.value("time_s", 0.0), textOf(a, "author"), textOf(a, "text"),
                                      textOf(a, "created_utc"), textOf(a, "modified_utc")});
}

// The zeros the session's samples were read on (for its derived channels):
// only with the whole session, since their indices are the session's.
void importZeros(SessionStore& store, std::int64_t session, const nlohmann::json& side)
{
    for (const auto& zero : side.value("zeros", nlohmann::json::array())) {
        const auto first = zero.value("first_index", std::int64_t{-1});
        if (first < 0) throw CsvError("the metadata file has a zero without a first sample index");
        store.addZero(session, {static_cast<std::uint64_t>(first), textOf(zero, "values_json")});
    }
}

// The verdict's trail, in its order; the last decision is the verdict.
// False when the file has none (an export from before trails existed).
bool importVerdictTrail(SessionStore& store, std::int64_t session, const nlohmann::json& side)
{
    const auto trail = side.value("verdicts", nlohmann::json::array());
    for (const auto& d : trail) {
        const auto role = verdictRoleFromString(textOf(d, "role"));
        const auto verdict = verdictFromString(textOf(d, "verdict"));
        if (!role || !verdict)
            throw CsvError("the metadata file has a verdict decision with an unknown role or verdict ('" +
                           textOf(d, "role") + "', '" + textOf(d, "verdict") + "')");
        store.decideVerdict(session, {0, *role, *verdict, textOf(d, "decided_by"), textOf(d, "decided_utc"),
                                      textOf(d, "note"), textOf(d, "basis_json")});
    }
    return !trail.empty();
}

// A cell as the binary32 sample it is stored as. Empty, or what programs
// print for no number ("nan", "inf"), it is a hole in its column alone, as
// from a board live. A number beyond binary32's range would be stored as
// infinity: it is refused (a file, unlike a stream, can be mended).
double cellValue(const CsvReader& reader, std::string_view cell, std::size_t column)
{
    if (cell.empty() || text::spellsNoNumber(cell)) return std::numeric_limits<double>::quiet_NaN();
    const double value = reader.number(cell, column);
    if (std::abs(value) > static_cast<double>(std::numeric_limits<float>::max()))
        throw reader.cellError(cell, column, "is beyond the ±3.4e38 a stored sample holds");
    return value;
}

}  // namespace

CsvImportResult importCsv(SessionStore& store, const std::string& path, const CsvImportOptions& options,
                          const std::function<bool(double)>& progress)
{
    CsvReader reader(path);
    const auto side = readSideFile(path);
    const auto& header = reader.header();

    const std::optional<std::size_t> timeColumn =
        options.timeColumn.empty() ? io::findTimeColumn(header) : std::optional(reader.column(options.timeColumn));
    // Rows are consecutive at a given rate unless a time column is named.
    const bool timed = !options.rate_hz || !options.timeColumn.empty();
    if (timed && !timeColumn)
        throw CsvError("'" + path + "' has no time column (t, time, time_s or timestamp): give its name or the rate");

    SessionMetadata metadata = options.metadata;
    std::optional<Mode> mode = options.mode;
    if (side) {
        completeMetadata(metadata, (*side)["session"]);
        const std::string sideMode = textOf((*side)["session"], "mode");
        if (!mode && !sideMode.empty()) {
            mode = modeFromString(sideMode);
            if (!mode) throw CsvError("the metadata file names an unknown mode '" + sideMode + "'");
        }
    }
    metadata.mode = mode.value_or(Mode::PanelScan);  // settled below, once the channels are known

    CsvImportResult result;
    result.usedSideFile = side.has_value();
    // Columns an export computed from the samples (its side file names
    // them) are not measurements: they are left out.
    std::vector<std::string> computed;
    if (side)
        for (const auto& column : side->value("computed_columns", nlohmann::json::array()))
            computed.push_back(textOf(column, "column"));
    std::vector<std::size_t> dataColumns;
    if (options.columns.empty()) {
        for (std::size_t c = 0; c < header.size(); ++c)
            if (c != timeColumn && std::ranges::find(computed, header[c]) == computed.end()) dataColumns.push_back(c);
    } else {
        for (const auto& name : options.columns) dataColumns.push_back(reader.column(name));
    }
    if (dataColumns.empty()) throw CsvError("'" + path + "' has no data column besides the time");
    // A header written by a program in Latin-1 ("µε" as 0xB5 …): read as
    // Latin-1, since a store's text must be UTF-8 (it goes to the server).
    bool latin1 = false;
    for (const std::size_t c : dataColumns) latin1 = latin1 || text::textProblem(header[c]).has_value();
    if (latin1)
        result.notes.push_back("the header is not UTF-8: its names and units were read as Latin-1 (" +
                               text::latin1ToUtf8(header[dataColumns.front()]) + ", …)");
    // Each column's unit is its header's ("d [mm]"), or the one given; a
    // unit of the table is stored in SI (core/UnitScale.h). A column with
    // none is a plain number.
    std::vector<double> toStored;
    for (const std::size_t c : dataColumns) {
        auto [name, unit] = io::splitColumnHeader(latin1 ? text::latin1ToUtf8(header[c]) : header[c]);
        if (const auto given = options.units.find(name); given != options.units.end()) unit = given->second;
        ChannelDescriptor channel{name, "", ChannelKind::Other};
        toStored.push_back(giveUnit(channel, unit));
        if (side) {
            for (const auto& stored : (*side)["channels"]) {
                // Exports name each channel's column; older ones had the name alone as the column.
                const std::string column =
                    stored.contains("column") ? textOf(stored, "column") : textOf(stored, "name");
                if (column != header[c]) continue;
                channel = {textOf(stored, "name"), textOf(stored, "unit"),
                           channelKindFromString(textOf(stored, "kind")).value_or(ChannelKind::Other),
                           channelRoleFromString(textOf(stored, "role"))};
                toStored.back() = 1.0;  // Tactiscope's own export: in the units it stored
            }
        }
        // A session's export and its math channels name a column by its
        // channel: two of one name could not be told apart.
        if (std::ranges::find(result.channels, channel.name, &ChannelDescriptor::name) != result.channels.end())
            throw CsvError("'" + path + "' has two columns named '" + channel.name +
                           "'; give each column a name of its own");
        result.channels.push_back(channel);
    }
    try {
        result.channels = applyRoles(result.channels, options.roles);
    } catch (const std::invalid_argument& e) {
        throw CsvError("'" + path + "': " + e.what());
    }
    for (const auto& [name, unit] : options.units)
        if (std::ranges::find(result.channels, name, &ChannelDescriptor::name) == result.channels.end())
            throw CsvError("'" + path + "': --units names '" + name + "', which is not one of its data columns");
    if (!mode) {
        // A scan when its columns are strains, else a general recording.
        metadata.mode = modeRefusal(Mode::PanelScan, result.channels) ? Mode::General : Mode::PanelScan;
    } else if (*mode == Mode::PanelScan && !side) {
        // Asked for a scan of bare columns: they are taken as the strains
        // the scan reads, and the note says so.
        std::string assumed;
        for (auto& channel : result.channels) {
            if (channel.kind != ChannelKind::Other || !channel.unit.empty()) continue;
            channel.kind = ChannelKind::Strain;
            assumed += (assumed.empty() ? "" : ", ") + channel.name;
        }
        if (!assumed.empty())
            result.notes.push_back(assumed + " carry no unit: read as strain, which a panel scan reads (give "
                                             "--units to say otherwise)");
    }

    if (options.rate_hz) {
        result.rate_hz = *options.rate_hz;
    } else if (side && !(*side)["channels"].empty() && (*side)["channels"][0].contains("sample_rate_hz")) {
        result.rate_hz = (*side)["channels"][0]["sample_rate_hz"].get<double>();
    } else {
        result.rate_hz = io::measureRate(path, *timeColumn);
    }
    if (!(result.rate_hz > 0.0) || !std::isfinite(result.rate_hz))
        throw CsvError("the sample rate must be a positive number of Hz");
    // A store keeps no rate beyond these (NumberRanges.h): one taken would
    // read back as a damaged store.
    if (!kSampleRateRange.holds(result.rate_hz))
        throw CsvError("'" + path + "': its sample rate, " + text::formatShortest(result.rate_hz) + " Hz, is not " +
                       kSampleRateRange.text());

    const RecordedIdentity identity = identityOf(side);
    if (const auto existing = identity.origin.uuid.empty() ? std::nullopt : store.sessionWithUuid(identity.origin.uuid))
        throw CsvError("'" + path + "' is session " + identity.origin.uuid + ", already in this store as session " +
                       std::to_string(*existing) + "; it was not imported again");

    // Like a recorder, so no other process records into the store meanwhile.
    const RecorderLock lock = RecorderLock::acquire(store.database().path());
    // One transaction: an import cancelled, failed or killed leaves nothing.
    Transaction transaction(store.database());
    result.session = store.beginSession(metadata, result.channels, result.rate_hz, identity.origin);
    const auto fileSize = static_cast<double>(std::filesystem::file_size(path));
    io::RowIndexer indexer(result.rate_hz, timeColumn ? io::timeScale(header[*timeColumn], path) : 1.0);
    const double dt_s = 1.0 / result.rate_hz;
    std::vector<SampleBlock> batch;
    SampleBlock block;
    std::size_t filled = 0;
    std::uint64_t end = 0;  // one past the last stored index
    const auto flushBlock = [&] {
        if (filled == 0) return;
        SampleBlock full(result.channels.size(), filled, block.t0_s(), dt_s, block.firstSampleIndex());
        for (std::size_t c = 0; c < result.channels.size(); ++c)
            std::copy_n(block.channel(c).begin(), filled, full.channel(c).begin());
        batch.push_back(std::move(full));
        filled = 0;
    };
    const auto flushBatch = [&] {
        flushBlock();
        store.appendBlocks(result.session, batch);
        batch.clear();
        if (progress && !progress(static_cast<double>(reader.bytesRead()) / fileSize))
            throw std::runtime_error("cancelled");
    };
    std::vector<std::string_view> fields;
    while (reader.next(fields)) {
        const std::uint64_t index =
            timed ? indexer.next(reader.number(fields[*timeColumn], *timeColumn), reader) : indexer.next();
        if (filled > 0 && (index != end || filled == kBlockRows)) {
            flushBlock();
            if (batch.size() == kBatchBlocks) flushBatch();
        }
        if (filled == 0)
            block = SampleBlock(result.channels.size(), kBlockRows, static_cast<double>(index) * dt_s, dt_s, index);
        for (std::size_t c = 0; c < dataColumns.size(); ++c)
            block.channel(c)[filled] = cellValue(reader, fields[dataColumns[c]], dataColumns[c]) * toStored[c];
        ++filled;
        result.lostSamples += index - end;
        end = index + 1;
        ++result.rows;
    }
    if (result.rows == 0) throw CsvError("'" + path + "' has a header but no data rows");
    flushBatch();
    if (side) importRecords(store, result.session, *side);
    if (identity.samplesPerChannel > end) {  // lost at the recording's end
        store.markLostUntil(result.session, identity.samplesPerChannel);
        result.lostSamples += identity.samplesPerChannel - end;
    }
    if (side && holdsWholeSession(*side)) importZeros(store, result.session, *side);
    const bool trail = side && holdsWholeSession(*side) && importVerdictTrail(store, result.session, *side);
    if (identity.verdict && !trail) store.setVerdict(result.session, *identity.verdict);
    if (!identity.unjudged.empty()) store.markUnjudged(result.session, identity.unjudged);
    store.endSession(result.session, identity.status, identity.endedUtc);
    transaction.commit();
    return result;
}

}  // namespace tactiscope::core::storage
