// Sensor profile JSON: the documented keys, errors naming the bad key, and a
// round trip.
#include "core/sensors/SensorProfile.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

using namespace tactiscope::core::sensors;

namespace {

std::string errorOf(const std::string& json)
{
    try {
        parseSensorProfile(json, "probe.json");
    } catch (const ProfileError& e) {
        return e.what();
    }
    return "no error";
}

const char* kPair = R"({"kind": "compliance_pair", "name": "paper probe",
    "high": {"length_m": 0.05, "width_m": 0.01, "thickness_m": 0.003, "youngs_modulus_pa": 3e9},
    "low": {"length_m": 0.05, "width_m": 0.01, "thickness_m": 0.001, "youngs_modulus_pa": 3e9}})";

}  // namespace

TEST(SensorProfile, ReadsACantilever)
{
    const auto profile = parseSensorProfile(
        R"({"kind": "cantilever", "name": "specimen", "length_m": 0.1, "width_m": 0.01, "thickness_m": 0.002,
            "youngs_modulus_pa": 3e9})",
        "specimen.json");
    const auto& c = std::get<CantileverProfile>(profile);
    EXPECT_EQ(c.name, "specimen");
    EXPECT_DOUBLE_EQ(c.geometry.length_m, 0.1);
    EXPECT_DOUBLE_EQ(c.geometry.youngsModulus_pa, 3e9);
}

TEST(SensorProfile, ReadsACompliancePairAndWritesItBack)
{
    const auto profile = parseSensorProfile(kPair, "probe.json");
    const auto& pair = std::get<CompliancePairProfile>(profile);
    EXPECT_DOUBLE_EQ(pair.high.thickness_m, 0.003);
    EXPECT_DOUBLE_EQ(pair.low.thickness_m, 0.001);
    EXPECT_EQ(profileName(profile), "paper probe");
    const auto again = parseSensorProfile(toJson(profile), "again.json");
    EXPECT_EQ(std::get<CompliancePairProfile>(again).high, pair.high);
    EXPECT_EQ(std::get<CompliancePairProfile>(again).low, pair.low);
}

TEST(SensorProfile, ErrorsNameTheFileAndTheKey)
{
    EXPECT_EQ(errorOf(R"({"kind": "cantilever", "name": "x", "length_m": 0.1, "width_m": 0.01, "thickness_m": -2,
                          "youngs_modulus_pa": 3e9})"),
              "probe.json: thickness_m: must be a positive number, got -2");
    EXPECT_EQ(errorOf(R"({"kind": "cantilever", "name": "x", "length_m": 0.1, "width_m": 0.01,
                          "youngs_modulus_pa": 3e9})"),
              "probe.json: thickness_m: missing");
    EXPECT_EQ(errorOf(R"({"kind": "cantilever", "name": "x", "lenght_m": 0.1, "length_m": 0.1, "width_m": 0.01,
                          "thickness_m": 0.002, "youngs_modulus_pa": 3e9})"),
              "probe.json: lenght_m: unknown key");
    EXPECT_EQ(errorOf(R"({"kind": "spring", "name": "x"})"),
              "probe.json: kind: 'spring' is not a known sensor kind (cantilever, compliance_pair, capacitive_beam)");
    EXPECT_EQ(errorOf(R"({"kind": "compliance_pair", "name": "x", "high": {"length_m": 0.05, "width_m": 0.01,
                          "thickness_m": "3 mm", "youngs_modulus_pa": 3e9}, "low": {}})"),
              "probe.json: high.thickness_m: must be a positive number, got \"3 mm\"");
    EXPECT_NE(errorOf(R"({"kind": "compliance_pair", "name": "x",
        "high": {"length_m": 0.05, "width_m": 0.01, "thickness_m": 0.001, "youngs_modulus_pa": 3e9},
        "low": {"length_m": 0.05, "width_m": 0.01, "thickness_m": 0.003, "youngs_modulus_pa": 3e9}})")
                  .find("high: must be the stiffer beam"),
              std::string::npos);
    EXPECT_EQ(errorOf("{\"kind\": ").rfind("probe.json: not valid JSON (", 0), 0u);
    EXPECT_EQ(errorOf("[1, 2]"), "probe.json: must be a JSON object");
}

TEST(SensorProfile, AMissingFileIsAProfileError)
{
    EXPECT_THROW(loadSensorProfile("/nonexistent/probe.json"), ProfileError);
}

TEST(SensorProfile, ReadsTheShippedCapacitiveBeamAndWritesItBack)
{
    const auto profile = loadSensorProfile(TACTISCOPE_SOURCE_DIR "/resources/profiles/capacitive-beam-paper-no1.json");
    const auto& beam = std::get<CapacitiveBeamProfile>(profile);
    EXPECT_DOUBLE_EQ(beam.geometry.beam.rootWidth_m, 0.005);
    EXPECT_DOUBLE_EQ(beam.geometry.beam.sheetLengthRatio, 0.6);
    ASSERT_EQ(beam.geometry.sheetLayers.size(), 3u);
    EXPECT_DOUBLE_EQ(beam.geometry.sheetLayers[1].thickness_m, 0.000015);
    EXPECT_DOUBLE_EQ(beam.geometry.c0_f, 51.44e-12);
    EXPECT_FALSE(beam.geometry.doubleLayer_f.has_value());
    const auto again = std::get<CapacitiveBeamProfile>(parseSensorProfile(toJson(profile), "again.json"));
    EXPECT_EQ(again.geometry.sheetLayers[2].name, beam.geometry.sheetLayers[2].name);
    EXPECT_DOUBLE_EQ(again.geometry.c0_f, beam.geometry.c0_f);
}

TEST(SensorProfile, CapacitiveBeamErrorsNameTheKey)
{
    const std::string head = R"({"kind": "capacitive_beam", "name": "x", "c0_pf": 51.44,
        "beam": {"length_m": 0.015, "root_width_m": 0.005, "thickness_m": 0.002, "youngs_modulus_pa": 83000,
                 "sheet_length_ratio": )";
    EXPECT_EQ(
        errorOf(head + R"(1.2}, "sheet_layers": [{"name": "e", "thickness_m": 1e-4, "youngs_modulus_pa": 1800}]})"),
        "probe.json: beam.sheet_length_ratio: must be below 1");
    EXPECT_EQ(errorOf(head + R"(0.6}, "sheet_layers": [{"name": "e", "thickness_m": 0, "youngs_modulus_pa": 1800}]})"),
              "probe.json: sheet_layers[0].thickness_m: must be a positive number, got 0");
    EXPECT_EQ(errorOf(head + R"(0.6}, "sheet_layers": []})"), "probe.json: sheet_layers: must be a non-empty list");
    EXPECT_EQ(errorOf(head + R"(0.6}, "sheet_layers": [{"name": "e", "thickness_m": 1e-4, "youngs_modulus_pa": 1800}],
                   "baseline_wander_pf_per_sqrt_s": -1})"),
              "probe.json: baseline_wander_pf_per_sqrt_s: must be a positive number, got -1");
}

// A beam's baseline stability (issue 55): read in pF/√s, kept in F/√s,
// written back; absent, none (the shipped paper's sensor states none).
TEST(SensorProfile, ACapacitiveBeamMayStateItsBaselineStability)
{
    auto profile = loadSensorProfile(TACTISCOPE_SOURCE_DIR "/resources/profiles/capacitive-beam-paper-no1.json");
    auto& beam = std::get<CapacitiveBeamProfile>(profile);
    EXPECT_FALSE(beam.baselineWander_f_per_sqrt_s.has_value());
    beam.baselineWander_f_per_sqrt_s = 0.2e-15;
    const std::string json = toJson(profile);
    EXPECT_NE(json.find("\"baseline_wander_pf_per_sqrt_s\": "), std::string::npos) << json;
    const auto again = std::get<CapacitiveBeamProfile>(parseSensorProfile(json, "again.json"));
    ASSERT_TRUE(again.baselineWander_f_per_sqrt_s);
    EXPECT_NEAR(*again.baselineWander_f_per_sqrt_s, 0.2e-15, 1e-24);
}

// A board printing its capacitance converter's counts has their scale in
// the capacitive beam's profile: a capacitance unit, counts per unit and
// the count of zero; no full scale (the capacitive mode judges no
// clipping), and no beam's unit.
TEST(SensorProfile, ACapacitiveBeamMayScaleItsCapacitanceInCountsAndWritesTheScaleBack)
{
    const std::string head = R"({"kind": "capacitive_beam", "name": "x", "c0_pf": 51.44,
        "beam": {"length_m": 0.015, "root_width_m": 0.005, "thickness_m": 0.002, "youngs_modulus_pa": 83000,
                 "sheet_length_ratio": 0.6}, "sheet_layers": [{"name": "e", "thickness_m": 1e-4,
                 "youngs_modulus_pa": 1800}], "channels": )";
    const auto profile = parseSensorProfile(
        head + R"({"c": {"unit": "pF", "counts_per_unit": 2048000, "offset": 8388608}}})", "probe.json");
    const ChannelScales expected{{"c", {"pF", 2048000.0, std::nullopt, 8388608.0}}};
    EXPECT_EQ(profileScales(profile), expected);
    EXPECT_EQ(profileScales(parseSensorProfile(toJson(profile), "again.json")), expected);
    EXPECT_EQ(errorOf(head + R"({"c": {"unit": "mN", "counts_per_unit": 2}}})"),
              "probe.json: channels.c.unit: 'mN' is not a capacitance unit (F, nF, pF, fF)");
    EXPECT_EQ(errorOf(head + R"({"c": {"unit": "pF", "counts_per_unit": 2, "full_scale": 8388608}}})"),
              "probe.json: channels.c.full_scale: a capacitance's range is not judged: the capacitive mode flags "
              "no clipping");
    // Nor does a compliance pair take a capacitance.
    std::string pair(kPair);
    pair.insert(pair.rfind('}'), R"(, "channels": {"stiff": {"unit": "pF"}})");
    EXPECT_EQ(errorOf(pair), "probe.json: channels.stiff.unit: 'pF' is not a strain, a force or a length unit "
                             "(strain, µε, N, mN, µN, m, mm, µm)");
}

TEST(SensorProfile, AProfileMaySayWhichChannelsPlayWhichRoleAndWritesThemBack)
{
    std::string json(kPair);
    json.insert(json.rfind('}'), R"(, "roles": {"ch1": "stiff-beam", "ch2": "soft-beam", "ch3": "displacement"})");
    const auto profile = parseSensorProfile(json, "probe.json");
    const tactiscope::core::RoleAssignment expected{{"ch1", tactiscope::core::ChannelRole::StiffBeam},
                                                    {"ch2", tactiscope::core::ChannelRole::SoftBeam},
                                                    {"ch3", tactiscope::core::ChannelRole::Displacement}};
    EXPECT_EQ(profileRoles(profile), expected);
    EXPECT_EQ(profileRoles(parseSensorProfile(toJson(profile), "again.json")), expected);
    EXPECT_TRUE(profileRoles(parseSensorProfile(kPair, "probe.json")).empty());
    EXPECT_EQ(toJson(parseSensorProfile(kPair, "probe.json")).find("roles"), std::string::npos);

    const auto withRoles = [](const char* roles) {
        std::string text(kPair);
        text.insert(text.rfind('}'), std::string(", \"roles\": ") + roles);
        return text;
    };
    EXPECT_EQ(errorOf(withRoles(R"(["stiff-beam"])")),
              "probe.json: roles: must be an object of channel names and roles");
    EXPECT_EQ(errorOf(withRoles(R"({"ch1": 3})")), "probe.json: roles.ch1: must be a role's name");
    EXPECT_EQ(errorOf(withRoles(R"({"ch1": "stiff"})")),
              "probe.json: roles: 'stiff' is not a channel role; the roles are cantilever-a, cantilever-b, "
              "stiff-beam, soft-beam, displacement, capacitance, reference-force or position");
    EXPECT_EQ(errorOf(withRoles(R"({"ch1": "stiff-beam", "ch2": "stiff-beam"})")),
              "probe.json: roles: the role stiff-beam is given to both 'ch1' and 'ch2'");
}

// A profile holding a 32 MB array kept the window from appearing and froze
// the profile list; the CLI's error quoted the whole value. A text over
// 1 MB is refused before it is parsed, a file before it is read, and a
// message quotes at most 40 characters of a bad value.
TEST(SensorProfile, AHugeProfileIsRefusedUnreadAndBadValuesAreQuotedShort)
{
    const std::string huge = R"({"kind": "cantilever", "name": "x", "junk": [)" + std::string(2'000'000, '1') + "]}";
    try {
        tactiscope::core::sensors::parseSensorProfile(huge, "huge.json");
        FAIL() << "a 2 MB profile was read";
    } catch (const tactiscope::core::sensors::ProfileError& e) {
        EXPECT_NE(
            std::string(e.what()).find("huge.json: " + std::to_string(huge.size()) + " bytes, not a sensor profile"),
            std::string::npos)
            << e.what();
    }
    const std::string path = ::testing::TempDir() + "/huge-profile.json";
    {
        std::ofstream file(path, std::ios::binary);
        file << huge;
    }
    EXPECT_THROW(tactiscope::core::sensors::loadSensorProfile(path), tactiscope::core::sensors::ProfileError);
    std::remove(path.c_str());

    const std::string longKind = R"({"kind": ")" + std::string(10'000, 'k') + R"(", "name": "x"})";
    const std::string longValue =
        R"({"kind": "cantilever", "name": "x", "length_m": [)" + std::string(9'000, '7') + R"(], "width_m": 1,
            "thickness_m": 1, "youngs_modulus_pa": 1})";
    const std::string longName = R"({"kind": "cantilever", "name": ")" + std::string(1'000, 'n') + R"(",
            "length_m": 1, "width_m": 1, "thickness_m": 1, "youngs_modulus_pa": 1})";
    for (const std::string& text : {longKind, longValue, longName}) {
        try {
            tactiscope::core::sensors::parseSensorProfile(text, "p.json");
            FAIL() << "accepted";
        } catch (const tactiscope::core::sensors::ProfileError& e) {
            EXPECT_LT(std::string(e.what()).size(), 200u) << e.what();
            EXPECT_NE(std::string(e.what()).find("characters)"), std::string::npos) << e.what();
        }
    }
}

// Issue 53: a board that prints raw counts has its scale in the profile.
TEST(SensorProfile, ACompliancePairMayScaleBeamsInCountsAndWritesTheScalesBack)
{
    const auto withChannels = [](const char* channels) {
        std::string text(kPair);
        text.insert(text.rfind('}'), std::string(", \"channels\": ") + channels);
        return text;
    };
    const auto profile =
        parseSensorProfile(withChannels(R"({"stiff": {"unit": "mN", "counts_per_unit": 20.5, "full_scale": 32767},
                         "soft": {"unit": "µε", "counts_per_unit": 3}})"),
                           "probe.json");
    const ChannelScales expected{{"stiff", {"mN", 20.5, 32767.0}}, {"soft", {"µε", 3.0, std::nullopt}}};
    EXPECT_EQ(profileScales(profile), expected);
    EXPECT_EQ(profileScales(parseSensorProfile(toJson(profile), "again.json")), expected);
    EXPECT_TRUE(profileScales(parseSensorProfile(kPair, "probe.json")).empty());

    // A displacement's length, given by its unit alone: the values are in it.
    EXPECT_EQ(profileScales(parseSensorProfile(withChannels(R"({"d": {"unit": "mm"}})"), "probe.json")),
              (ChannelScales{{"d", {"mm", 1.0, std::nullopt}}}));
    EXPECT_EQ(errorOf(withChannels(R"({"stiff": {"unit": "V", "counts_per_unit": 2}})")),
              "probe.json: channels.stiff.unit: 'V' is not a strain, a force or a length unit (strain, µε, N, mN, "
              "µN, m, mm, µm)");
    EXPECT_EQ(errorOf(withChannels(R"({"stiff": {"unit": "N", "counts_per_unit": 0}})")),
              "probe.json: channels.stiff.counts_per_unit: must be a positive number, got 0");
    // An offset: the count of zero, written back.
    const auto offset = parseSensorProfile(
        withChannels(R"({"d": {"unit": "mm", "counts_per_unit": 400, "offset": -2048.5}})"), "probe.json");
    const ChannelScales centred{{"d", {"mm", 400.0, std::nullopt, -2048.5}}};
    EXPECT_EQ(profileScales(offset), centred);
    EXPECT_EQ(profileScales(parseSensorProfile(toJson(offset), "again.json")), centred);
    EXPECT_EQ(errorOf(withChannels(R"({"stiff": {"unit": "N", "counts_per_unit": 2, "offset": "mid"}})")),
              "probe.json: channels.stiff.offset: must be a number, got \"mid\"");
    EXPECT_EQ(errorOf(withChannels(R"({"stiff": {"unit": "N", "counts_per_unit": 2, "zero": 5}})")),
              "probe.json: channels.stiff.zero: unknown key");
    EXPECT_EQ(errorOf(withChannels(R"([1])")), "probe.json: channels: must be a JSON object");
}
