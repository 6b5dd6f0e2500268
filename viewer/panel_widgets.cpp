#include "panel_widgets.hpp"

#include "gl/debug.hpp"

namespace strata {

void helpTooltip(const std::string& text) {
    if (!text.empty() && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", text.c_str());
}

void drawErrorLines(const std::string& lastGlError, const std::string& lastError) {
    std::size_t errors = gl::errorCount();
    if (errors) ImGui::TextColored(kErrorColour, "GL errors: %zu", errors);
    else ImGui::Text("GL errors: 0");
    if (!lastGlError.empty()) ImGui::TextWrapped("last GL error: %s", lastGlError.c_str());
    if (!lastError.empty()) ImGui::TextColored(kErrorColour, "%s", lastError.c_str());
}

}  // namespace strata
