#include "oit/technique_settings.hpp"

#include "io/bounded_read.hpp"
#include "io/printable.hpp"
#include "oit/technique.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <stdexcept>

namespace strata {
namespace {

std::string joinNames(const std::vector<SettingDescription>& descriptions) {
    std::string out;
    for (const auto& d : descriptions) out += (out.empty() ? "" : ", ") + d.name;
    return out.empty() ? "none" : out;
}

int findSetting(const std::vector<SettingDescription>& descriptions, const std::string& name) {
    for (std::size_t i = 0; i < descriptions.size(); ++i)
        if (descriptions[i].name == name) return int(i);
    return -1;
}

std::string joinIds(const std::vector<std::string>& ids) {
    std::string out;
    for (const auto& id : ids) out += (out.empty() ? "" : ", ") + id;
    return out;
}

// Applies the assignments to `values` (which holds an entry for each of `ids`).
void assign(const std::vector<std::string>& ids, SettingsById& values, const std::vector<SettingAssignment>& assignments) {
    std::map<std::string, std::vector<SettingDescription>> descriptions;
    for (const auto& id : ids) {
        const TechniqueEntry* entry = findTechnique(id);
        if (!entry) createTechnique(id);  // throws the list of known ids
        descriptions[id] = entry->settings;
    }
    for (const auto& a : assignments) {
        const std::string where = a.origin + " " + a.text + ": ";
        try {
            auto eq = a.text.find('=');
            if (eq == std::string::npos || eq == 0) throw std::invalid_argument("not of the form [technique.]name=value");
            std::string key = a.text.substr(0, eq), text = a.text.substr(eq + 1);
            auto dot = key.find('.');
            if (dot != std::string::npos) {
                std::string id = key.substr(0, dot), name = key.substr(dot + 1);
                if (!findTechnique(id)) throw std::invalid_argument("unknown technique '" + id + "'");
                if (!descriptions.count(id))
                    throw std::invalid_argument("technique " + id + " is not among those run (" + joinIds(ids) + ")");
                const auto& ds = descriptions[id];
                int i = findSetting(ds, name);
                if (i < 0)
                    throw std::invalid_argument("technique " + id + " has no setting '" + name + "' (has: " + joinNames(ds) + ")");
                values[id][i] = parseSettingValue(ds[i], text);
                continue;
            }
            bool matched = false;
            for (const auto& id : ids) {
                const auto& ds = descriptions[id];
                int i = findSetting(ds, key);
                if (i < 0) continue;
                values[id][i] = parseSettingValue(ds[i], text);
                matched = true;
            }
            if (!matched && ids.size() == 1)
                throw std::invalid_argument("technique " + ids[0] + " has no setting '" + key + "' (has: " +
                                            joinNames(descriptions[ids[0]]) + ")");
            if (!matched) {
                std::vector<std::string> names;
                for (const auto& [id, ds] : descriptions)
                    for (const auto& d : ds)
                        if (std::find(names.begin(), names.end(), d.name) == names.end()) names.push_back(d.name);
                std::sort(names.begin(), names.end());
                throw std::invalid_argument("no technique run has a setting '" + key + "' (settings: " +
                                            (names.empty() ? "none" : joinIds(names)) + ")");
            }
        } catch (const std::invalid_argument& e) {
            throw std::invalid_argument(where + e.what());
        }
    }
}

}  // namespace

SettingsById resolveSettings(const std::vector<std::string>& ids, const std::vector<SettingAssignment>& assignments) {
    SettingsById values;
    for (const auto& id : ids) {
        const TechniqueEntry* entry = findTechnique(id);
        if (!entry) createTechnique(id);  // throws the list of known ids
        auto& v = values[id];
        for (const auto& d : entry->settings) v.push_back(d.defaultValue);
    }
    assign(ids, values, assignments);
    return values;
}

void applySettings(Technique& technique, const std::vector<SettingAssignment>& assignments) {
    const std::string& id = technique.info().id;
    SettingsById values{{id, technique.settings()}};
    assign({id}, values, assignments);
    technique.setSettings(values[id]);
}

std::vector<SettingAssignment> commandLineAssignments(const std::vector<std::string>& texts) {
    std::vector<SettingAssignment> out;
    for (const auto& t : texts) out.push_back({t, "--set"});
    return out;
}

std::vector<SettingAssignment> readSettingsPreset(const std::string& path) {
    auto fail = [&](const std::string& why) { throw std::invalid_argument(printable(path, 120) + ": " + why); };
    // A preset is a few lines; the limit keeps /dev/zero or a mistaken model file from being read whole.
    std::string text;
    try {
        text = readBoundedFile(path, kSettingsPresetLimit);
    } catch (const ReadError& e) {
        throw std::invalid_argument(e.what());
    }
    nlohmann::ordered_json doc;
    try {
        doc = nlohmann::ordered_json::parse(text);
    } catch (const nlohmann::json::exception& e) {
        std::string what = e.what();
        auto bracket = what.find("] ");
        fail(printable(bracket == std::string::npos ? what : what.substr(bracket + 2), 160));
    }
    if (!doc.is_object()) fail("expected a JSON object of \"[technique.]name\": value");
    std::vector<SettingAssignment> out;
    for (const auto& [key, value] : doc.items()) {
        std::string text;
        if (value.is_boolean()) text = value.get<bool>() ? "true" : "false";
        else if (value.is_number_integer()) text = std::to_string(value.get<long long>());
        else if (value.is_number()) {
            char number[40];
            std::snprintf(number, sizeof number, "%.17g", value.get<double>());
            text = number;
        } else fail("\"" + printable(key, 40) + "\" is not a number or a boolean");
        out.push_back({key + "=" + text, path});
    }
    return out;
}

std::unique_ptr<Technique> createConfiguredTechnique(const std::string& id, const SettingsById& settings) {
    auto technique = createTechnique(id);
    auto it = settings.find(id);
    if (it != settings.end()) technique->setSettings(it->second);
    return technique;
}

std::string formatSettings(const std::vector<SettingDescription>& descriptions, const SettingValues& values) {
    std::string out;
    for (std::size_t i = 0; i < descriptions.size() && i < values.size(); ++i)
        out += (i ? " " : "") + descriptions[i].name + "=" + formatSettingValue(descriptions[i], values[i]);
    return out;
}

}  // namespace strata
