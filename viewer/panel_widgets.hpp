#pragma once
// ImGui pieces both panels (viewer/panel.hpp, viewer/immersive_panel.hpp) draw the same way.
#include <imgui.h>

#include <string>

namespace strata {

inline const ImVec4 kErrorColour{1.0f, 0.4f, 0.3f, 1.0f};

// The tooltip of the item just drawn, while the mouse is over it (nothing for empty text).
void helpTooltip(const std::string& text);

// The count of GL errors this process has seen, the last one (empty: none) and the last render
// or shader error (empty: none).
void drawErrorLines(const std::string& lastGlError, const std::string& lastError);

}  // namespace strata
