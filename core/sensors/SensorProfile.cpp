// Sensor profile JSON: parsing with key-level errors, and writing.
#include "core/sensors/SensorProfile.h"

#include "core/JsonText.h"
#include "core/UnitScale.h"
#include "core/sensors/CompliancePair.h"
#include "core/text/ShortQuote.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace tactiscope::core::sensors {
namespace {

using Json = nlohmann::json;

// Reads keys of one JSON object, remembering which were used so leftovers
// can be reported as unknown.
class ObjectReader {
public:
    ObjectReader(const Json& object, std::string source, std::string prefix)
        : m_object(object),
          m_source(std::move(source)),
          m_prefix(std::move(prefix))
    {
        if (!object.is_object()) fail("", "must be a JSON object");
    }

    [[noreturn]] void fail(const std::string& key, const std::string& problem) const
    {
        std::string path = m_prefix + key;
        if (key.empty() && !path.empty() && path.back() == '.') path.pop_back();  // the object itself
        throw ProfileError(m_source + ": " + (path.empty() ? "" : path + ": ") + problem);
    }

    const Json& require(const std::string& key)
    {
        const auto it = m_object.find(key);
        if (it == m_object.end()) fail(key, "missing");
        m_used.insert(key);
        return *it;
    }

    std::string string(const std::string& key)
    {
        const Json& value = require(key);
        if (!value.is_string() || value.get<std::string>().empty()) fail(key, "must be a non-empty string");
        return value.get<std::string>();
    }

    double finite(const std::string& key)
    {
        const Json& value = require(key);
        if (!value.is_number() || !std::isfinite(value.get<double>()))
            fail(key, "must be a number, got " + text::shortened(value.dump()));
        return value.get<double>();
    }

    double positive(const std::string& key)
    {
        const Json& value = require(key);
        if (!value.is_number() || !(value.get<double>() > 0.0) || !std::isfinite(value.get<double>()))
            fail(key, "must be a positive number, got " + text::shortened(value.dump()));
        return value.get<double>();
    }

    ObjectReader object(const std::string& key) { return ObjectReader(require(key), m_source, m_prefix + key + "."); }

    // The elements of a non-empty array of objects, each with its own reader.
    std::vector<ObjectReader> objects(const std::string& key)
    {
        const Json& value = require(key);
        if (!value.is_array() || value.empty()) fail(key, "must be a non-empty list");
        std::vector<ObjectReader> readers;
        for (std::size_t i = 0; i < value.size(); ++i)
            readers.emplace_back(value[i], m_source, m_prefix + key + "[" + std::to_string(i) + "].");
        return readers;
    }

    bool has(const std::string& key) const { return m_object.contains(key); }

    std::vector<std::string> keys() const
    {
        std::vector<std::string> names;
        for (const auto& [key, value] : m_object.items()) names.push_back(key);
        return names;
    }

    void allowOptional(const std::string& key) { m_used.insert(key); }

    void rejectUnknownKeys() const
    {
        for (const auto& [key, value] : m_object.items()) {
            if (!m_used.count(key)) fail(text::shortened(key), "unknown key");
        }
    }

private:
    const Json& m_object;
    std::string m_source;
    std::string m_prefix;
    std::set<std::string> m_used;
};

CantileverGeometry readGeometry(ObjectReader& reader)
{
    CantileverGeometry g;
    g.length_m = reader.positive("length_m");
    g.width_m = reader.positive("width_m");
    g.thickness_m = reader.positive("thickness_m");
    g.youngsModulus_pa = reader.positive("youngs_modulus_pa");
    return g;
}

// A beam nested in a pair may repeat kind and name for readability.
CantileverGeometry readNestedBeam(ObjectReader reader)
{
    reader.allowOptional("kind");
    reader.allowOptional("name");
    const CantileverGeometry g = readGeometry(reader);
    reader.rejectUnknownKeys();
    return g;
}

CapacitiveBeamGeometry readCapacitiveBeam(ObjectReader& reader)
{
    CapacitiveBeamGeometry g;
    ObjectReader beam = reader.object("beam");
    g.beam.length_m = beam.positive("length_m");
    g.beam.rootWidth_m = beam.positive("root_width_m");
    g.beam.thickness_m = beam.positive("thickness_m");
    g.beam.youngsModulus_pa = beam.positive("youngs_modulus_pa");
    g.beam.sheetLengthRatio = beam.positive("sheet_length_ratio");
    if (g.beam.sheetLengthRatio >= 1.0) beam.fail("sheet_length_ratio", "must be below 1");
    beam.rejectUnknownKeys();
    for (ObjectReader& layer : reader.objects("sheet_layers")) {
        g.sheetLayers.push_back(
            {layer.string("name"), layer.positive("thickness_m"), layer.positive("youngs_modulus_pa")});
        layer.rejectUnknownKeys();
    }
    g.c0_f = reader.positive("c0_pf") * 1e-12;
    if (reader.has("c_edl_pf")) g.doubleLayer_f = reader.positive("c_edl_pf") * 1e-12;
    return g;
}

// "roles": {"channel": "role", …}, checked as the command line's list is.
RoleAssignment readRoles(ObjectReader& reader)
{
    if (!reader.has("roles")) return {};
    const Json& roles = reader.require("roles");
    if (!roles.is_object()) reader.fail("roles", "must be an object of channel names and roles");
    std::string text;
    for (const auto& [channel, role] : roles.items()) {
        if (!role.is_string()) reader.fail("roles." + channel, "must be a role's name");
        text += (text.empty() ? "" : ",") + channel + "=" + role.get<std::string>();
    }
    try {
        return parseRoleAssignment(text);
    } catch (const std::invalid_argument& e) {
        reader.fail("roles", e.what());
    }
}

// "limits": ["QUANTITY>warning:W,critical:C", …], each read as the
// command line's --limit is.
ProfileLimits readLimits(ObjectReader& reader)
{
    if (!reader.has("limits")) return std::nullopt;
    const Json& limits = reader.require("limits");
    if (!limits.is_array()) reader.fail("limits", "must be a list of limits such as \"force>warning:0.0005\"");
    std::vector<trigger::LimitSpec> specs;
    for (const auto& limit : limits) {
        if (!limit.is_string()) reader.fail("limits", "each limit must be a text such as \"force>warning:0.0005\"");
        const auto parsed = trigger::parseLimit(limit.get<std::string>());
        if (!parsed.limit) reader.fail("limits", parsed.error);
        specs.push_back(*parsed.limit);
    }
    return specs;
}

Json limitsJson(const std::vector<trigger::LimitSpec>& limits)
{
    Json json = Json::array();
    for (const auto& limit : limits) json.push_back(limit.text());
    return json;
}

// "channels": {"NAME": {"unit", "counts_per_unit", "offset", "full_scale"}}:
// a compliance pair's beams a device sends in counts, read as a strain or
// a force, and its displacement as a length; a capacitive beam's
// capacitance in counts. Without counts_per_unit the values are in the
// unit ("d": {"unit": "mm"}: a board printing millimetres).
enum class ScaledQuantities { Beams, Capacitance };

ChannelScales readScales(ObjectReader& reader, ScaledQuantities quantities)
{
    if (!reader.has("channels")) return {};
    ObjectReader channels = reader.object("channels");
    ChannelScales scales;
    for (const std::string& name : channels.keys()) {
        ObjectReader entry = channels.object(name);
        ChannelScale scale;
        scale.unit = entry.string("unit");
        const auto unit = physicalUnit(scale.unit);
        const auto kind = unit ? unit->kind : ChannelKind::Other;
        if (quantities == ScaledQuantities::Beams && kind != ChannelKind::Strain && kind != ChannelKind::Force &&
            kind != ChannelKind::Position)
            entry.fail("unit", text::quoteShort(scale.unit) +
                                   " is not a strain, a force or a length unit (strain, µε, N, mN, µN, m, mm, µm)");
        if (quantities == ScaledQuantities::Capacitance && kind != ChannelKind::Capacitance)
            entry.fail("unit", text::quoteShort(scale.unit) + " is not a capacitance unit (F, nF, pF, fF)");
        if (entry.has("counts_per_unit")) scale.countsPerUnit = entry.positive("counts_per_unit");
        if (entry.has("offset")) scale.offset_counts = entry.finite("offset");
        // The capacitive readout judges no clipping (nor does it for a probe's capacitance).
        if (quantities == ScaledQuantities::Capacitance && entry.has("full_scale"))
            entry.fail("full_scale", "a capacitance's range is not judged: the capacitive mode flags no clipping");
        if (entry.has("full_scale")) scale.fullScale_counts = entry.positive("full_scale");
        entry.rejectUnknownKeys();
        scales.emplace(name, std::move(scale));
    }
    return scales;
}

Json scalesJson(const ChannelScales& scales)
{
    Json json = Json::object();
    for (const auto& [channel, scale] : scales) {
        Json entry{{"unit", scale.unit}, {"counts_per_unit", scale.countsPerUnit}};
        if (scale.offset_counts != 0.0) entry["offset"] = scale.offset_counts;
        if (scale.fullScale_counts) entry["full_scale"] = *scale.fullScale_counts;
        json[channel] = std::move(entry);
    }
    return json;
}

Json rolesJson(const RoleAssignment& roles)
{
    Json json = Json::object();
    for (const auto& [channel, role] : roles) json[channel] = std::string(toString(role));
    return json;
}

Json geometryJson(const CantileverGeometry& g)
{
    return Json{{"length_m", g.length_m},
                {"width_m", g.width_m},
                {"thickness_m", g.thickness_m},
                {"youngs_modulus_pa", g.youngsModulus_pa}};
}

}  // namespace

void refuseOversizedProfile(std::uintmax_t bytes, const std::string& source)
{
    if (bytes > kMostProfileBytes)
        throw ProfileError(source + ": " + std::to_string(bytes) +
                           " bytes, not a sensor profile (one holds a few dozen numbers and names, at most 1 MB)");
}

SensorProfile parseSensorProfile(std::string_view text, const std::string& source)
{
    refuseOversizedProfile(text.size(), source);
    Json json;
    try {
        json = parseJsonText(text, source);
    } catch (const JsonTextError& e) {
        throw ProfileError(e.what());
    }
    ObjectReader reader(json, source, "");
    const std::string kind = reader.string("kind");
    const std::string name = reader.string("name");
    if (name.size() > kMostProfileNameCharacters)
        reader.fail("name", text::shortened(name) + " is longer than a name (at most " +
                                std::to_string(kMostProfileNameCharacters) + " characters)");
    if (kind == "cantilever") {
        CantileverProfile profile{name, readGeometry(reader)};
        reader.rejectUnknownKeys();
        return profile;
    }
    if (kind == "compliance_pair") {
        CompliancePairProfile profile{name,
                                      readNestedBeam(reader.object("high")),
                                      readNestedBeam(reader.object("low")),
                                      readRoles(reader),
                                      readLimits(reader),
                                      readScales(reader, ScaledQuantities::Beams)};
        reader.rejectUnknownKeys();
        const double kh = CantileverBeam(profile.high).stiffness_n_per_m();
        const double kl = CantileverBeam(profile.low).stiffness_n_per_m();
        if (!(kh > kl)) {
            reader.fail("high", "must be the stiffer beam (k_high = " + std::to_string(kh) +
                                    " N/m, k_low = " + std::to_string(kl) + " N/m)");
        }
        return profile;
    }
    if (kind == "capacitive_beam") {
        CapacitiveBeamProfile profile{name, readCapacitiveBeam(reader), readRoles(reader), readLimits(reader),
                                      readScales(reader, ScaledQuantities::Capacitance)};
        if (reader.has("baseline_wander_pf_per_sqrt_s"))
            profile.baselineWander_f_per_sqrt_s = reader.positive("baseline_wander_pf_per_sqrt_s") * 1e-12;
        reader.rejectUnknownKeys();
        return profile;
    }
    reader.fail("kind",
                text::quoteShort(kind) + " is not a known sensor kind (cantilever, compliance_pair, capacitive_beam)");
}

SensorProfile loadSensorProfile(const std::string& path)
{
    std::error_code error;
    if (const auto bytes = std::filesystem::file_size(path, error); !error) refuseOversizedProfile(bytes, path);
    std::ifstream file(path, std::ios::binary);
    if (!file) throw ProfileError(path + ": cannot open the file");
    std::ostringstream text;
    text << file.rdbuf();
    return parseSensorProfile(text.str(), path);
}

std::string toJson(const SensorProfile& profile)
{
    Json json;
    if (const auto* c = std::get_if<CantileverProfile>(&profile)) {
        json = geometryJson(c->geometry);
        json["kind"] = "cantilever";
        json["name"] = c->name;
    } else if (const auto* pair = std::get_if<CompliancePairProfile>(&profile)) {
        json = Json{{"kind", "compliance_pair"},
                    {"name", pair->name},
                    {"high", geometryJson(pair->high)},
                    {"low", geometryJson(pair->low)}};
        if (!pair->roles.empty()) json["roles"] = rolesJson(pair->roles);
        if (pair->limits) json["limits"] = limitsJson(*pair->limits);
        if (!pair->channels.empty()) json["channels"] = scalesJson(pair->channels);
    } else if (const auto* capacitive = std::get_if<CapacitiveBeamProfile>(&profile)) {
        const auto& g = capacitive->geometry;
        Json layers = Json::array();
        for (const auto& layer : g.sheetLayers)
            layers.push_back({{"name", layer.name},
                              {"thickness_m", layer.thickness_m},
                              {"youngs_modulus_pa", layer.youngsModulus_pa}});
        json = Json{{"kind", "capacitive_beam"},
                    {"name", capacitive->name},
                    {"beam",
                     {{"length_m", g.beam.length_m},
                      {"root_width_m", g.beam.rootWidth_m},
                      {"thickness_m", g.beam.thickness_m},
                      {"youngs_modulus_pa", g.beam.youngsModulus_pa},
                      {"sheet_length_ratio", g.beam.sheetLengthRatio}}},
                    {"sheet_layers", layers},
                    {"c0_pf", g.c0_f * 1e12}};
        if (g.doubleLayer_f) json["c_edl_pf"] = *g.doubleLayer_f * 1e12;
        if (!capacitive->roles.empty()) json["roles"] = rolesJson(capacitive->roles);
        if (capacitive->limits) json["limits"] = limitsJson(*capacitive->limits);
        if (!capacitive->channels.empty()) json["channels"] = scalesJson(capacitive->channels);
        if (capacitive->baselineWander_f_per_sqrt_s)
            json["baseline_wander_pf_per_sqrt_s"] = *capacitive->baselineWander_f_per_sqrt_s * 1e12;
    }
    return json.dump(2);
}

const std::string& profileName(const SensorProfile& profile)
{
    return std::visit([](const auto& p) -> const std::string& { return p.name; }, profile);
}

ChannelScales profileScales(const SensorProfile& profile)
{
    if (const auto* pair = std::get_if<CompliancePairProfile>(&profile)) return pair->channels;
    if (const auto* capacitive = std::get_if<CapacitiveBeamProfile>(&profile)) return capacitive->channels;
    return {};
}

RoleAssignment profileRoles(const SensorProfile& profile)
{
    if (const auto* pair = std::get_if<CompliancePairProfile>(&profile)) return pair->roles;
    if (const auto* capacitive = std::get_if<CapacitiveBeamProfile>(&profile)) {
        // A channel it scales is the beam's capacitance, in counts, unless
        // it says otherwise.
        RoleAssignment roles = capacitive->roles;
        for (const auto& [channel, scale] : capacitive->channels) roles.try_emplace(channel, ChannelRole::Capacitance);
        return roles;
    }
    return {};
}

}  // namespace tactiscope::core::sensors
