#include "scene/gltf_ignored.hpp"

#include "io/printable.hpp"

#include <algorithm>
#include <charconv>
#include <cctype>
#include <map>
#include <set>

namespace strata::detail {

void IgnoredLog::note(const std::string& kind, const std::string& message, const std::string& place) {
    for (Entry& e : entries_)
        if (e.kind == kind) {
            ++e.more;
            return;
        }
    entries_.push_back({kind, message, place, 0});
}

std::vector<std::string> IgnoredLog::lines(const std::string& file) const {
    std::vector<std::string> out;
    for (const Entry& e : entries_) {
        std::string line = file + ": " + e.message;
        if (!e.place.empty())
            line += " (" + e.place + (e.more ? ", and " + std::to_string(e.more) + " more" : "") + ")";
        out.push_back(line);
    }
    return out;
}

namespace {

// The glTF 2.0 attribute semantics with an index: SET_n, n decimal without leading zeros.
const char* const kIndexedSets[] = {"TEXCOORD", "COLOR", "JOINTS", "WEIGHTS"};

// Splits "TEXCOORD_12" into ("TEXCOORD", 12); false when the name is not SET_n for a known set.
bool indexedSemantic(const std::string& name, std::string& set, int& index) {
    for (const char* s : kIndexedSets) {
        std::string prefix = std::string(s) + "_";
        if (name.rfind(prefix, 0) != 0) continue;
        std::string digits = name.substr(prefix.size());
        if (digits.empty() || digits.size() > 6 || (digits.size() > 1 && digits[0] == '0') ||
            !std::all_of(digits.begin(), digits.end(), [](char c) { return std::isdigit((unsigned char)c); }))
            return false;
        set = s;
        std::from_chars(digits.data(), digits.data() + digits.size(), index);  // at most 6 digits: fits
        return true;
    }
    return false;
}

}  // namespace

// KHR_materials_volume gives tau and albedo, KHR_mesh_quantization's integer attributes are
// decoded like any accessor, KHR_texture_transform places a texture, KHR_materials_emissive_strength
// scales emission, KHR_materials_unlit drops the light, KHR_lights_punctual's lights replace the
// default rig, KHR_materials_transmission and _ior make a coloured filter (without refraction).
bool implementedExtension(const std::string& extension) {
    return extension == "KHR_materials_volume" || extension == "KHR_mesh_quantization" ||
           extension == "KHR_texture_transform" || extension == "KHR_materials_emissive_strength" ||
           extension == "KHR_materials_unlit" || extension == "KHR_lights_punctual" ||
           extension == "KHR_materials_transmission" || extension == "KHR_materials_ior";
}

void noteIgnoredAttributes(const tinygltf::Primitive& p, const std::string& place, IgnoredLog& log) {
    std::map<std::string, std::set<int>> sets;
    for (const auto& [name, accessor] : p.attributes) {
        (void)accessor;
        std::string set;
        int index = 0;
        if (indexedSemantic(name, set, index)) {
            sets[set].insert(index);
        } else if (name != "POSITION" && name != "NORMAL" && name != "TANGENT" && name.rfind('_', 0) != 0) {
            // Application-specific semantics start with an underscore; anything else is not glTF.
            log.note("unknown attribute", "unknown attribute " + name + " ignored", place);
        }
    }
    std::set<std::string> gapped;
    for (const auto& [set, indices] : sets) {
        // glTF requires SET_0 .. SET_n without gaps (validator: MESH_PRIMITIVE_INDEXED_SEMANTIC_CONTINUITY).
        int expected = 0;
        for (int index : indices) {
            if (index != expected) {
                gapped.insert(set);
                log.note("gap " + set, set + "_" + std::to_string(index) + " without " + set + "_" +
                                           std::to_string(expected) + ": attribute set is not contiguous, ignored",
                         place);
                break;
            }
            ++expected;
        }
    }
    if (sets.count("COLOR") && !gapped.count("COLOR") && *sets["COLOR"].rbegin() > 0)
        log.note("colour sets", "COLOR_1 and above ignored: only COLOR_0 is read", place);
    if (sets.count("TEXCOORD") && !gapped.count("TEXCOORD") && *sets["TEXCOORD"].rbegin() > 1)
        log.note("texcoord sets", "TEXCOORD_2 and above ignored: only TEXCOORD_0 and TEXCOORD_1 are read", place);
    if (!p.targets.empty())
        log.note("morph targets", "morph targets ignored: the base geometry is drawn", place);
}

void noteIgnoredFeatures(const tinygltf::Model& model, IgnoredLog& log) {
    // extensionsRequired should be listed in extensionsUsed too; a file that forgets is still heard.
    std::vector<std::string> ignored;
    for (const auto* list : {&model.extensionsUsed, &model.extensionsRequired})
        for (const std::string& e : *list)
            if (!implementedExtension(e) && std::find(ignored.begin(), ignored.end(), e) == ignored.end()) ignored.push_back(e);
    if (!ignored.empty()) {
        std::string names;
        for (const std::string& e : ignored) names += (names.empty() ? "" : ", ") + e;
        log.note("extensions", "extensions ignored: " + names);
    }
    if (!model.skins.empty())
        log.note("skins", "skins ignored: skinned meshes are drawn in their bind pose");
    if (!model.animations.empty())
        log.note("animations", "animations ignored: the scene is drawn at rest");
}

std::string unimplementedRequiredExtension(const tinygltf::Model& model) {
    for (const std::string& e : model.extensionsRequired)
        if (!implementedExtension(e)) return e;
    return {};
}

std::string requiredExtensionProblem(const std::string& name) {
    return "requires extension " + printable(name, 60) + ", which Strata does not implement";
}

}  // namespace strata::detail
