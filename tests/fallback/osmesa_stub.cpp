// A stand-in for libOSMesa.so.8 that has no renderer: every context creation fails, as the real
// library's does on a machine without its software rasteriser. Tests only: fallback.none puts it
// before the system's library on LD_LIBRARY_PATH (the backend opens OSMesa by its soname), and
// tools/run_device_checks.sh carries it in place of Mesa's, which the conformance binary links.
// (Mesa's own switch, GALLIUM_DRIVER set to an unknown driver, crashes inside
// OSMesaCreateContextAttribs instead of failing.)
#include <GL/osmesa.h>

extern "C" {

GLAPI OSMesaContext GLAPIENTRY OSMesaCreateContextAttribs(const int*, OSMesaContext) { return nullptr; }
GLAPI OSMesaContext GLAPIENTRY OSMesaCreateContextExt(GLenum, GLint, GLint, GLint, OSMesaContext) { return nullptr; }
GLAPI OSMesaContext GLAPIENTRY OSMesaCreateContext(GLenum, OSMesaContext) { return nullptr; }
GLAPI void GLAPIENTRY OSMesaDestroyContext(OSMesaContext) {}
GLAPI GLboolean GLAPIENTRY OSMesaMakeCurrent(OSMesaContext, void*, GLenum, GLsizei, GLsizei) { return GL_FALSE; }
GLAPI OSMesaContext GLAPIENTRY OSMesaGetCurrentContext() { return nullptr; }
GLAPI OSMESAproc GLAPIENTRY OSMesaGetProcAddress(const char*) { return nullptr; }
GLAPI GLboolean GLAPIENTRY OSMesaGetColorBuffer(OSMesaContext, GLint*, GLint*, GLint*, void**) { return GL_FALSE; }
}
