// A small streaming JSON writer for machine-readable CLI output: objects,
// arrays, strings (escaped), numbers (shortest round-trip; not-finite as
// null), booleans. It checks nothing about nesting: callers write valid
// structures, and tests parse the result.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace tactiscope::core::text {

class JsonWriter {
public:
    JsonWriter& beginObject() { return open('{'); }
    JsonWriter& endObject() { return close('}'); }
    JsonWriter& beginArray() { return open('['); }
    JsonWriter& endArray() { return close(']'); }
    JsonWriter& key(std::string_view name);
    JsonWriter& value(std::string_view text);
    JsonWriter& value(const char* text) { return value(std::string_view(text)); }
    JsonWriter& value(double number);
    JsonWriter& value(long long number);
    JsonWriter& value(bool flag);
    JsonWriter& null();

    const std::string& str() const { return m_out; }

private:
    void separate();
    JsonWriter& open(char bracket);
    JsonWriter& close(char bracket);

    std::string m_out;
    std::vector<bool> m_first;  // per open container: nothing written yet
    bool m_afterKey = false;
};

}  // namespace tactiscope::core::text
