#include "glfw_window.h"

#include <utility>
// glad first; GLFW must not include the system GL header.
#include "gl_loader.h"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>

#include "util/error.h"

namespace strata::viewer {

GlfwWindow::GlfwWindow(int width, int height, const std::string& title) {
    if (!glfwInit()) throw Error("view: cannot open a window (no display?); try --headless");
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (!window_) {
        glfwTerminate();
        throw Error("view: cannot create an OpenGL 3.3 core window; try --headless");
    }
    glfwMakeContextCurrent(window_);
    // The UI frame rate is capped by the run loop, not by vsync: Xvfb has none.
    glfwSwapInterval(0);
    glfwSetWindowUserPointer(window_, this);
    glfwSetDropCallback(window_, &GlfwWindow::onDrop);
    try {
        loadGl(reinterpret_cast<GLADloadfunc>(glfwGetProcAddress));
    } catch (...) {
        glfwDestroyWindow(window_);
        glfwTerminate();
        throw;
    }
}

GlfwWindow::~GlfwWindow() {
    shutdownImGui();
    glfwDestroyWindow(window_);
    glfwTerminate();
}

void GlfwWindow::initImGui() {
    ImGui_ImplGlfw_InitForOpenGL(window_, true);
    imguiInitialised_ = true;
}

void GlfwWindow::shutdownImGui() {
    // The backend needs its ImGui context; an early exit may already have destroyed it.
    if (imguiInitialised_ && ImGui::GetCurrentContext()) ImGui_ImplGlfw_Shutdown();
    imguiInitialised_ = false;
}

void GlfwWindow::beginFrame() {
    glfwPollEvents();
    ImGui_ImplGlfw_NewFrame();
}

void GlfwWindow::waitForEvent() { glfwWaitEvents(); }

void GlfwWindow::waitForEvent(double seconds) {
    if (seconds > 0.0) glfwWaitEventsTimeout(seconds);
}

void GlfwWindow::swapBuffers() { glfwSwapBuffers(window_); }

bool GlfwWindow::shouldClose() const { return glfwWindowShouldClose(window_); }

void GlfwWindow::framebufferSize(int& width, int& height) const {
    glfwGetFramebufferSize(window_, &width, &height);
}

std::vector<std::string> GlfwWindow::takeDroppedPaths() { return std::exchange(dropped_, {}); }

void GlfwWindow::onDrop(GLFWwindow* window, int count, const char** paths) {
    auto* self = static_cast<GlfwWindow*>(glfwGetWindowUserPointer(window));
    for (int i = 0; i < count; ++i) self->dropped_.emplace_back(paths[i]);
}

}  // namespace strata::viewer
