#include "oit/settings.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace strata {
namespace {

std::string number(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.10g", v);
    return text;
}

// Long or binary input is quoted cut and escaped, so the error stays one readable line.
std::string quoted(std::string_view text) {
    std::string out = "'";
    for (std::size_t i = 0; i < text.size() && i < 40; ++i) {
        unsigned char c = static_cast<unsigned char>(text[i]);
        if (c < 0x20 || c >= 0x7f) {
            char hex[8];
            std::snprintf(hex, sizeof hex, "\\x%02x", c);
            out += hex;
        } else {
            out += char(c);
        }
    }
    if (text.size() > 40) out += "...";
    return out + "'";
}

}  // namespace

const char* toString(SettingType type) {
    switch (type) {
        case SettingType::Integer: return "integer";
        case SettingType::Real: return "real";
        case SettingType::Flag: return "flag";
    }
    return "?";
}

const char* toString(SettingChange change) {
    switch (change) {
        case SettingChange::Nothing: return "nothing";
        case SettingChange::Reallocate: return "reallocate";
        case SettingChange::Recompile: return "recompile";
    }
    return "?";
}

std::string describeRange(const SettingDescription& d) {
    if (d.type == SettingType::Flag) return "flag (true or false, 1 or 0, on or off)";
    if (!d.allowed.empty()) {
        std::string out;
        for (std::size_t i = 0; i < d.allowed.size(); ++i)
            out += (i == 0 ? "" : i + 1 == d.allowed.size() ? " or " : ", ") + number(d.allowed[i]);
        return out;
    }
    return std::string(toString(d.type)) + " in [" + number(d.min) + ", " + number(d.max) + "]";
}

void checkSettingValue(const SettingDescription& d, double value) {
    auto fail = [&] {
        throw std::invalid_argument("setting " + d.name + " = " + number(value) + ": expected " + describeRange(d));
    };
    if (!std::isfinite(value)) fail();
    if (d.type != SettingType::Real && value != std::floor(value)) fail();
    if (!d.allowed.empty()) {
        if (std::find(d.allowed.begin(), d.allowed.end(), value) == d.allowed.end()) fail();
        return;
    }
    if (value < d.min || value > d.max) fail();
}

double parseSettingValue(const SettingDescription& d, std::string_view text) {
    auto fail = [&] {
        throw std::invalid_argument("setting " + d.name + " = " + quoted(text) + ": expected " + describeRange(d));
    };
    if (d.type == SettingType::Flag) {
        if (text == "1" || text == "true" || text == "on") return 1;
        if (text == "0" || text == "false" || text == "off") return 0;
        fail();
    }
    double value = 0;
    if (d.type == SettingType::Integer) {
        // Integers are written as integers: "1.0" and "1e3" are rejected rather than guessed at.
        long long i = 0;
        auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), i);
        if (text.empty() || ec != std::errc() || end != text.data() + text.size()) fail();
        value = double(i);
    } else {
        auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (text.empty() || ec != std::errc() || end != text.data() + text.size()) fail();
    }
    try {
        checkSettingValue(d, value);
    } catch (const std::invalid_argument&) {
        fail();
    }
    return value;
}

std::string formatSettingValue(const SettingDescription& d, double value) {
    if (d.type == SettingType::Flag) return value != 0 ? "true" : "false";
    return number(value);
}

}  // namespace strata
