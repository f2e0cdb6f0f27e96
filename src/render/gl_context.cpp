#include "render/gl_context.hpp"

#include <GL/osmesa.h>

#include <cstdlib>
#include <cstring>

#include "core/error.hpp"

namespace dinam {

GlContext::GlContext(int width, int height)
    : width_(width), height_(height), pixels_(static_cast<std::size_t>(width) * height * 4) {
  // Mesa picks its Gallium driver from GALLIUM_DRIVER; anything but the CPU rasterisers (zink,
  // d3d12, a GPU driver) crashes OSMesa's context creation, so a stray value is not inherited.
  const char* driver = std::getenv("GALLIUM_DRIVER");
  if (driver != nullptr && std::strcmp(driver, "llvmpipe") != 0 &&
      std::strcmp(driver, "softpipe") != 0) {
    setenv("GALLIUM_DRIVER", "llvmpipe", 1);
  }
  const int attributes[] = {OSMESA_FORMAT,
                            OSMESA_RGBA,
                            OSMESA_DEPTH_BITS,
                            24,
                            OSMESA_STENCIL_BITS,
                            0,
                            OSMESA_PROFILE,
                            OSMESA_CORE_PROFILE,
                            OSMESA_CONTEXT_MAJOR_VERSION,
                            3,
                            OSMESA_CONTEXT_MINOR_VERSION,
                            3,
                            0};
  OSMesaContext context = OSMesaCreateContextAttribs(attributes, nullptr);
  if (context == nullptr) {
    throw RuntimeError(
        "cannot create an OSMesa OpenGL 3.3 core-profile context; is libosmesa6 (Mesa 20 or "
        "later) installed? Run scripts/install-deps.sh");
  }
  context_ = context;
  if (OSMesaMakeCurrent(context, pixels_.data(), GL_UNSIGNED_BYTE, width, height) == 0) {
    OSMesaDestroyContext(context);
    throw RuntimeError(fmt::format("cannot make the {}x{} OSMesa context current", width, height));
  }
}

GlContext::~GlContext() {
  OSMesaDestroyContext(static_cast<OSMesaContext>(context_));
}

}  // namespace dinam
