// The one settings path: descriptions, value parsing, `[id.]name=value` resolution and presets.
#include "oit/settings.hpp"
#include "oit/technique.hpp"
#include "oit/technique_settings.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <stdexcept>
#include <string>

using namespace strata;

namespace {

struct Example {
    int count = 3;
    double scale = 0.5;
    bool enabled = true;
    int bits = 32;
    static const SettingsSchema<Example>& schema() {
        static const SettingsSchema<Example> s{
            integerSetting(&Example::count, "count", 1, 64, SettingChange::Reallocate, "how many"),
            realSetting(&Example::scale, "scale", 0.0, 2.0, SettingChange::Nothing, "how much"),
            flagSetting(&Example::enabled, "enabled", SettingChange::Recompile, "whether"),
            precisionSetting(&Example::bits, "example targets"),
        };
        return s;
    }
};

SettingDescription describe(const std::string& name) {
    for (const auto& d : Example::schema().descriptions())
        if (d.name == name) return d;
    throw std::logic_error("no " + name);
}

// The error text of `f`, or "" when it does not throw std::invalid_argument.
template <class F>
std::string errorOf(F f) {
    try {
        f();
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "";
}

std::vector<SettingAssignment> cli(std::vector<std::string> texts) { return commandLineAssignments(texts); }

double valueOf(const SettingsById& s, const std::string& id, const std::string& name) {
    const auto& ds = findTechnique(id)->settings;
    for (std::size_t i = 0; i < ds.size(); ++i)
        if (ds[i].name == name) return s.at(id).at(i);
    throw std::logic_error(id + " has no " + name);
}

std::filesystem::path writeTemp(const std::string& name, const std::string& text) {
    auto path = std::filesystem::temp_directory_path() / ("strata-settings-test-" + name);
    std::ofstream(path) << text;
    return path;
}

}  // namespace

TEST_CASE("a schema takes its defaults from the struct and round-trips values exactly") {
    const auto& schema = Example::schema();
    auto ds = schema.descriptions();
    REQUIRE(ds.size() == 4);
    CHECK(ds[0].defaultValue == 3);
    CHECK(ds[1].defaultValue == 0.5);
    CHECK(ds[2].defaultValue == 1);
    CHECK(ds[3].defaultValue == 32);
    CHECK(ds[3].allowed == std::vector<double>{16, 32});
    Example e;
    e.count = 64;
    e.scale = 1.25;
    e.enabled = false;
    e.bits = 16;
    CHECK(schema.read(e) == SettingValues{64, 1.25, 0, 16});
    Example back = schema.write(schema.read(e));
    CHECK(back.count == 64);
    CHECK(back.scale == 1.25);
    CHECK_FALSE(back.enabled);
    CHECK(back.bits == 16);
}

TEST_CASE("integers are written as integers and stay in range") {
    const auto d = describe("count");
    CHECK(parseSettingValue(d, "1") == 1);
    CHECK(parseSettingValue(d, "64") == 64);
    for (const char* bad : {"0", "65", "-1", "1.5", "2.0", "1e1", "abc", "", " 3", "3 ", "0x10", "99999999999999999999"}) {
        CAPTURE(bad);
        CHECK(errorOf([&] { parseSettingValue(d, bad); }).find("setting count = ") == 0);
    }
    CHECK(errorOf([&] { parseSettingValue(d, "65"); }) == "setting count = '65': expected integer in [1, 64]");
}

TEST_CASE("reals are finite and in range; flags are 0/1, true/false or on/off") {
    const auto scale = describe("scale");
    CHECK(parseSettingValue(scale, "0.25") == 0.25);
    CHECK(parseSettingValue(scale, "2") == 2);
    for (const char* bad : {"nan", "inf", "-0.1", "2.0001", "1e400", "0.5x"}) {
        CAPTURE(bad);
        CHECK_FALSE(errorOf([&] { parseSettingValue(scale, bad); }).empty());
    }
    const auto flag = describe("enabled");
    for (const char* on : {"1", "true", "on"}) CHECK(parseSettingValue(flag, on) == 1);
    for (const char* off : {"0", "false", "off"}) CHECK(parseSettingValue(flag, off) == 0);
    for (const char* bad : {"2", "yes", "TRUE", ""}) {
        CAPTURE(bad);
        CHECK_FALSE(errorOf([&] { parseSettingValue(flag, bad); }).empty());
    }
}

TEST_CASE("a setting with allowed values takes only those") {
    const auto d = describe("precision");
    CHECK(parseSettingValue(d, "16") == 16);
    CHECK(parseSettingValue(d, "32") == 32);
    for (const char* bad : {"24", "8", "64", "17", "16.5"})
        CHECK(errorOf([&] { parseSettingValue(d, bad); }).find("expected 16 or 32") != std::string::npos);
    CHECK_THROWS_AS(checkSettingValue(d, 24), std::invalid_argument);
    CHECK_NOTHROW(checkSettingValue(d, 16));
}

TEST_CASE("long or binary values are quoted short and escaped in the error") {
    const auto d = describe("count");
    std::string message = errorOf([&] { parseSettingValue(d, std::string(5000, '7') + "\x01"); });
    CHECK(message.size() < 120);
    CHECK(message.find("...") != std::string::npos);
    CHECK(errorOf([&] { parseSettingValue(d, "a\nb"); }).find("'a\\x0ab'") != std::string::npos);
}

TEST_CASE("every registered technique describes its settings soundly, and its object agrees") {
    for (const auto& e : techniqueRegistry()) {
        CAPTURE(e.info.id);
        std::set<std::string> names;
        for (const auto& d : e.settings) {
            CAPTURE(d.name);
            CHECK(names.insert(d.name).second);
            CHECK_FALSE(d.help.empty());
            CHECK(d.name.find_first_of(".= ") == std::string::npos);
            CHECK_NOTHROW(checkSettingValue(d, d.defaultValue));
            CHECK(d.min <= d.max);
            CHECK(std::abs(d.max) <= 9007199254740992.0);
        }
        auto t = e.create();
        auto ds = t->settingDescriptions();
        REQUIRE(ds.size() == e.settings.size());
        SettingValues defaults;
        for (std::size_t i = 0; i < ds.size(); ++i) {
            CHECK(ds[i].name == e.settings[i].name);
            defaults.push_back(e.settings[i].defaultValue);
        }
        CHECK(t->settings() == defaults);
    }
}

TEST_CASE("resolveSettings: qualified, unqualified, order, and every rejection") {
    const std::vector<std::string> ids = {"abuffer", "kbuffer", "ll"};
    auto s = resolveSettings(ids, cli({"capacity=5", "ll.capacity=9", "kbuffer.tail=true", "precision=16"}));
    CHECK(valueOf(s, "kbuffer", "capacity") == 5);
    CHECK(valueOf(s, "ll", "capacity") == 9);  // later and qualified wins for ll only
    CHECK(valueOf(s, "kbuffer", "tail") == 1);
    CHECK(valueOf(s, "ll", "tail") == 0);
    CHECK(valueOf(s, "ll", "precision") == 16);
    CHECK(valueOf(s, "abuffer", "compute_resolve") == 0);  // defaults where nothing was said
    CHECK(s.size() == 3);

    CHECK(errorOf([&] { resolveSettings(ids, cli({"capacty=5"})); }) ==
          "--set capacty=5: no technique run has a setting 'capacty' (settings: capacity, compute_resolve, "
          "initial_nodes, max_block_mib, precision, tail)");
    CHECK(errorOf([&] { resolveSettings({"ll"}, cli({"capacty=5"})); }) ==
          "--set capacty=5: technique ll has no setting 'capacty' (has: capacity, tail, precision)");
    CHECK(errorOf([&] { resolveSettings(ids, cli({"ll.capacity=abc"})); }) ==
          "--set ll.capacity=abc: setting capacity = 'abc': expected integer in [1, 1024]");
    CHECK(errorOf([&] { resolveSettings(ids, cli({"f2b.max_passes=3"})); }) ==
          "--set f2b.max_passes=3: technique f2b is not among those run (abuffer, kbuffer, ll)");
    CHECK(errorOf([&] { resolveSettings(ids, cli({"nope.capacity=3"})); }) ==
          "--set nope.capacity=3: unknown technique 'nope'");
    CHECK(errorOf([&] { resolveSettings(ids, cli({"capacity"})); }).find("not of the form") != std::string::npos);
    CHECK(errorOf([&] { resolveSettings(ids, cli({"=3"})); }).find("not of the form") != std::string::npos);
    CHECK(errorOf([&] { resolveSettings({"nope"}, {}); }).find("unknown technique 'nope'") == 0);
    // An unqualified value must suit every technique that has the name.
    CHECK(errorOf([&] { resolveSettings(ids, cli({"capacity=100"})); }).find("expected integer in [1, 64]") !=
          std::string::npos);
}

TEST_CASE("applySettings changes one technique from its current values, all or none") {
    auto t = createTechnique("kbuffer");
    applySettings(*t, cli({"capacity=4"}));
    applySettings(*t, cli({"kbuffer.tail=on"}));
    CHECK(t->settings() == SettingValues{4, 1, 32});
    CHECK_THROWS_AS(applySettings(*t, cli({"capacity=5", "precision=20"})), std::invalid_argument);
    CHECK(t->settings() == SettingValues{4, 1, 32});
}

TEST_CASE("a JSON preset gives assignments in file order that name the file") {
    auto path = writeTemp("ok.json", R"({"capacity": 3, "ll.tail": true, "max_block_mib": 0.5, "precision": 16.0})");
    auto a = readSettingsPreset(path.string());
    REQUIRE(a.size() == 4);
    CHECK(a[0].text == "capacity=3");
    CHECK(a[1].text == "ll.tail=true");
    CHECK(a[2].text == "max_block_mib=0.5");
    CHECK(a[3].text == "precision=16");
    CHECK(a[0].origin == path.string());
    auto s = resolveSettings({"ll", "abuffer"}, a);
    CHECK(valueOf(s, "ll", "capacity") == 3);
    CHECK(valueOf(s, "abuffer", "max_block_mib") == 0.5);

    auto typo = writeTemp("typo.json", R"({"ll.capacty": 3})");
    CHECK(errorOf([&] { resolveSettings({"ll"}, readSettingsPreset(typo.string())); }).find(typo.string() + " ll.capacty=3: ") == 0);
    for (const char* text : {"[1, 2]", R"({"capacity": "3"})", R"({"capacity": null})", "{", R"({"capacity": 1e400})"}) {
        CAPTURE(text);
        auto bad = writeTemp("bad.json", text);
        CHECK(errorOf([&] { readSettingsPreset(bad.string()); }).find(bad.string() + ": ") == 0);
    }
    CHECK(errorOf([] { readSettingsPreset("/dev/zero"); }) == "/dev/zero: is a character device, not a regular file");
    CHECK(errorOf([] { readSettingsPreset("/nonexistent/preset.json"); }) == "/nonexistent/preset.json: no such file");
    for (const char* name : {"ok.json", "typo.json", "bad.json"})
        std::filesystem::remove(std::filesystem::temp_directory_path() / (std::string("strata-settings-test-") + name));
}
