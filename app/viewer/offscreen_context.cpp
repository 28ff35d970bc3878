#include "offscreen_context.h"

#include <dlfcn.h>
#include <string>
#include <vector>
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include "util/error.h"
// glad before osmesa.h, which would otherwise pull in the system GL header.
#include "gl_loader.h"
#include <GL/osmesa.h>

namespace strata::viewer {
namespace {

class EglContext final : public OffscreenContext {
public:
    EglContext() {
        auto getPlatformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
            eglGetProcAddress("eglGetPlatformDisplayEXT"));
        if (!getPlatformDisplay) throw Error("EGL: no eglGetPlatformDisplayEXT");
        display_ = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (display_ == EGL_NO_DISPLAY || !eglInitialize(display_, nullptr, nullptr)) {
            throw Error("EGL: no surfaceless Mesa display");
        }
        if (!eglBindAPI(EGL_OPENGL_API)) fail("cannot bind the OpenGL API");
        const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 3,
                                     EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                     EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
        // EGL_KHR_no_config_context + EGL_KHR_surfaceless_context: no config, no surface.
        context_ = eglCreateContext(display_, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
        if (context_ == EGL_NO_CONTEXT) fail("cannot create an OpenGL 3.3 core context");
        if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) {
            fail("cannot make the context current");
        }
        try {
            loadGl(reinterpret_cast<GLADloadfunc>(eglGetProcAddress));
        } catch (...) {
            release();
            throw;
        }
    }
    ~EglContext() override { release(); }
    std::string_view backendName() const override { return "egl"; }

private:
    [[noreturn]] void fail(const std::string& what) {
        release();
        throw Error("EGL: " + what);
    }
    void release() {
        if (display_ == EGL_NO_DISPLAY) return;
        eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        if (context_ != EGL_NO_CONTEXT) eglDestroyContext(display_, context_);
        eglTerminate(display_);
        display_ = EGL_NO_DISPLAY;
    }

    EGLDisplay display_ = EGL_NO_DISPLAY;
    EGLContext context_ = EGL_NO_CONTEXT;
};

// OSMesa is opened when a context is asked for, not linked: it carries llvmpipe and LLVM, whose
// relocations cost about 70 ms at the start of every `strata` process (measured with an empty
// program linked against it), `render` included, which never draws.
class OsMesaLibrary {
public:
    // The soname of Mesa's OSMesa ABI.
    static constexpr const char* kSoname = "libOSMesa.so.8";

    OsMesaLibrary() {
        // RTLD_NODELETE: LLVM is not made to be unloaded.
        library_ = dlopen(kSoname, RTLD_NOW | RTLD_LOCAL | RTLD_NODELETE);
        if (!library_) throw Error(std::string("OSMesa: ") + dlerror());
        createContextAttribs = resolve<decltype(&OSMesaCreateContextAttribs)>("OSMesaCreateContextAttribs");
        makeCurrent = resolve<decltype(&OSMesaMakeCurrent)>("OSMesaMakeCurrent");
        destroyContext = resolve<decltype(&OSMesaDestroyContext)>("OSMesaDestroyContext");
        getProcAddress = resolve<GLADloadfunc>("OSMesaGetProcAddress");
    }
    ~OsMesaLibrary() { dlclose(library_); }
    OsMesaLibrary(const OsMesaLibrary&) = delete;
    OsMesaLibrary& operator=(const OsMesaLibrary&) = delete;

    decltype(&OSMesaCreateContextAttribs) createContextAttribs;
    decltype(&OSMesaMakeCurrent) makeCurrent;
    decltype(&OSMesaDestroyContext) destroyContext;
    GLADloadfunc getProcAddress;

private:
    template <typename Function>
    Function resolve(const char* name) {
        void* symbol = dlsym(library_, name);
        if (!symbol) {
            dlclose(library_);
            throw Error(std::string("OSMesa: no ") + name + " in " + kSoname);
        }
        return reinterpret_cast<Function>(symbol);
    }

    void* library_ = nullptr;
};

class OsMesaContext final : public OffscreenContext {
public:
    OsMesaContext() {
        const int attributes[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 0,
                                  OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                                  OSMESA_CONTEXT_MAJOR_VERSION, 3, OSMESA_CONTEXT_MINOR_VERSION, 3, 0};
        context_ = osMesa_.createContextAttribs(attributes, nullptr);
        if (!context_) throw Error("OSMesa: cannot create an OpenGL 3.3 core context");
        // OSMesa needs a colour buffer to make a context current; the viewer draws to its own
        // framebuffer object, so one pixel is enough.
        if (!osMesa_.makeCurrent(context_, pixel_.data(), GL_UNSIGNED_BYTE, 1, 1)) {
            osMesa_.destroyContext(context_);
            throw Error("OSMesa: cannot make the context current");
        }
        try {
            loadGl(osMesa_.getProcAddress);
        } catch (...) {
            osMesa_.destroyContext(context_);
            throw;
        }
    }
    ~OsMesaContext() override { osMesa_.destroyContext(context_); }
    std::string_view backendName() const override { return "osmesa"; }

private:
    OsMesaLibrary osMesa_;
    OSMesaContext context_ = nullptr;
    std::vector<unsigned char> pixel_ = std::vector<unsigned char>(4);
};

}  // namespace

OffscreenBackend parseOffscreenBackend(std::string_view name) {
    if (name.empty() || name == "auto") return OffscreenBackend::Auto;
    if (name == "egl") return OffscreenBackend::Egl;
    if (name == "osmesa") return OffscreenBackend::OsMesa;
    throw UsageError("--headless: unknown backend '" + std::string(name) + "' (use egl|osmesa)");
}

std::unique_ptr<OffscreenContext> OffscreenContext::create(OffscreenBackend backend) {
    switch (backend) {
        case OffscreenBackend::Egl: return std::make_unique<EglContext>();
        case OffscreenBackend::OsMesa: return std::make_unique<OsMesaContext>();
        case OffscreenBackend::Auto: break;
    }
    try {
        return std::make_unique<EglContext>();
    } catch (const Error& egl) {
        try {
            return std::make_unique<OsMesaContext>();
        } catch (const Error& osmesa) {
            throw Error(std::string("no offscreen OpenGL context: ") + egl.what() + "; " + osmesa.what());
        }
    }
}

}  // namespace strata::viewer
