// Sensor profile JSON: parsing with key-level errors, and writing.
#include "core/sensors/SensorProfile.h"

#include "core/sensors/CompliancePair.h"

#include <nlohmann/json.hpp>

#include <cmath>
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
        const std::string path = m_prefix + key;
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

    double positive(const std::string& key)
    {
        const Json& value = require(key);
        if (!value.is_number() || !(value.get<double>() > 0.0) || !std::isfinite(value.get<double>()))
            fail(key, "must be a positive number, got " + value.dump());
        return value.get<double>();
    }

    ObjectReader object(const std::string& key) { return ObjectReader(require(key), m_source, m_prefix + key + "."); }

    void allowOptional(const std::string& key) { m_used.insert(key); }

    void rejectUnknownKeys() const
    {
        for (const auto& [key, value] : m_object.items()) {
            if (!m_used.count(key)) fail(key, "unknown key");
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

Json geometryJson(const CantileverGeometry& g)
{
    return Json{{"length_m", g.length_m},
                {"width_m", g.width_m},
                {"thickness_m", g.thickness_m},
                {"youngs_modulus_pa", g.youngsModulus_pa}};
}

}  // namespace

SensorProfile parseSensorProfile(std::string_view text, const std::string& source)
{
    Json json;
    try {
        json = Json::parse(text);
    } catch (const Json::parse_error& e) {
        throw ProfileError(source + ": not valid JSON (" + e.what() + ")");
    }
    ObjectReader reader(json, source, "");
    const std::string kind = reader.string("kind");
    const std::string name = reader.string("name");
    if (kind == "cantilever") {
        CantileverProfile profile{name, readGeometry(reader)};
        reader.rejectUnknownKeys();
        return profile;
    }
    if (kind == "compliance_pair") {
        CompliancePairProfile profile{name, readNestedBeam(reader.object("high")),
                                      readNestedBeam(reader.object("low"))};
        reader.rejectUnknownKeys();
        const double kh = CantileverBeam(profile.high).stiffness_n_per_m();
        const double kl = CantileverBeam(profile.low).stiffness_n_per_m();
        if (!(kh > kl)) {
            reader.fail("high", "must be the stiffer beam (k_high = " + std::to_string(kh) +
                                    " N/m, k_low = " + std::to_string(kl) + " N/m)");
        }
        return profile;
    }
    reader.fail("kind", "'" + kind + "' is not a known sensor kind (cantilever, compliance_pair)");
}

SensorProfile loadSensorProfile(const std::string& path)
{
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
    }
    return json.dump(2);
}

const std::string& profileName(const SensorProfile& profile)
{
    return std::visit([](const auto& p) -> const std::string& { return p.name; }, profile);
}

}  // namespace tactiscope::core::sensors
