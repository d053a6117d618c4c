#pragma once
// A desktop OpenGL 3.3 core context without a window (EGL, surfaceless: Mesa's llvmpipe runs
// it anywhere), and the frame it draws into: RGBA16F colour, as the watergraph runtime's, so
// the water's linear radiance may exceed 1 until the output transform.
#include <string>

#include <GL/gl.h>
#include <GL/glext.h>

// Makes the context current for the rest of the process; on failure returns false with
// `why` saying what EGL refused.
bool createHeadlessContext(std::string& why);

struct Frame {
  GLuint framebuffer = 0, color = 0, depth = 0;
  int width = 0, height = 0;
};

// An RGBA16F colour texture with a 32-bit float depth buffer, bound for drawing.
bool createFrame(int width, int height, Frame& frame, std::string& why);
