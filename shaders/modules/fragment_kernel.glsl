// The fragment kernel: the host draws one triangle over the image (fullscreen.vert), the
// scissor picking the band of rows this pass traces, and each fragment is one pixel
// (path_tracer_main.glsl). It writes both targets of the framebuffer the host binds.

layout(location = 0) out vec4 outEstimate;
layout(location = 1) out vec4 outMoments;
#if FEATURE_BUFFERS
layout(location = 2) out vec4 outAlbedoDepth;
layout(location = 3) out vec4 outNormalCoverage;
#endif

void main()
{
    // Before any branch: the uniforms are read once (shadergen/UniformBlock.h says why).
    readUniformsOnce();
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec4 estimate;
    vec4 moments;
    readPreviousAccumulation(pixel, estimate, moments);
    accumulatePaths(pixel, estimate, moments);
    outEstimate = estimate;
    outMoments = moments;
#if FEATURE_BUFFERS
    outAlbedoDepth = accumulatedAlbedoDepth;
    outNormalCoverage = accumulatedNormalCoverage;
#endif
}
