#include "fragment_inspector.hpp"

#include "panel_widgets.hpp"

#include "image/image.hpp"
#include "render/depth_order.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace strata {
namespace {

const char* keptName(Kept k) { return k == Kept::Yes ? "yes" : k == Kept::No ? "no" : "?"; }

std::string objectName(const GpuScene& scene, int object) {
    if (object < 0 || std::size_t(object) >= scene.objects().size()) return "?";
    return scene.scene().materials[std::size_t(scene.objects()[std::size_t(object)].material)].name;
}

// The material's alpha factor for an object, and what the texture and COLOR_0 multiplied it by
// (the fragment's alpha over the factor): "factor x texel" for the window and the smoke test.
struct AlphaParts {
    float factor = 1.0f;
    float texel = 1.0f;  // texture x vertex alpha at the fragment; 1 for a factor-only material
};

AlphaParts alphaParts(const GpuScene& scene, const SurfaceFragment& f) {
    AlphaParts parts;
    if (f.object < 0 || std::size_t(f.object) >= scene.objects().size()) return parts;
    parts.factor = scene.scene().materials[std::size_t(scene.objects()[std::size_t(f.object)].material)].alpha;
    parts.texel = parts.factor > 0.0f ? f.alpha / parts.factor : 0.0f;
    return parts;
}

double distance(glm::vec3 a, glm::vec3 b) {
    glm::vec3 d = glm::abs(a - b);
    return double(std::max(d.r, std::max(d.g, d.b)));
}

// What the match says, in one line for the window and the smoke test.
std::string verdict(const Inspection& in) {
    const int n = int(in.reference.fragments.size());
    char text[200];
    if (in.firstMatch < 0)
        std::snprintf(text, sizeof text, "no depth-ordered prefix matches (closest: the nearest %d, off by %.4f)",
                      in.bestPrefix, in.bestDistance);
    else if (in.firstMatch == in.lastMatch && in.firstMatch == n)
        std::snprintf(text, sizeof text, "all %d kept", n);
    else if (in.firstMatch == in.lastMatch)
        std::snprintf(text, sizeof text, "the nearest %d of %d kept", in.firstMatch, n);
    else
        std::snprintf(text, sizeof text, "the nearest %d to %d of %d kept (prefixes alike in colour)", in.firstMatch,
                      in.lastMatch, n);
    return text;
}

}  // namespace

void inferKept(Inspection& in, double tolerance) {
    const auto& fragments = in.reference.fragments;
    const int n = int(fragments.size());
    in.prefixColours.clear();
    std::vector<SurfaceFragment> prefix;
    for (int k = 0; k <= n; ++k) {
        in.prefixColours.push_back(compositeOrdered(prefix, in.reference.opaqueColor));
        if (k < n) prefix.push_back(fragments[std::size_t(k)]);
    }
    in.firstMatch = in.lastMatch = -1;
    in.bestDistance = 1e30;
    for (int k = 0; k <= n; ++k) {
        const double d = distance(in.prefixColours[std::size_t(k)], in.techniqueColour);
        // Ties go to the longer prefix: with nothing to tell them apart, "kept" is the likelier.
        if (d <= in.bestDistance) {
            in.bestDistance = d;
            in.bestPrefix = k;
        }
        if (d <= tolerance) {
            if (in.firstMatch < 0) in.firstMatch = k;
            in.lastMatch = k;
        }
    }
    in.kept.assign(std::size_t(n), Kept::Undecided);
    if (in.firstMatch < 0) return;
    for (int i = 0; i < n; ++i)
        in.kept[std::size_t(i)] = i < in.firstMatch ? Kept::Yes : i >= in.lastMatch ? Kept::No : Kept::Undecided;
}

void FragmentInspector::inspect(const GpuScene& scene, const Camera& camera, glm::ivec2 size, glm::vec2 windowSize,
                                GLuint output, const std::string& techniqueId, const TechniqueStats& stats) {
    if (!active() || size.x <= 0 || size.y <= 0) return;
    if (scene_ != &scene || !raycast_) {
        raycast_ = std::make_unique<RaycastReference>(scene.scene(), scene.objects());
        scene_ = &scene;
    }
    // Window units to framebuffer pixels (they differ on HiDPI displays).
    const glm::vec2 scale = windowSize.x > 0.0f && windowSize.y > 0.0f ? glm::vec2(size) / windowSize : glm::vec2(1.0f);
    const int x = std::clamp(int(std::floor(float(selected_->x) * scale.x)), 0, size.x - 1);
    const int top = std::clamp(int(std::floor(float(selected_->y) * scale.y)), 0, size.y - 1);
    Inspection in;
    in.fromTop = {x, top};
    in.pixel = {x, size.y - 1 - top};
    in.techniqueId = techniqueId;
    in.frameStats = stats;
    in.reference = raycast_->samplePixel(camera, size.x, size.y, in.pixel.x, in.pixel.y);
    float texel[4] = {0, 0, 0, 0};
    glGetTextureSubImage(output, 0, in.pixel.x, in.pixel.y, 0, 1, 1, 1, GL_RGBA, GL_FLOAT, sizeof texel, texel);
    in.techniqueColour = {texel[0], texel[1], texel[2]};
    inferKept(in);
    last_ = std::move(in);
}

void FragmentInspector::drawWindow(const GpuScene& scene) {
    if (!active() || !last_) return;
    const Inspection& in = *last_;
    ImGui::SetNextWindowSize(ImVec2(560.0f, 320.0f), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowPos(ImVec2(ImGui::GetIO().DisplaySize.x - 570.0f, 8.0f), ImGuiCond_FirstUseEver);
    if (!ImGui::Begin("Fragments at a pixel", &open_)) {
        ImGui::End();
        return;
    }
    ImGui::Text("pixel %d, %d from the top-left (GL row %d)   %zu transparent fragments", in.fromTop.x, in.fromTop.y,
                in.pixel.y, in.reference.fragments.size());
    ImGui::Text("%s: %s", in.techniqueId.c_str(), verdict(in).c_str());
    ImGui::TextWrapped("\"kept\" is inferred: the technique's pixel (%.3f %.3f %.3f) against the reference composite "
                       "of the nearest k fragments for every k, within 2/255; no technique reports its fragments per "
                       "pixel. Reference pixel %.3f %.3f %.3f.",
                       in.techniqueColour.r, in.techniqueColour.g, in.techniqueColour.b, in.reference.color.r,
                       in.reference.color.g, in.reference.color.b);
    ImGui::Text("whole frame: captured %llu dropped %llu%s", static_cast<unsigned long long>(in.frameStats.fragmentsCaptured),
                static_cast<unsigned long long>(in.frameStats.fragmentsDropped),
                in.frameStats.overflowed ? "  OVERFLOWED" : "");
    if (ImGui::BeginTable("fragments", 8, ImGuiTableFlags_BordersInnerH | ImGuiTableFlags_SizingFixedFit |
                                              ImGuiTableFlags_ScrollY)) {
        for (const char* h : {"#", "depth", "object", "primitive", "colour", "alpha", "layer", "kept"})
            ImGui::TableSetupColumn(h);
        ImGui::TableHeadersRow();
        const double tol = tieToleranceFromUlps(scene.scene().depthTieUlps);
        for (std::size_t i = 0; i < in.reference.fragments.size(); ++i) {
            const SurfaceFragment& f = in.reference.fragments[i];
            const bool tied = i > 0 && sameDepthLayer(in.reference.fragments[i - 1].depth, f.depth, tol);
            ImGui::TableNextRow();
            ImGui::PushID(int(i));  // the swatches share a label
            ImGui::TableNextColumn();
            ImGui::Text("%zu", i);
            ImGui::TableNextColumn();
            ImGui::Text("%.6f", f.depth);
            ImGui::TableNextColumn();
            ImGui::Text("%d %s", f.object, objectName(scene, f.object).c_str());
            ImGui::TableNextColumn();
            ImGui::Text("%d", f.primitive);
            ImGui::TableNextColumn();
            const ImVec4 swatch(linearToSrgb(f.color.r), linearToSrgb(f.color.g), linearToSrgb(f.color.b), 1.0f);
            ImGui::ColorButton("##c", swatch, ImGuiColorEditFlags_NoTooltip, ImVec2(12.0f, 12.0f));
            ImGui::SameLine();
            ImGui::Text("%.2f %.2f %.2f", f.color.r, f.color.g, f.color.b);
            ImGui::TableNextColumn();
            if (f.coloredFilter) {
                ImGui::Text("%.3f, passes %.2f %.2f %.2f", f.alpha, f.transmittance.r, f.transmittance.g,
                            f.transmittance.b);
                helpTooltip("transmissive glass: what passes behind it per channel (the rgb techniques composite "
                            "that); alpha is its scalar form, 1 - mean, which the others composite");
            } else {
                const AlphaParts parts = alphaParts(scene, f);
                ImGui::Text("%.3f = %.3f x %.3f", f.alpha, parts.factor, parts.texel);
                helpTooltip("the fragment's alpha = the material's alpha factor x the texture's (and COLOR_0's) alpha here");
            }
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(tied ? "tied" : "");
            helpTooltip(tied ? "same depth layer as the fragment above (the tie rule): coplanar" : "");
            ImGui::TableNextColumn();
            const Kept k = in.kept[i];
            ImGui::TextColored(k == Kept::Yes ? ImVec4(0.5f, 0.9f, 0.5f, 1.0f)
                               : k == Kept::No ? kErrorColour : ImVec4(0.8f, 0.8f, 0.5f, 1.0f),
                               "%s", keptName(k));
            ImGui::PopID();
        }
        ImGui::EndTable();
    }
    if (in.reference.hasOpaque)
        ImGui::Text("behind: opaque object %d %s at depth %.6f", in.reference.opaqueObject,
                    objectName(scene, in.reference.opaqueObject).c_str(), in.reference.opaqueDepth);
    else
        ImGui::TextUnformatted("behind: the background");
    ImGui::End();
}

void FragmentInspector::printFigures(const GpuScene& scene) const {
    if (!last_) return;
    const Inspection& in = *last_;
    std::printf("inspect: pixel=%d,%d gl_row=%d fragments=%zu technique=%s match_first=%d match_last=%d "
                "best_distance=%.6f verdict=\"%s\"\n",
                in.fromTop.x, in.fromTop.y, in.pixel.y, in.reference.fragments.size(), in.techniqueId.c_str(),
                in.firstMatch, in.lastMatch, in.bestDistance, verdict(in).c_str());
    for (std::size_t i = 0; i < in.reference.fragments.size(); ++i) {
        const SurfaceFragment& f = in.reference.fragments[i];
        const AlphaParts parts = alphaParts(scene, f);
        const glm::vec3 passes = f.passes();
        std::printf("fragment: %zu depth=%.6f object=%d (%s) primitive=%d rgb=%.4f,%.4f,%.4f alpha=%.4f "
                    "alpha_factor=%.4f texel_alpha=%.4f passes=%.4f,%.4f,%.4f kept=%s\n",
                    i, f.depth, f.object, objectName(scene, f.object).c_str(), f.primitive, f.color.r, f.color.g,
                    f.color.b, f.alpha, parts.factor, parts.texel, passes.r, passes.g, passes.b, keptName(in.kept[i]));
    }
}

std::optional<glm::vec2> ClickDetector::update(glm::vec2 cursor, bool leftDown, bool panelWantsMouse) {
    constexpr float kSlop = 3.0f;  // pixels the cursor may move during a click
    if (leftDown && !down_) {
        down_ = true;
        valid_ = !panelWantsMouse;
        pressedAt_ = cursor;
    } else if (leftDown && glm::length(cursor - pressedAt_) > kSlop) {
        valid_ = false;
    } else if (!leftDown && down_) {
        down_ = false;
        if (valid_ && glm::length(cursor - pressedAt_) <= kSlop) return cursor;
    }
    return std::nullopt;
}

}  // namespace strata
