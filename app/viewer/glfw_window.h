#pragma once
// The windowed context: a GLFW window with an OpenGL 3.3 core context, Dear ImGui's GLFW platform
// backend, and the drop callback that backend does not install (dropped scene files open scenes).
#include <string>
#include <vector>

struct GLFWwindow;

namespace strata::viewer {

class GlfwWindow {
public:
    // Throws strata::Error when GLFW cannot start (no display: use --headless) or the context
    // cannot be made. Loads OpenGL through gl_loader.h.
    GlfwWindow(int width, int height, const std::string& title);
    ~GlfwWindow();
    GlfwWindow(const GlfwWindow&) = delete;
    GlfwWindow& operator=(const GlfwWindow&) = delete;

    // After ImGui::CreateContext: installs the ImGui GLFW backend.
    void initImGui();
    void shutdownImGui();
    // Polls events and starts the ImGui platform frame.
    void beginFrame();
    // Blocks until the window has an event (input, resize, expose, a dropped file): how the
    // viewer rests without using CPU once rendering has reached its target.
    void waitForEvent();
    // The same, for at most `seconds`: how it paces its frames while the render goes on and
    // nobody touches anything, yet answers input at once.
    void waitForEvent(double seconds);
    void swapBuffers();
    bool shouldClose() const;
    void framebufferSize(int& width, int& height) const;
    // Paths dropped on the window since the last call.
    std::vector<std::string> takeDroppedPaths();

private:
    static void onDrop(GLFWwindow* window, int count, const char** paths);

    GLFWwindow* window_ = nullptr;
    bool imguiInitialised_ = false;
    std::vector<std::string> dropped_;
};

}  // namespace strata::viewer
