// A headless OpenGL 4.5 core context through EGL, without a display or window: the GPU path of the
// 3D harness (report §2.4 ran Algorithm 1 on OpenGL; lexel renders only into framebuffer objects).
//
// Creation order: EGL devices (EGL_EXT_device_enumeration) ranked NVIDIA (EGL_NV_device_cuda)
// first, other hardware next, Mesa's software device (llvmpipe) last, each through
// eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT); then Mesa's surfaceless platform. The first
// display that gives a core 4.6 or 4.5 context with the capabilities the passes use (compute
// shaders, GL_DEPTH_COMPONENT32F, RGBA32F and R32I render targets, timer queries, clip control)
// wins. GL functions come from libepoxy, which needs no initialisation.
//
// One process-wide context serves every renderer (Context::Shared): EGL displays are per device,
// and terminating one would end every context on it. A context is current on one thread at a
// time; CurrentContext locks the context's mutex and makes it current on the calling thread, so
// any thread may use it, one after another.
//
// The environment variable LEXEL_GL_REQUIRE_HARDWARE=1 turns "only a software renderer was found"
// into GlUnavailable (for GPU runners, where falling back to llvmpipe silently would mislead).
#pragma once

#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>

namespace lexel::spatial::gl {

// No usable context: no EGL, no device, no 4.5 core context, or a capability missing. what() is
// one line: the reason and what was tried.
class GlUnavailable : public std::runtime_error {
  public:
    explicit GlUnavailable(const std::string& message) : std::runtime_error(message) {}
};

struct ContextInfo {
    std::string renderer;    // GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
    std::string vendor;      // GL_VENDOR
    std::string version;     // GL_VERSION
    std::string platform;    // how it was reached: "EGL device 0 (EGL_NV_device_cuda)", ...
    bool software = false;   // a CPU rasterizer (llvmpipe, softpipe, swrast)
    int maxTextureSize = 0;  // GL_MAX_TEXTURE_SIZE, texels per side
    // "<renderer>, OpenGL <version> via <platform>" on one line.
    std::string Describe() const;
};

class Context {
  public:
    // The process-wide context, created on the first call. Throws GlUnavailable (then and on every
    // later call, with the same reason) when none can be created.
    static Context& Shared();

    const ContextInfo& Info() const { return info_; }

    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;

  private:
    friend class CurrentContext;
    Context() = default;
    void MakeCurrent() const;
    void Release() const;

    void* display_ = nullptr;  // EGLDisplay
    void* context_ = nullptr;  // EGLContext
    ContextInfo info_;
    mutable std::recursive_mutex mutex_;
};

// The context locked and current on this thread for the lifetime of the object (re-entrant on one
// thread: nested scopes keep it current until the outermost ends).
class CurrentContext {
  public:
    explicit CurrentContext(const Context& context);
    ~CurrentContext();
    CurrentContext(const CurrentContext&) = delete;
    CurrentContext& operator=(const CurrentContext&) = delete;

  private:
    const Context& context_;
    std::unique_lock<std::recursive_mutex> lock_;
    bool outermost_ = false;
    int* depthCounter_ = nullptr;  // this thread's nesting depth
};

}  // namespace lexel::spatial::gl
