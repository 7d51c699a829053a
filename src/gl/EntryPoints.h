#pragma once
// The one header through which the project reaches OpenGL. Include it instead of <GL/glew.h>.
//
// Why this exists: the renderer must run both in a GLFW window (GLX, any driver) and in an
// OSMesa context (headless llvmpipe). The two are different GL implementations living in one
// process, so no entry point may be bound at link time; each must be looked up through the
// context that is current. GLEW already does that for everything past GL 1.1, through
// glXGetProcAddressARB; EntryPoints.cpp routes that lookup to the current context's loader.
// GLEW declares the GL 1.0/1.1 functions as plain symbols instead, which would bind to one
// implementation for the whole process; the macros below send the few the project uses
// through pointers loaded the same way.
#include <GL/glew.h>

namespace gl {

// A context's entry-point lookup: glfwGetProcAddress, OSMesaGetProcAddress, ...
using ProcAddressLoader = void* (*)(const char* name);

// Loads every entry point (GLEW's and the core ones below) for the context that is current
// now, through `loader`. Call after making a context current; throws on failure.
void loadEntryPoints(ProcAddressLoader loader, bool contextHasGlx);

// GL 1.0/1.1 functions, resolved per context (GLEW leaves these to the linker).
struct CoreEntryPoints {
    decltype(&::glBindTexture) bindTexture = nullptr;
    decltype(&::glClear) clear = nullptr;
    decltype(&::glClearColor) clearColor = nullptr;
    decltype(&::glDeleteTextures) deleteTextures = nullptr;
    decltype(&::glDisable) disable = nullptr;
    decltype(&::glDrawArrays) drawArrays = nullptr;
    decltype(&::glDrawBuffer) drawBuffer = nullptr;
    decltype(&::glEnable) enable = nullptr;
    decltype(&::glFinish) finish = nullptr;
    decltype(&::glFlush) flush = nullptr;
    decltype(&::glGenTextures) genTextures = nullptr;
    decltype(&::glGetError) getError = nullptr;
    decltype(&::glGetFloatv) getFloatv = nullptr;
    decltype(&::glGetIntegerv) getIntegerv = nullptr;
    decltype(&::glGetString) getString = nullptr;
    decltype(&::glPixelStorei) pixelStorei = nullptr;
    decltype(&::glReadBuffer) readBuffer = nullptr;
    decltype(&::glReadPixels) readPixels = nullptr;
    decltype(&::glScissor) scissor = nullptr;
    decltype(&::glTexImage2D) texImage2D = nullptr;
    decltype(&::glTexParameteri) texParameteri = nullptr;
    decltype(&::glTexSubImage2D) texSubImage2D = nullptr;
    decltype(&::glViewport) viewport = nullptr;
};

// Process-wide like GLEW's own pointers: GL has one current context per thread, and the
// renderer uses GL from one thread.
extern CoreEntryPoints core;

}  // namespace gl

#define glBindTexture gl::core.bindTexture
#define glClear gl::core.clear
#define glClearColor gl::core.clearColor
#define glDeleteTextures gl::core.deleteTextures
#define glDisable gl::core.disable
#define glDrawArrays gl::core.drawArrays
#define glDrawBuffer gl::core.drawBuffer
#define glEnable gl::core.enable
#define glFinish gl::core.finish
#define glFlush gl::core.flush
#define glGenTextures gl::core.genTextures
#define glGetError gl::core.getError
#define glGetFloatv gl::core.getFloatv
#define glGetIntegerv gl::core.getIntegerv
#define glGetString gl::core.getString
#define glPixelStorei gl::core.pixelStorei
#define glReadBuffer gl::core.readBuffer
#define glReadPixels gl::core.readPixels
#define glScissor gl::core.scissor
#define glTexImage2D gl::core.texImage2D
#define glTexParameteri gl::core.texParameteri
#define glTexSubImage2D gl::core.texSubImage2D
#define glViewport gl::core.viewport
