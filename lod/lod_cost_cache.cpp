#include "lod/lod_cost_cache.hpp"

#include "io/atomic_file.hpp"

#include <epoxy/gl.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <utility>
#include <vector>

namespace strata::lod {
namespace {

// Every coefficient with its JSON name, so that load and store cannot disagree.
std::vector<std::pair<const char*, double LodCostModel::*>> coefficients() {
    return {{"geometry_fixed_ms", &LodCostModel::geometryFixedMs},
            {"geometry_ms_per_megatriangle", &LodCostModel::geometryMsPerMegatriangle},
            {"geometry_ms_per_megapixel", &LodCostModel::geometryMsPerMegapixel},
            {"impostor_fixed_ms", &LodCostModel::impostorFixedMs},
            {"impostor_instance_ms", &LodCostModel::impostorInstanceMs},
            {"impostor_ms_per_kiloquad", &LodCostModel::impostorMsPerKiloquad},
            {"impostor_ms_per_kiloside_px", &LodCostModel::impostorMsPerKilosidePx},
            {"impostor_ms_per_megapixel", &LodCostModel::impostorMsPerMegapixel}};
}

std::string glString(GLenum name) {
    const auto* s = reinterpret_cast<const char*>(glGetString(name));
    return s ? s : "";
}

}  // namespace

std::string currentDeviceKey() { return glString(GL_RENDERER) + " | " + glString(GL_VERSION); }

std::optional<LodCalibration> loadCostModel(const std::filesystem::path& file, const std::string& deviceKey) {
    std::ifstream in(file);
    if (!in) return std::nullopt;
    const nlohmann::json j = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
    if (!j.is_object() || j.value("version", 0) != kCostModelVersion || j.value("device", std::string()) != deviceKey)
        return std::nullopt;
    const auto model = j.find("model");
    if (model == j.end() || !model->is_object()) return std::nullopt;
    LodCalibration c;
    for (const auto& [name, member] : coefficients()) {
        const auto value = model->find(name);
        if (value == model->end() || !value->is_number()) return std::nullopt;
        const double v = value->get<double>();
        if (!std::isfinite(v) || v < 0.0) return std::nullopt;
        c.model.*member = v;
    }
    c.device = deviceKey.substr(0, deviceKey.find(" | "));
    c.wallMs = 0.0;
    return c;
}

bool storeCostModel(const std::filesystem::path& file, const std::string& deviceKey, const LodCalibration& calibration) {
    nlohmann::json model = nlohmann::json::object();
    for (const auto& [name, member] : coefficients()) model[name] = calibration.model.*member;
    const nlohmann::json j = {{"version", kCostModelVersion},
                              {"device", deviceKey},
                              {"calibration_ms", calibration.wallMs},
                              {"model", model}};
    try {
        std::filesystem::create_directories(file.parent_path());
        writeTextFile(file, j.dump(2) + "\n");
        return true;
    } catch (const std::exception&) {
        return false;
    }
}

}  // namespace strata::lod
