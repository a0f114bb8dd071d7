// Headless EGL context creation (see context.h for the order). Every EGL call that epoxy would
// abort on when the driver lacks it is guarded by an extension check first.
#include "lexel/spatial/gl/context.h"

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <string_view>
#include <vector>

namespace lexel::spatial::gl {

std::string ContextInfo::Describe() const {
    return renderer + ", OpenGL " + version + " via " + platform;
}

namespace {

bool HasExtension(const char* list, std::string_view name) {
    if (list == nullptr) return false;
    std::string_view rest(list);
    while (!rest.empty()) {
        const std::size_t end = rest.find(' ');
        if (rest.substr(0, end) == name) return true;
        if (end == std::string_view::npos) break;
        rest.remove_prefix(end + 1);
    }
    return false;
}

std::string Lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
    return s;
}

std::string GlString(GLenum name) {
    const auto* s = reinterpret_cast<const char*>(glGetString(name));
    return s ? s : "";
}

// A display to try: its platform call and a description for messages.
struct Candidate {
    EGLenum platform;
    void* nativeDisplay;
    std::string description;
    int rank;  // 0 NVIDIA, 1 other hardware, 2 software, 3 surfaceless
};

std::vector<Candidate> Candidates() {
    std::vector<Candidate> out;
    const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    const bool platformDisplay = HasExtension(client, "EGL_EXT_platform_base");
    if (!platformDisplay) return out;
    if (HasExtension(client, "EGL_EXT_device_enumeration") &&
        HasExtension(client, "EGL_EXT_platform_device")) {
        EGLint count = 0;
        if (eglQueryDevicesEXT(0, nullptr, &count) && count > 0) {
            std::vector<EGLDeviceEXT> devices(static_cast<std::size_t>(count));
            eglQueryDevicesEXT(count, devices.data(), &count);
            const bool query = HasExtension(client, "EGL_EXT_device_query");
            for (EGLint i = 0; i < count; ++i) {
                const char* ext =
                    query ? eglQueryDeviceStringEXT(devices[i], EGL_EXTENSIONS) : nullptr;
                int rank = 1;
                std::string kind = "hardware";
                if (HasExtension(ext, "EGL_NV_device_cuda")) {
                    rank = 0;
                    kind = "EGL_NV_device_cuda";
                } else if (HasExtension(ext, "EGL_MESA_device_software")) {
                    rank = 2;
                    kind = "Mesa software";
                } else if (HasExtension(ext, "EGL_EXT_device_drm")) {
                    kind = "DRM";
                }
                out.push_back({EGL_PLATFORM_DEVICE_EXT, devices[i],
                               "EGL device " + std::to_string(i) + " (" + kind + ")", rank});
            }
        }
    }
    if (HasExtension(client, "EGL_MESA_platform_surfaceless"))
        out.push_back({EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, "EGL surfaceless", 3});
    std::stable_sort(out.begin(), out.end(),
                     [](const Candidate& a, const Candidate& b) { return a.rank < b.rank; });
    return out;
}

// The capabilities the passes use; empty when all are there, else what is missing.
std::string MissingCapability() {
    if (epoxy_gl_version() < 45)
        return "OpenGL " + std::to_string(epoxy_gl_version() / 10) + "." +
               std::to_string(epoxy_gl_version() % 10) + " (4.5 core needed)";
    GLint invocations = 0;
    glGetIntegerv(GL_MAX_COMPUTE_WORK_GROUP_INVOCATIONS, &invocations);
    if (invocations < 64) return "compute work groups of 64 invocations";
    GLint bits = 0;
    glGetQueryiv(GL_TIME_ELAPSED, GL_QUERY_COUNTER_BITS, &bits);
    if (bits < 30) return "GPU timer queries";
    // One framebuffer with every format the camera and shadow passes render into.
    GLuint textures[4], fbo = 0;
    glCreateTextures(GL_TEXTURE_2D, 4, textures);
    const GLenum formats[4] = {GL_R32I, GL_RGBA32F, GL_RGBA32F, GL_DEPTH_COMPONENT32F};
    for (int i = 0; i < 4; ++i) glTextureStorage2D(textures[i], 1, formats[i], 4, 4);
    glCreateFramebuffers(1, &fbo);
    for (int i = 0; i < 3; ++i)
        glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT0 + i, textures[i], 0);
    glNamedFramebufferTexture(fbo, GL_DEPTH_ATTACHMENT, textures[3], 0);
    const GLenum status = glCheckNamedFramebufferStatus(fbo, GL_FRAMEBUFFER);
    glDeleteFramebuffers(1, &fbo);
    glDeleteTextures(4, textures);
    if (status != GL_FRAMEBUFFER_COMPLETE)
        return "render targets R32I + RGBA32F + GL_DEPTH_COMPONENT32F";
    return "";
}

// A core context on `display`, current on this thread, or nullopt with the reason in *why.
std::optional<EGLContext> CreateOn(EGLDisplay display, std::string* why) {
    EGLint major = 0, minor = 0;
    if (!eglInitialize(display, &major, &minor)) {
        *why = "eglInitialize failed";
        return std::nullopt;
    }
    if (!eglBindAPI(EGL_OPENGL_API)) {
        *why = "no desktop OpenGL API";
        return std::nullopt;
    }
    EGLConfig config = EGL_NO_CONFIG_KHR;
    if (!HasExtension(eglQueryString(display, EGL_EXTENSIONS), "EGL_KHR_no_config_context")) {
        const EGLint attributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
        EGLint count = 0;
        if (!eglChooseConfig(display, attributes, &config, 1, &count) || count < 1) {
            *why = "no OpenGL config";
            return std::nullopt;
        }
    }
    for (const EGLint minorVersion : {6, 5}) {
        const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                     4,
                                     EGL_CONTEXT_MINOR_VERSION,
                                     minorVersion,
                                     EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                     EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                     EGL_NONE};
        const EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, attributes);
        if (context == EGL_NO_CONTEXT) continue;
        if (eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) return context;
        eglDestroyContext(display, context);
    }
    *why = "no OpenGL 4.5 core context";
    return std::nullopt;
}

}  // namespace

Context& Context::Shared() {
    // Created once; never destroyed (EGL and the driver tear themselves down at exit).
    static std::string failure;
    static Context* shared = []() -> Context* {
        const bool requireHardware = [] {
            const char* v = std::getenv("LEXEL_GL_REQUIRE_HARDWARE");
            return v != nullptr && std::strcmp(v, "1") == 0;
        }();
        const std::vector<Candidate> candidates = Candidates();
        if (candidates.empty()) {
            failure = "no EGL device or surfaceless platform (is libegl-mesa0 installed?)";
            return nullptr;
        }
        std::string tried;
        for (const Candidate& c : candidates) {
            const EGLDisplay display =
                eglGetPlatformDisplayEXT(c.platform, c.nativeDisplay, nullptr);
            std::string why = "no display";
            std::optional<EGLContext> context;
            if (display != EGL_NO_DISPLAY) context = CreateOn(display, &why);
            if (context) {
                why = MissingCapability();
                const std::string renderer = GlString(GL_RENDERER);
                const std::string lower = Lower(renderer);
                const bool software = lower.find("llvmpipe") != std::string::npos ||
                                      lower.find("softpipe") != std::string::npos ||
                                      lower.find("swrast") != std::string::npos;
                if (why.empty() && software && requireHardware)
                    why =
                        "software renderer " + renderer + " refused (LEXEL_GL_REQUIRE_HARDWARE=1)";
                if (why.empty()) {
                    auto* ctx = new Context();
                    ctx->display_ = display;
                    ctx->context_ = *context;
                    ctx->info_ = {renderer,
                                  GlString(GL_VENDOR),
                                  GlString(GL_VERSION),
                                  c.description,
                                  software,
                                  0};
                    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &ctx->info_.maxTextureSize);
                    eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
                    return ctx;
                }
                eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
                eglDestroyContext(display, *context);
            }
            tried += (tried.empty() ? "" : "; ") + c.description + ": " + why;
        }
        failure = tried;
        return nullptr;
    }();
    if (shared == nullptr) throw GlUnavailable("no OpenGL 4.5 context: " + failure);
    return *shared;
}

void Context::MakeCurrent() const {
    if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
        throw GlUnavailable("eglMakeCurrent failed (error " + std::to_string(eglGetError()) + ")");
}

void Context::Release() const {
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
}

CurrentContext::CurrentContext(const Context& context) : context_(context), lock_(context.mutex_) {
    // Re-entrant: only the outermost scope on this thread makes current and releases.
    thread_local int depth = 0;
    outermost_ = depth == 0;
    if (outermost_) context_.MakeCurrent();
    ++depth;
    depthCounter_ = &depth;
}

CurrentContext::~CurrentContext() {
    --*depthCounter_;
    if (outermost_) context_.Release();
}

}  // namespace lexel::spatial::gl
