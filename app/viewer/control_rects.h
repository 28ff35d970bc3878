#pragma once
// The screen rectangles of named ImGui controls as last drawn (the panel's and its file
// dialog's), so that scripted input (the tests) can click them.
#include <map>
#include <string>
#include <imgui.h>

namespace strata::viewer {

struct ControlRect {
    ImVec2 min, max;
    ImVec2 centre() const { return ImVec2(0.5f * (min.x + max.x), 0.5f * (min.y + max.y)); }
};

class ControlRects {
public:
    // The item just drawn, under `name`. `labelled`: the item has a label to the right of its
    // frame, which is left out.
    void remember(const std::string& name, bool labelled = true) {
        ControlRect rect{ImGui::GetItemRectMin(), ImGui::GetItemRectMax()};
        if (labelled) rect.max.x = rect.min.x + ImGui::CalcItemWidth();
        rects_[name] = rect;
    }
    const std::map<std::string, ControlRect>& all() const { return rects_; }

private:
    std::map<std::string, ControlRect> rects_;
};

}  // namespace strata::viewer
