#pragma once
// An ImGui context for tests that run frames without a renderer (no OpenGL): its default font is
// built, which NewFrame needs and by which CalcTextSize measures as the panel does.
#include <imgui.h>

namespace strata::test {

struct HeadlessImGui {
    explicit HeadlessImGui(ImVec2 displaySize) {
        ImGui::CreateContext();
        ImGuiIO& io = ImGui::GetIO();
        io.IniFilename = nullptr;
        io.DisplaySize = displaySize;
        io.DeltaTime = 1.0f / 60.0f;
        unsigned char* pixels = nullptr;
        int width = 0, height = 0;
        io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);
    }
    ~HeadlessImGui() { ImGui::DestroyContext(); }
    HeadlessImGui(const HeadlessImGui&) = delete;
    HeadlessImGui& operator=(const HeadlessImGui&) = delete;
};

}  // namespace strata::test
