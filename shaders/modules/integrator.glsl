// The path tracer: one path per call, an unbiased estimate of the radiance through a pixel
// (Kajiya 1986), with next-event estimation for the lights (direct_lighting.glsl) and
// multiple importance sampling (Veach 1997, power heuristic) between light and BSDF sampling
// of the lights that BSDF-sampled rays can meet (sphere lights, the environment map), so
// that no light is counted twice.

// Smallest cosine between wo and the facing normal (see Surface.facingNormal).
const float kMinimumViewCosine = 1e-4;

// `uPattern`: the pigment's random choice (pigmentColor), uniform on [0, 1).
Surface surfaceAt(int object, vec3 p, vec3 normal, vec3 wo, float insideSign, float footprint,
                  float uPattern)
{
    int finish = objectFinish(object);
    Surface s;
    s.position = p;
    s.normal = normal;
    s.entering = insideSign > 0.0;
    vec3 facing = insideSign * normal;
    float cosView = dot(facing, wo);
    if (cosView < kMinimumViewCosine)
        facing = normalize(facing + (kMinimumViewCosine - cosView) * wo);
    s.facingNormal = facing;
    s.color = pigmentColor(objectPigment(object), p, normal, footprint, 0.0, uPattern);
    s.emission = finishEmission(finish);
    s.phongExponent = finishPhongExponent(finish);
    s.material = finishMaterial(finish);
    s.ior = finishIor(finish);
    s.lightIndex = objectSphereLight(object);
#if HAS_MICROFACET
    s.roughness = finishRoughness(finish);
#endif
#if HAS_ROUGH_CONDUCTOR
    s.complexIor = finishHasComplexIor(finish);
    s.conductorEta = finishConductorEta(finish);
    s.conductorK = finishConductorK(finish);
#endif
    return s;
}

// Most paths carry no more than 16 crossings of index-1 dielectrics (see lights.glsl).
const int kMaxNullCrossings = 32;

// A path between segments: the ray about to be traced and what the path has gathered.
struct PathState {
    vec3 origin;
    vec3 direction;
    RayCone cone;
    float insideSign;  // -1 while the ray travels inside a solid
    int containing;    // the solid it travels in, or -1
    vec3 throughput;
    float radianceScale;  // product of the refractions' (eta_o / eta_i)^2
    vec3 radiance;
    // The last scattering could not have been found by light sampling (a delta, or a ray
    // through the surface): the emission this ray meets counts in full, without MIS.
    bool previousWasDelta;
    float previousPdf;
    vec3 previousPosition;
    int scattering;
    int nullCrossings;
    float marchStart;  // how far along the ray its search may begin (see cameraMarchStart)
#if FEATURE_BUFFERS
    // What the camera path met first (path_tracer_main.glsl accumulates it): the albedo and
    // normal of the first surface that is not a perfect mirror or glass, tinted by those
    // passed through (as Open Image Denoise asks); where the path escapes first, the
    // environment's radiance clamped to 1 and no normal. featureDepth: the camera ray's
    // distance to what it hit, -1 until then or where it hit nothing.
    vec3 featureAlbedo;
    vec3 featureNormal;
    vec3 featureTint;
    float featureDepth;
    bool featuresFound;
    bool cameraSegment;
#endif
};

// The most segments (traced rays) one path can take.
int maxSegmentsPerPath()
{
    return gMaxBounces + 1 + kMaxNullCrossings;
}

// `cameraClear`: where the camera ray's march may begin (cameraMarchStart, 0 from inside).
PathState startPath(vec2 filmPoint, int cameraContaining, float cameraClear)
{
    PathState path;
    cameraRay(filmPoint, path.origin, path.direction);
    path.cone = RayCone(0.0, cameraPixelSpread());
    path.containing = cameraContaining;
    path.insideSign = cameraContaining >= 0 ? -1.0 : 1.0;
    path.throughput = vec3(1.0);
    path.radianceScale = 1.0;
    path.radiance = vec3(0.0);
    path.previousWasDelta = true;  // the camera ray: emission seen directly counts in full
    path.previousPdf = 0.0;
    path.previousPosition = path.origin;
    path.scattering = 0;
    path.nullCrossings = 0;
    path.marchStart = cameraClear;
#if FEATURE_BUFFERS
    path.featureAlbedo = vec3(0.0);
    path.featureNormal = vec3(0.0);
    path.featureTint = vec3(1.0);
    path.featureDepth = -1.0;
    path.featuresFound = false;
    path.cameraSegment = true;
#endif
    return path;
}

// Traces the path's next ray and scatters at what it hits. Returns false once the path has
// ended, its radiance then final.
bool continuePath(inout PathState path)
{
#if PROFILE_COUNTERS
    ++workSegments;
    workOnCameraRay = path.cone.spread > 0.0;
#endif
    SurfaceHit hit = findSurface(path.origin, path.direction, path.insideSign, path.cone,
                                 path.marchStart, path.containing);
#if FEATURE_BUFFERS
    bool cameraSegment = path.cameraSegment;
    path.cameraSegment = false;
    if (!hit.found && !path.featuresFound) {
        path.featureAlbedo = path.featureTint * min(environmentRadiance(path.direction), vec3(1.0));
        path.featuresFound = true;
    }
    if (hit.found && cameraSegment)
        path.featureDepth = distance(hit.position, path.origin);
#endif
    if (!hit.found) {
        float weight = 1.0;
#if HAS_ENVIRONMENT_LIGHT
        // The environment map is a light: weighed against light sampling as a sphere light
        // is below.
        if (!path.previousWasDelta)
            weight = gMultipleImportanceSampling
                         ? powerHeuristic(path.previousPdf,
                                          lightPdf(ENVIRONMENT_LIGHT_INDEX,
                                                   path.previousPosition, path.direction))
                         : 0.0;
#endif
        path.radiance += path.throughput * environmentRadiance(path.direction) * weight;
        return false;
    }
    vec3 direction = path.direction;
    float insideSign = path.insideSign;
    vec3 p = hit.position;
    float footprint = hit.footprint;
    float tolerance = hit.tolerance;
    vec3 wo = -direction;
    // A scattering event's pattern takes its own stratified dimension; the crossings of
    // index-1 surfaces between two events (which share the event's number) take numbers of
    // the random stream, since two vertices of one path looked up with one number would
    // correlate their colours and bias their product.
#if HAS_TEXTURE_PIGMENT
    float uPattern = isNullInterface(hit.object) ? random01()
                                                 : bounceSample1D(path.scattering, SAMPLE_PATTERN);
#else
    const float uPattern = 0.0;
#endif
    Surface s = surfaceAt(hit.object, p, hit.normal, wo, insideSign, footprint, uPattern);
#if FEATURE_BUFFERS
    if (!path.featuresFound) {
        if (isDeltaMaterial(s.material) || isNullInterface(hit.object)) {
            path.featureTint *= s.color;
        } else {
            path.featureAlbedo = path.featureTint * s.color;
            path.featureNormal = s.normal;
            path.featuresFound = true;
        }
    }
#endif

#if HAS_SPHERE_LIGHTS
    // Emission, seen from outside the sphere, only along rays that truly meet it: the march
    // accepts rays passing within the hit tolerance, which would widen every light by that
    // much (bright outlines), and light sampling never picks those directions either.
    if (s.lightIndex >= 0 && s.entering &&
        rayMeetsSphereLight(path.origin, path.direction, s.lightIndex)) {
        float weight = 1.0;
        if (!path.previousWasDelta)
            weight = gMultipleImportanceSampling
                         ? powerHeuristic(path.previousPdf,
                                          lightPdf(s.lightIndex, path.previousPosition,
                                                   path.direction))
                         : 0.0;
        path.radiance += path.throughput * s.emission * weight;
    }
#endif
#if HAS_NULL_INTERFACES
    if (isNullInterface(hit.object) && path.nullCrossings < kMaxNullCrossings) {
        // No interface, no scattering event: the ray goes on unbent, tinted.
        path.throughput *= s.color;
        ++path.nullCrossings;
        path.cone = RayCone(footprint, path.cone.spread);
        return spawn(p, s.facingNormal, direction, tolerance, hit.object, path.insideSign,
                     path.origin, path.marchStart, path.containing);
    }
#endif
    if (path.scattering == gMaxBounces)
        return false;
    int bounce = path.scattering++;

    if (!isDeltaMaterial(s.material))
        path.radiance += path.throughput *
                         directLighting(s, wo, tolerance, insideSign,
                                        bounceSample1D(bounce, SAMPLE_LIGHT_SELECTION),
                                        bounceSample2D(bounce, SAMPLE_LIGHT_POINT));

    BsdfSample scattered = bsdfSample(s, wo, bounceSample1D(bounce, SAMPLE_BSDF_LOBE),
                                      bounceSample2D(bounce, SAMPLE_BSDF_DIRECTION));
    if (!scattered.valid)
        return false;
    path.throughput *= scattered.weight;
    path.radianceScale *= scattered.radianceScale;
    path.previousWasDelta = scattered.isDelta;
#if HAS_ROUGH_DIELECTRIC
    // Light sampling looks only on the side of the surface the path arrived from
    // (directLighting): a direction through the surface has no light-sampling counterpart,
    // so the light it finds counts in full.
    if (dot(scattered.direction, s.facingNormal) < 0.0)
        path.previousWasDelta = true;
#endif
    path.previousPdf = scattered.pdf;
    // Light sampling measured its cone from the surface point; MIS weighs the same pdfs.
    path.previousPosition = p;

    // Past the first scattering events, end dim paths at random and reweight the survivors:
    // unbiased, and no throughput clamp undoes it. Dimness is judged without the
    // refractions' radiance scaling, which leaving the medium undoes.
    if (path.scattering > gRussianRouletteDepth) {
        float survival = min(1.0, maxComponent(path.throughput) / path.radianceScale);
        if (!(bounceSample1D(bounce, SAMPLE_ROULETTE) < survival))
            return false;
        path.throughput /= survival;
    }

    // Specular chains keep the pixel's cone; a diffuse or glossy bounce integrates over
    // directions, so its rays resolve the scene at this point's footprint.
    path.cone = RayCone(footprint, scattered.isDelta ? path.cone.spread : 0.0);
    path.direction = scattered.direction;
    return spawn(p, s.facingNormal, scattered.direction, tolerance, hit.object,
                 path.insideSign, path.origin, path.marchStart, path.containing);
}
