// The compute kernel (OpenGL 4.3): the host dispatches one invocation per pixel of a
// rectangle of the image (uRegion: the band of rows this pass traces, or the preview's
// corner), in work groups of COMPUTE_GROUP_WIDTH x COMPUTE_GROUP_HEIGHT pixels, and each does
// what a fragment of fragment_kernel.glsl does (path_tracer_main.glsl), writing the targets
// as images. Graphics-light GPUs (the data-centre kind) shade fragments on a few of their
// processors only; a dispatch runs on all of them.

layout(local_size_x = COMPUTE_GROUP_WIDTH, local_size_y = COMPUTE_GROUP_HEIGHT) in;

layout(rgba32f, binding = 0) uniform writeonly image2D uNextEstimate;
layout(rgba32f, binding = 1) uniform writeonly image2D uNextMoments;
#if FEATURE_BUFFERS
layout(rgba32f, binding = 2) uniform writeonly image2D uNextAlbedoDepth;
layout(rgba32f, binding = 3) uniform writeonly image2D uNextNormalCoverage;
#endif
// x, y: the rectangle's lower-left pixel; z, w: its width and height.
uniform ivec4 uRegion;

void main()
{
    readUniformsOnce();
    // A group at the rectangle's right or top edge has invocations past it.
    if (any(greaterThanEqual(gl_GlobalInvocationID.xy, uvec2(uRegion.zw))))
        return;
    ivec2 pixel = uRegion.xy + ivec2(gl_GlobalInvocationID.xy);
    vec4 estimate;
    vec4 moments;
    readPreviousAccumulation(pixel, estimate, moments);
    accumulatePaths(pixel, estimate, moments);
    imageStore(uNextEstimate, pixel, estimate);
    imageStore(uNextMoments, pixel, moments);
#if FEATURE_BUFFERS
    imageStore(uNextAlbedoDepth, pixel, accumulatedAlbedoDepth);
    imageStore(uNextNormalCoverage, pixel, accumulatedNormalCoverage);
#endif
}
