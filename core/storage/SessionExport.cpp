// Session export to CSV and JSON, window by window.
#include "core/storage/SessionExport.h"

#include "core/detector/DefectSitesJson.h"
#include "core/modes/ModeDefinition.h"
#include "core/storage/DefectRecords.h"
#include "core/storage/StoredSites.h"

#include "core/storage/SafeOutput.h"

#include "core/text/JsonWriter.h"
#include "core/text/NumberFormat.h"
#include "core/timing/ClockMappingJson.h"
#include "core/timing/ClockMappingText.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>

namespace tactiscope::core::storage {
namespace {

// Read a window at a time: at most this many samples per channel, and this
// many values in all (32 MB of doubles), so a session of 10 000 channels
// is read in windows of 400 samples, not 5 GB at once.
constexpr std::uint64_t kWindow = 65536;
constexpr std::uint64_t kWindowValues = std::uint64_t{1} << 22;
// A JSON export holds a group of whole columns at once: this many values
// (64 MB of binary32, as stored).
constexpr std::uint64_t kGroupValues = std::uint64_t{1} << 24;

// The shortest text that reads back to the same binary32 (stored values are
// binary32, see ChunkCodec.h).
std::string_view formatSample(double value, char (&buffer)[32])
{
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, static_cast<float>(value));
    return {buffer, static_cast<std::size_t>(result.ptr - buffer)};
}

SessionSummary requireSession(SessionSource& store, std::int64_t session)
{
    auto summary = store.session(session);
    if (!summary) throw StorageError("there is no session " + std::to_string(session));
    return *summary;
}

using RowFunction = std::function<void(std::uint64_t, const std::vector<std::vector<double>>&, std::size_t)>;

// The range's end index, clipped to the session's samples.
std::uint64_t endOf(const ExportRange& range, std::uint64_t total)
{
    return range.count > total - std::min(range.first, total) ? total : range.first + range.count;
}

// Calls row(index, window, s) for every stored sample (not in a gap) of the
// range, in order; window[k][s] is the value of channel wanted[k], then of
// each computed column.
void forEachSample(SessionSource& store, std::int64_t session, const std::vector<std::size_t>& wanted,
                   const RowFunction& row, const ExportRange& range = {}, ComputedColumns* computed = nullptr)
{
    const auto snapshot = store.snapshot();  // one consistent state, even while recording
    const std::uint64_t end = endOf(range, store.sampleCount(session));
    const auto gaps = store.gaps(session);
    auto gap = gaps.begin();
    std::vector<std::vector<double>> window(wanted.size());
    const std::uint64_t step =
        std::clamp<std::uint64_t>(kWindowValues / std::max<std::uint64_t>(1, wanted.size()), 1, kWindow);
    for (std::uint64_t first = range.first; first < end; first += step) {
        // Every channel of the window in one read: each chunk decoded once,
        // the session's channels looked up once (per channel, both were
        // repeated for each channel: quadratic in the channels).
        window.resize(wanted.size());
        store.readChannels(session, wanted, first, std::min(step, end - first), window);
        if (computed) {
            auto columns = computed->read(first, std::min(step, end - first));
            window.insert(window.end(), std::make_move_iterator(columns.begin()),
                          std::make_move_iterator(columns.end()));
        }
        for (std::size_t s = 0; s < window[0].size(); ++s) {
            const std::uint64_t index = first + s;
            while (gap != gaps.end() && gap->firstIndex + gap->count <= index) ++gap;
            if (gap != gaps.end() && index >= gap->firstIndex) continue;  // lost: no row
            row(index, window, s);
        }
    }
}

void optional(text::JsonWriter& json, const char* key, std::optional<double> value)
{
    json.key(key);
    if (value)
        json.value(*value);
    else
        json.null();
}

// Events of every analysis, readings, annotations, the zeros and the verdict's trail.
void writeRecords(text::JsonWriter& json, SessionSource& store, std::int64_t session)
{
    json.key("events").beginArray();
    for (const auto& analysis : store.analyses(session)) {
        for (const auto& e : store.events(session, analysis)) {
            json.beginObject();
            json.key("analysis").value(e.analysis);
            json.key("kind").value(toString(e.kind));
            json.key("start_s").value(e.start_s);
            json.key("end_s").value(e.end_s);
            json.key("direction").value(static_cast<long long>(e.direction));
            optional(json, "peak_r", e.peakR);
            optional(json, "lag_s", e.lag_s);
            optional(json, "speed_m_per_s", e.speed_m_per_s);
            json.key("note").value(e.note);
            json.endObject();
        }
    }
    json.endArray();
    json.key("readings").beginArray();
    for (const auto& analysis : store.analyses(session)) {
        for (const auto& r : store.readings(session, analysis)) {
            json.beginObject();
            json.key("analysis").value(r.analysis);
            json.key("kind").value(toString(r.kind));
            json.key("start_s").value(r.start_s);
            json.key("end_s").value(r.end_s);
            json.key("quantity").value(r.quantity);
            json.key("value").value(r.value);
            json.key("unit").value(r.unit);
            optional(json, "standard_error", r.standardError);
            json.key("site").value(r.site);
            json.key("details_json").value(r.detailsJson);
            json.endObject();
        }
    }
    json.endArray();
    json.key("annotations").beginArray();
    for (const auto& a : store.annotations(session)) {
        json.beginObject();
        json.key("time_s").value(a.time_s);
        json.key("author").value(a.author);
        json.key("text").value(a.text);
        json.key("created_utc").value(a.createdUtc);
        json.key("modified_utc").value(a.modifiedUtc);
        json.endObject();
    }
    json.endArray();
    json.key("zeros").beginArray();
    for (const auto& zero : store.zeros(session)) {
        json.beginObject();
        json.key("first_index").value(static_cast<long long>(zero.firstIndex));
        json.key("values_json").value(zero.valuesJson);
        json.endObject();
    }
    json.endArray();
    json.key("verdicts").beginArray();
    for (const auto& d : store.verdicts(session)) {
        json.beginObject();
        json.key("role").value(toString(d.role));
        json.key("verdict").value(toString(d.verdict));
        json.key("decided_by").value(d.decidedBy);
        json.key("decided_utc").value(d.decidedUtc);
        json.key("note").value(d.note);
        json.key("basis_json").value(d.basisJson);
        json.endObject();
    }
    json.endArray();
}

void writeMetadata(text::JsonWriter& json, SessionSource& store, std::int64_t session, const ExportRange& range)
{
    const auto s = requireSession(store, session);
    const std::uint64_t total = store.sampleCount(session);
    json.key("session").beginObject();
    // The id at the station that recorded it, wherever it is exported from,
    // so a central store's export is the station's to the byte.
    json.key("id").value(static_cast<long long>(s.stationId != 0 ? s.stationId : s.id));
    json.key("uuid").value(s.uuid);
    json.key("mode").value(toString(s.metadata.mode));
    json.key("subject").value(s.metadata.subject);
    json.key("operator").value(s.metadata.operatorName);
    json.key("site").value(s.metadata.site);
    json.key("notes").value(s.metadata.notes);
    json.key("started_utc").value(s.startedUtc);
    json.key("ended_utc").value(s.endedUtc);
    json.key("status").value(toString(s.status));
    json.key("verdict").value(verdictText(s.verdict));
    if (!s.unjudged.empty()) json.key("unjudged").value(s.unjudged);
    json.key("device_model").value(s.metadata.deviceModel);
    json.key("device_serial").value(s.metadata.deviceSerial);
    json.key("device_firmware").value(s.metadata.deviceFirmware);
    json.key("app_version").value(s.appVersion);
    json.key("profile_json").value(s.metadata.profileJson);
    json.key("calibrations_json").value(s.metadata.calibrationsJson);
    json.key("trigger").value(s.metadata.trigger);
    json.key("signal_setup").value(s.metadata.signalSetup);
    // A session of several devices holds no samples of its own: each
    // device's count and exported range are under its "devices" entry.
    if (s.devices == 0) json.key("samples_per_channel").value(static_cast<long long>(total));
    json.endObject();
    if (s.devices == 0) {
        // Which samples the export holds, as indices and as session seconds.
        const std::uint64_t first = std::min(range.first, total), end = endOf(range, total);
        json.key("exported_range").beginObject();
        json.key("first_index").value(static_cast<long long>(first));
        json.key("count").value(static_cast<long long>(end - first));
        json.key("from_s").value(s.sampleRate_hz > 0.0 ? static_cast<double>(first) / s.sampleRate_hz : 0.0);
        json.key("to_s").value(s.sampleRate_hz > 0.0 ? static_cast<double>(end) / s.sampleRate_hz : 0.0);
        json.endObject();
    }
    json.key("channels").beginArray();
    for (const auto& channel : store.channels(session)) {
        json.beginObject();
        json.key("name").value(channel.descriptor.name);
        json.key("column").value(csvHeader(channel.descriptor));
        json.key("unit").value(channel.descriptor.unit);
        json.key("kind").value(toString(channel.descriptor.kind));
        if (channel.descriptor.role) json.key("role").value(toString(*channel.descriptor.role));
        json.key("sample_rate_hz").value(channel.sampleRate_hz);
        json.endObject();
    }
    json.endArray();
    json.key("gaps").beginArray();
    for (const auto& gap : store.gaps(session)) {
        json.beginObject();
        json.key("first_index").value(static_cast<long long>(gap.firstIndex));
        json.key("count").value(static_cast<long long>(gap.count));
        json.endObject();
    }
    json.endArray();
    writeRecords(json, store, session);
    // A panel scan's defect sites, from the events recorded live.
    if (definitionOf(s.metadata.mode).detectsDefects && s.devices == 0)
        detector::writeSitesJson(json, storedSites(store, session, defectEventsOf(store.events(session))));
}

// A device's part, read sample by sample in windows, each sample's time
// on the session's clock (its own time mapped; its own as it is when no
// mapping was stored); its computed columns, if given, after its channels.
class PartReader {
public:
    PartReader(SessionSource& store, const SessionPart& part, std::unique_ptr<ComputedColumns> computed)
        : m_store(store),
          m_computed(std::move(computed)),
          m_part(part.id),
          m_clock(timing::clockMappingFromJson(part.clockJson)),
          m_channels(store.channels(part.id)),
          m_rate_hz(m_channels.empty() ? 1.0 : m_channels.front().sampleRate_hz),
          m_end(store.sampleCount(part.id)),
          m_gaps(store.gaps(part.id)),
          m_wanted(m_channels.size())
    {
        for (std::size_t c = 0; c < m_wanted.size(); ++c) m_wanted[c] = c;
        m_step = std::clamp<std::uint64_t>(kWindowValues / std::max<std::size_t>(1, m_wanted.size()), 1, kWindow);
        m_gap = m_gaps.begin();
        settle();
    }

    bool done() const { return m_channels.empty() || m_index >= m_end; }
    double time_s() const
    {
        const double own_s = static_cast<double>(m_index) / m_rate_hz;
        return m_clock ? m_clock->host_s(own_s) : own_s;
    }
    double value(std::size_t channel) const { return m_window[channel][m_index - m_windowFirst]; }
    const std::vector<StoredChannel>& channels() const { return m_channels; }
    std::vector<ChannelDescriptor> computedChannels() const
    {
        return m_computed ? m_computed->channels() : std::vector<ChannelDescriptor>{};
    }
    // Stored channels then computed ones, as value() numbers them.
    std::size_t columnCount() const { return m_window.size(); }
    void next()
    {
        ++m_index;
        settle();
    }

private:
    // On the next stored sample (past gaps), its window read.
    void settle()
    {
        for (;;) {
            while (m_gap != m_gaps.end() && m_gap->firstIndex + m_gap->count <= m_index) ++m_gap;
            if (m_gap != m_gaps.end() && m_index >= m_gap->firstIndex) {
                m_index = m_gap->firstIndex + m_gap->count;
                continue;
            }
            break;
        }
        if (done() || (m_index >= m_windowFirst && m_index < m_windowFirst + m_windowCount)) return;
        m_window.resize(m_wanted.size());
        m_windowFirst = m_index;
        m_windowCount = m_store.readChannels(m_part, m_wanted, m_index, std::min(m_step, m_end - m_index), m_window);
        if (m_computed)
            for (auto& column : m_computed->read(m_windowFirst, m_windowCount)) m_window.push_back(std::move(column));
    }

    SessionSource& m_store;
    std::unique_ptr<ComputedColumns> m_computed;
    std::int64_t m_part;
    std::optional<timing::ClockMapping> m_clock;
    std::vector<StoredChannel> m_channels;
    double m_rate_hz;
    std::uint64_t m_end;
    std::vector<SampleGap> m_gaps;
    std::vector<SampleGap>::const_iterator m_gap;
    std::vector<std::size_t> m_wanted;
    std::uint64_t m_step = 1;
    std::uint64_t m_index = 0;
    std::uint64_t m_windowFirst = 0;
    std::uint64_t m_windowCount = 0;
    std::vector<std::vector<double>> m_window;
};

// The parts' samples on one time axis: rows in the order of their times on
// the session's clock, each device's channels filled in its own rows and
// empty in the others' (no value is made up between a device's samples).
void writeDevicesCsv(SessionSource& store, const std::vector<SessionPart>& parts, std::ostream& out,
                     const PartColumns& partColumns)
{
    const auto snapshot = store.snapshot();
    std::vector<PartReader> readers;
    readers.reserve(parts.size());
    for (const auto& part : parts) readers.emplace_back(store, part, partColumns ? partColumns(part.id) : nullptr);
    out << "t [s]";
    for (std::size_t p = 0; p < parts.size(); ++p) {
        for (const auto& channel : readers[p].channels())
            out << ',' << parts[p].deviceName << '/' << csvHeader(channel.descriptor);
        for (const auto& channel : readers[p].computedChannels())
            out << ',' << parts[p].deviceName << '/' << csvHeader(channel);
    }
    out << '\n';
    char buffer[32];
    for (;;) {
        PartReader* earliest = nullptr;
        for (auto& reader : readers)
            if (!reader.done() && (!earliest || reader.time_s() < earliest->time_s())) earliest = &reader;
        if (!earliest) break;
        out << text::formatShortest(earliest->time_s());
        for (auto& reader : readers)
            for (std::size_t c = 0; c < reader.columnCount(); ++c) {
                out << ',';
                if (&reader != earliest) continue;
                // Stored samples are binary32; computed ones keep every digit.
                if (c < reader.channels().size())
                    out << formatSample(reader.value(c), buffer);
                else
                    out << text::formatShortest(reader.value(c));
            }
        out << '\n';
        earliest->next();
    }
}

// The parts as the metadata lists them: each device's name, its clock
// mapping (as stored, and in words) and its own session's metadata.
void writeDevices(text::JsonWriter& json, SessionSource& store, const std::vector<SessionPart>& parts)
{
    json.key("time").value("each device's sample times mapped onto the session's clock, in seconds from its "
                           "start; the mapping of each and its uncertainty are under its \"clock\"");
    json.key("devices").beginArray();
    for (const auto& part : parts) {
        json.beginObject();
        json.key("name").value(part.deviceName);
        json.key("clock");
        if (const auto clock = timing::clockMappingFromJson(part.clockJson)) {
            json.beginObject();
            json.key("reference_s").value(clock->reference_s);
            json.key("offset_s").value(clock->offset_s);
            json.key("drift").value(clock->drift);
            json.key("offset_u_s").value(clock->offset_u_s);
            json.key("drift_u").value(clock->drift_u);
            json.key("sample_period_s").value(clock->samplePeriod_s);
            // The whole standard uncertainty of a time at the part's start, as `sessions show` states it.
            json.key("u_at_start_s");
            if (const auto u = clock->uncertainty_s(0.0))
                json.value(*u);
            else
                json.null();
            json.key("uncertainty").value(timing::toString(clock->basis));
            json.key("span_s").value(clock->span_s);
            json.endObject();
        } else {
            json.null();
        }
        json.key("clock_text").value(timing::clockMappingText(part.clockJson));
        writeMetadata(json, store, part.id, {});
        json.endObject();
    }
    json.endArray();
}

}  // namespace

std::string csvHeader(const ChannelDescriptor& channel)
{
    if (!channel.unit.empty()) return channel.name + " [" + channel.unit + "]";
    if (channel.kind == ChannelKind::Strain) return channel.name + " [strain]";
    return channel.name;
}

void writeSessionCsv(SessionSource& store, std::int64_t session, std::ostream& out, const ExportRange& range,
                     ComputedColumns* computed, const PartColumns& partColumns)
{
    requireSession(store, session);
    if (const auto parts = store.parts(session); !parts.empty()) {
        // The whole session: a range and `computed` are one device's.
        writeDevicesCsv(store, parts, out, partColumns);
        return;
    }
    const auto channels = store.channels(session);
    out << "t [s]";
    for (const auto& channel : channels) out << ',' << csvHeader(channel.descriptor);
    if (computed)
        for (const auto& channel : computed->channels()) out << ',' << csvHeader(channel);
    out << '\n';
    const double rate_hz = channels.front().sampleRate_hz;
    char buffer[32];
    std::vector<std::size_t> all(channels.size());
    for (std::size_t c = 0; c < all.size(); ++c) all[c] = c;
    forEachSample(
        store, session, all,
        [&](std::uint64_t index, const auto& window, std::size_t s) {
            out << text::formatShortest(static_cast<double>(index) / rate_hz);
            // Stored samples are binary32; computed ones keep every digit.
            for (std::size_t c = 0; c < window.size(); ++c)
                out << ','
                    << (c < all.size() ? formatSample(window[c][s], buffer) : text::formatShortest(window[c][s]));
            out << '\n';
        },
        range, computed);
}

void writeSessionMetadataJson(SessionSource& store, std::int64_t session, std::ostream& out, const ExportRange& range,
                              ComputedColumns* computed, const PartColumns& partColumns)
{
    text::JsonWriter json;
    json.beginObject();
    writeMetadata(json, store, session, range);
    const auto parts = store.parts(session);
    if (!parts.empty()) writeDevices(json, store, parts);
    // Each computed column as the CSV names it (DEVICE/NAME in a part).
    const auto describe = [&json](const ChannelDescriptor& channel, const std::string& device,
                                  const std::string& basis) {
        const std::string prefix = device.empty() ? std::string() : device + '/';
        json.beginObject();
        json.key("name").value(prefix + channel.name);
        json.key("column").value(prefix + csvHeader(channel));
        json.key("unit").value(channel.unit);
        json.key("kind").value(toString(channel.kind));
        json.key("computed_with").value(basis);
        json.endObject();
    };
    std::vector<std::pair<std::string, std::unique_ptr<ComputedColumns>>> ofParts;
    if (partColumns)
        for (const auto& part : parts)
            if (auto columns = partColumns(part.id)) ofParts.emplace_back(part.deviceName, std::move(columns));
    const bool oneDevice = parts.empty() && computed;
    if (oneDevice || !ofParts.empty()) {
        json.key("computed_columns").beginArray();
        if (oneDevice)
            for (const auto& channel : computed->channels()) describe(channel, {}, computed->basis());
        for (const auto& [device, columns] : ofParts)
            for (const auto& channel : columns->channels()) describe(channel, device, columns->basis());
        json.endArray();
    }
    json.endObject();
    out << json.str() << '\n';
}

namespace {

// One session's samples as JSON columns, "t" (each sample's time by
// timeOf(index)) and one per channel, written into an open object.
void writeSampleColumns(SessionSource& store, std::int64_t session, std::ostream& out,
                        const std::function<double(std::uint64_t)>& timeOf)
{
    // The samples are written column by column ("t", then each channel), a
    // group of columns per pass over the store: as many as kGroupValues
    // values hold, so an hour-long session of a few channels never sits in
    // memory whole and a session of thousands of channels is not read once
    // per channel (quadratic: 10 000 channels took minutes).
    const auto channels = store.channels(session);
    if (channels.empty()) return;
    const std::uint64_t samples = std::max<std::uint64_t>(1, store.sampleCount(session));
    const std::size_t group =
        static_cast<std::size_t>(std::clamp<std::uint64_t>(kGroupValues / samples, 1, channels.size()));
    char buffer[32];
    const auto column = [&](const std::string& name, bool leading) {
        text::JsonWriter key;
        key.value(name);
        out << (leading ? "" : ",") << key.str() << ":[";
    };
    column("t", true);
    bool first = true;
    forEachSample(store, session, {0}, [&](std::uint64_t index, const auto&, std::size_t) {
        out << (first ? "" : ",") << text::formatShortest(timeOf(index));
        first = false;
    });
    out << ']';
    std::vector<std::vector<float>> values;
    for (std::size_t from = 0; from < channels.size(); from += group) {
        std::vector<std::size_t> wanted;
        for (std::size_t c = from; c < std::min(channels.size(), from + group); ++c) wanted.push_back(c);
        values.assign(wanted.size(), {});
        forEachSample(store, session, wanted, [&](std::uint64_t, const auto& window, std::size_t s) {
            for (std::size_t k = 0; k < wanted.size(); ++k) values[k].push_back(static_cast<float>(window[k][s]));
        });
        for (std::size_t k = 0; k < wanted.size(); ++k) {
            column(channels[wanted[k]].descriptor.name, false);
            for (std::size_t s = 0; s < values[k].size(); ++s)
                out << (s == 0 ? "" : ",") << formatSample(values[k][s], buffer);
            out << ']';
        }
    }
}

}  // namespace

void writeSessionJson(SessionSource& store, std::int64_t session, std::ostream& out)
{
    const auto parts = store.parts(session);
    text::JsonWriter head;
    head.beginObject();
    writeMetadata(head, store, session, {});
    if (!parts.empty()) writeDevices(head, store, parts);
    out << head.str() << ",\"samples\":{";
    if (parts.empty()) {
        const auto channels = store.channels(session);
        const double rate_hz = channels.empty() ? 1.0 : channels.front().sampleRate_hz;
        writeSampleColumns(store, session, out,
                           [rate_hz](std::uint64_t i) { return static_cast<double>(i) / rate_hz; });
    }
    // A session of several devices: an object of columns per device, its
    // "t" on the session's clock.
    for (std::size_t p = 0; p < parts.size(); ++p) {
        text::JsonWriter key;
        key.value(parts[p].deviceName);
        out << (p ? "," : "") << key.str() << ":{";
        const auto channels = store.channels(parts[p].id);
        const double rate_hz = channels.empty() ? 1.0 : channels.front().sampleRate_hz;
        const auto clock = timing::clockMappingFromJson(parts[p].clockJson);
        writeSampleColumns(store, parts[p].id, out, [&](std::uint64_t i) {
            const double own_s = static_cast<double>(i) / rate_hz;
            return clock ? clock->host_s(own_s) : own_s;
        });
        out << '}';
    }
    out << "}}\n";
}

std::string metadataSidePath(const std::string& csvPath)
{
    return std::filesystem::path(csvPath).replace_extension(".meta.json").string();
}

void exportSession(SessionSource& store, std::int64_t session, ExportFormat format, const std::string& path,
                   const ExportRange& range, ComputedColumns* computed, const PartColumns& partColumns)
{
    // The store is the one file an export must never replace (a central
    // store's location names no file).
    const auto protectedFiles = storeFiles(store.location());
    refuseOverwriting(path, protectedFiles);
    if (format == ExportFormat::Csv) refuseOverwriting(metadataSidePath(path), protectedFiles);
    if (format == ExportFormat::Json) {
        writeAtomically(path, [&](std::ostream& out) { writeSessionJson(store, session, out); });
        return;
    }
    writeAtomically(path,
                    [&](std::ostream& out) { writeSessionCsv(store, session, out, range, computed, partColumns); });
    writeAtomically(metadataSidePath(path), [&](std::ostream& out) {
        writeSessionMetadataJson(store, session, out, range, computed, partColumns);
    });
}

}  // namespace tactiscope::core::storage
