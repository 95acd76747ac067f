// CalibrationRecord lookup and JSON form.
#include "core/calibration/CalibrationRecord.h"

#include "core/JsonText.h"
#include "core/text/JsonWriter.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <ctime>

namespace tactiscope::core::calibration {

std::optional<double> CalibrationRecord::value(const std::string& name) const
{
    for (const auto& [key, v] : values) {
        if (key == name) return v;
    }
    return std::nullopt;
}

std::string CalibrationRecord::toJson() const
{
    text::JsonWriter json;
    json.beginObject();
    json.key("kind").value(kind);
    json.key("sensor").value(sensorName);
    json.key("operator").value(operatorName);
    json.key("timestamp_utc").value(timestampUtc);
    json.key("values").beginObject();
    for (const auto& [key, v] : values) json.key(key).value(v);
    json.endObject();
    json.key("fit").beginObject();
    json.key("slope").value(fit.slope);
    json.key("intercept").value(fit.intercept);
    json.key("r_squared").value(fit.rSquared);
    json.key("slope_standard_error").value(fit.slopeStandardError);
    json.key("intercept_standard_error").value(fit.interceptStandardError);
    json.key("residual_standard_deviation").value(fit.residualStandardDeviation);
    json.key("points").value(static_cast<long long>(fit.points));
    json.key("residuals").beginArray();
    for (double r : fit.residuals) json.value(r);
    json.endArray();
    json.endObject();
    json.endObject();
    return json.str();
}

CalibrationRecord CalibrationRecord::fromJson(std::string_view text)
{
    try {
        const auto json = parseOrderedJsonText(text, "calibration record");  // keeps the values' order
        CalibrationRecord record;
        record.kind = json.at("kind").get<std::string>();
        record.sensorName = json.at("sensor").get<std::string>();
        record.operatorName = json.at("operator").get<std::string>();
        record.timestampUtc = json.at("timestamp_utc").get<std::string>();
        for (const auto& [key, value] : json.at("values").items()) record.values.emplace_back(key, value.get<double>());
        const auto& fit = json.at("fit");
        record.fit.slope = fit.at("slope").get<double>();
        record.fit.intercept = fit.at("intercept").get<double>();
        record.fit.rSquared = fit.at("r_squared").get<double>();
        record.fit.slopeStandardError = fit.at("slope_standard_error").get<double>();
        record.fit.interceptStandardError = fit.at("intercept_standard_error").get<double>();
        record.fit.residualStandardDeviation = fit.at("residual_standard_deviation").get<double>();
        record.fit.points = fit.at("points").get<std::size_t>();
        record.fit.residuals = fit.at("residuals").get<std::vector<double>>();
        return record;
    } catch (const nlohmann::ordered_json::exception& e) {
        throw std::invalid_argument(std::string("not a calibration record: ") + e.what());
    } catch (const JsonTextError& e) {
        throw std::invalid_argument(std::string("not a calibration record: ") + e.what());
    }
}

std::vector<CalibrationRecord> recordsFromJsonArray(const std::string& json)
{
    std::vector<CalibrationRecord> records;
    const auto array = nlohmann::json::parse(json.empty() ? "[]" : json, nullptr, false);
    if (!array.is_array()) return records;
    for (const auto& record : array) {
        try {
            records.push_back(CalibrationRecord::fromJson(record.dump()));
        } catch (const std::invalid_argument&) {
        }
    }
    return records;
}

std::string utcTimestampNow()
{
    const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
    std::tm utc{};
    gmtime_r(&now, &utc);
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
    return text;
}

std::string beamSensorName(const std::string& probeName, bool stiffBeam)
{
    return probeName + (stiffBeam ? " — stiff beam" : " — soft beam");
}

}  // namespace tactiscope::core::calibration
