// TextChecks: UTF-8 validation (RFC 3629: no overlong forms, no surrogates,
// nothing above U+10FFFF), Latin-1 to UTF-8, and the uuid shape.
#include "core/text/TextChecks.h"

#include <cctype>
#include <cstdio>

namespace tactiscope::core::text {
namespace {

std::string at(std::size_t index, unsigned char byte, const char* what)
{
    char text[64];
    std::snprintf(text, sizeof text, "byte 0x%02X at %zu %s", byte, index, what);
    return text;
}

}  // namespace

std::optional<std::string> textProblem(std::string_view text)
{
    for (std::size_t i = 0; i < text.size();) {
        const auto lead = static_cast<unsigned char>(text[i]);
        if (lead == 0) return "a NUL character at " + std::to_string(i);
        std::size_t length = 0;
        unsigned low = 0x80, high = 0xBF;  // the second byte's range
        if (lead < 0x80) {
            ++i;
            continue;
        } else if (lead >= 0xC2 && lead <= 0xDF) {
            length = 2;
        } else if (lead >= 0xE0 && lead <= 0xEF) {
            length = 3;
            if (lead == 0xE0) low = 0xA0;   // no overlong forms
            if (lead == 0xED) high = 0x9F;  // no surrogates
        } else if (lead >= 0xF0 && lead <= 0xF4) {
            length = 4;
            if (lead == 0xF0) low = 0x90;
            if (lead == 0xF4) high = 0x8F;  // nothing above U+10FFFF
        } else {
            return at(i, lead, "is not UTF-8");
        }
        if (i + length > text.size()) return at(i, lead, "starts a character the text cuts off");
        for (std::size_t k = 1; k < length; ++k) {
            const auto next = static_cast<unsigned char>(text[i + k]);
            if (next < (k == 1 ? low : 0x80) || next > (k == 1 ? high : 0xBF)) return at(i + k, next, "is not UTF-8");
        }
        i += length;
    }
    return std::nullopt;
}

std::string latin1ToUtf8(std::string_view text)
{
    std::string out;
    out.reserve(text.size() + text.size() / 4);
    for (const char c : text) {
        const auto byte = static_cast<unsigned char>(c);
        if (byte < 0x80) {
            out += c;
        } else {
            out += static_cast<char>(0xC0 | (byte >> 6));
            out += static_cast<char>(0x80 | (byte & 0x3F));
        }
    }
    return out;
}

bool isUuid(std::string_view text)
{
    if (text.size() != 36) return false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const bool dash = i == 8 || i == 13 || i == 18 || i == 23;
        if (dash ? text[i] != '-' : !std::isxdigit(static_cast<unsigned char>(text[i]))) return false;
    }
    return true;
}

}  // namespace tactiscope::core::text
