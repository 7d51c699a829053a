// The work a path does, counted for bench_throughput in shaders built with PROFILE_COUNTERS
// (RenderSettings::profileCounters); in every other shader COUNT_WORK is nothing. Such a
// shader accumulates these counts per pixel in place of radiance (path_tracer_main.glsl).

#if PROFILE_COUNTERS
int workCameraSteps = 0;    // march steps of camera rays and their specular chains, and the
                            // pixel's cone march
int workBounceSteps = 0;    // march steps of rays after a diffuse or glossy bounce
int workShadowSteps = 0;    // march steps of shadow rays
int workShadowRays = 0;
int workSegments = 0;       // rays traced (path segments)
int workEvaluations = 0;    // distance evaluations outside marches: normals, refinement,
                            // spawn checks
bool workOnCameraRay = true;
#define COUNT_WORK(counter, n) counter += (n)
#define COUNT_MARCH_STEP() if (workOnCameraRay) ++workCameraSteps; else ++workBounceSteps
#else
#define COUNT_WORK(counter, n)
#define COUNT_MARCH_STEP()
#endif
