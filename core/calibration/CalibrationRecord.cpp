// CalibrationRecord lookup and JSON form.
#include "core/calibration/CalibrationRecord.h"

#include "core/text/JsonWriter.h"

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
    json.key("points").value(static_cast<long long>(fit.points));
    json.key("residuals").beginArray();
    for (double r : fit.residuals) json.value(r);
    json.endArray();
    json.endObject();
    json.endObject();
    return json.str();
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

}  // namespace tactiscope::core::calibration
