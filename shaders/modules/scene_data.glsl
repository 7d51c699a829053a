// The scene's numbers, as uniforms: editing a value re-uploads them and never recompiles.
// The host (render/SceneUniforms.cpp) fills them; the generated preamble sizes them. Each
// record's layout is written here, and its records are decoded only by the accessors below.
// (The shape parameters are no records: the generated code and the interpreter's program
// address them by slot.)

// Shape parameters: one or more vec4 per primitive or transform.
uniform vec4 uShapeParameters[SHAPE_PARAMETER_ARRAY_SIZE];

// --- uniforms read once -------------------------------------------------------------------
// llvmpipe reads a uniform with one load for all pixels of a SIMD group only where every
// pixel of the group is known to run (outside every branch and loop that some pixel may have
// left); elsewhere it gathers it pixel by pixel, with a bounds check, as if its index varied.
// Nearly all of a path's work runs inside such loops, so every uniform it read there was
// gathered at every use. So main() first copies the uniforms into variables, and the code
// reads those: each module declares its copies and the function that fills them right after
// its uniforms, then renames the uniforms to their copies with #define, so that the code
// below keeps the uniforms' names. (Scene 6: 1.16x for the shape parameters alone;
// docs/PERFORMANCE.md.) Copies of arrays are made element by element: a whole-array
// assignment is propagated back to the uniform by the compiler. Arrays read at indices that
// vary are left alone; their copies would be gathered too.

#if SHAPE_PARAMETERS_READ_ONCE
// The specialised shader's generated shape code reads the parameters at constant indices.
vec4 uShapeParametersReadOnce[SHAPE_PARAMETER_ARRAY_SIZE];
void readShapeParametersOnce()
{
    for (int i = 0; i < SHAPE_PARAMETER_ARRAY_SIZE; ++i)
        uShapeParametersReadOnce[i] = uShapeParameters[i];
}
#define uShapeParameters uShapeParametersReadOnce
#else
void readShapeParametersOnce() {}
#endif

// Per object: x = pigment, y = finish, z = sphere light index or -1, w = the start of its
// shape program (general shader only).
uniform ivec4 uObjects[OBJECT_ARRAY_SIZE];

// Per pigment, three vec4: (kind, size, texture layer, -), (colour, -), (second colour, -).
uniform vec4 uPigments[3 * PIGMENT_ARRAY_SIZE];

// Per finish, two vec4: (emitted radiance, Blinn-Phong exponent), (material, ior, GGX
// roughness alpha, -).
uniform vec4 uFinishes[2 * FINISH_ARRAY_SIZE];

#if HAS_ROUGH_CONDUCTOR
// Per finish, two vec4: (eta, 1 where the finish has this complex index of refraction, 0
// where its Fresnel is Schlick's with the pigment), (k, -).
uniform vec4 uFinishConductors[2 * FINISH_ARRAY_SIZE];
#endif

// Per light, three vec4: (position or centre, radius), (intensity or radiance, selection
// probability), (cumulative selection probability, the object that is the light or -1, its
// culling bit or 0, its kind: a LIGHT_* code). Lights are chosen in proportion to their
// emitted power; what each kind's record holds is scene/Lights.h's Light.
uniform vec4 uLights[3 * LIGHT_ARRAY_SIZE];
// The culling bits of every sphere light that has one: rays leave those out of their marches
// and intersect the spheres exactly instead (ray_queries_traced.glsl).
uniform uint uSphereLightPieces;

// The pigment, material and light codes (PIGMENT_*, MATERIAL_*, LIGHT_*) are generated
// #defines (render/ShaderCodes.h), from the kinds' descriptions in scene/Pigments.h,
// scene/Materials.h and scene/Lights.h.

// A table of one record (one light, as in every classic scene) is read once, like the other
// uniforms, and its accessors read that copy whatever index they are given (an index out of
// range was clamped to the one record before): scene 1 gained 1.11x from its light's record
// read at a constant index alone (docs/PERFORMANCE.md). Larger tables are indexed by values
// that vary from pixel to pixel (the object a ray hit), and are gathered.
#if OBJECT_ARRAY_SIZE == 1
ivec4 uObjectsReadOnce[1];
#define OBJECT_RECORD(object) uObjectsReadOnce[0]
#else
#define OBJECT_RECORD(object) uObjects[object]
#endif
#if PIGMENT_ARRAY_SIZE == 1
vec4 uPigmentsReadOnce[3];
#define PIGMENT_RECORD(pigment, part) uPigmentsReadOnce[part]
#else
#define PIGMENT_RECORD(pigment, part) uPigments[3 * (pigment) + (part)]
#endif
#if FINISH_ARRAY_SIZE == 1
vec4 uFinishesReadOnce[2];
#define FINISH_RECORD(finish, part) uFinishesReadOnce[part]
#if HAS_ROUGH_CONDUCTOR
vec4 uFinishConductorsReadOnce[2];
#define CONDUCTOR_RECORD(finish, part) uFinishConductorsReadOnce[part]
#endif
#else
#define FINISH_RECORD(finish, part) uFinishes[2 * (finish) + (part)]
#define CONDUCTOR_RECORD(finish, part) uFinishConductors[2 * (finish) + (part)]
#endif
#if LIGHT_ARRAY_SIZE == 1
vec4 uLightsReadOnce[3];
#define LIGHT_RECORD(light, part) uLightsReadOnce[part]
#else
#define LIGHT_RECORD(light, part) uLights[3 * (light) + (part)]
#endif
uint uSphereLightPiecesReadOnce;
void readSceneDataUniformsOnce()
{
    readShapeParametersOnce();
#if OBJECT_ARRAY_SIZE == 1
    uObjectsReadOnce[0] = uObjects[0];
#endif
#if PIGMENT_ARRAY_SIZE == 1
    for (int part = 0; part < 3; ++part)
        uPigmentsReadOnce[part] = uPigments[part];
#endif
#if FINISH_ARRAY_SIZE == 1
    for (int part = 0; part < 2; ++part)
        uFinishesReadOnce[part] = uFinishes[part];
#if HAS_ROUGH_CONDUCTOR
    for (int part = 0; part < 2; ++part)
        uFinishConductorsReadOnce[part] = uFinishConductors[part];
#endif
#endif
#if LIGHT_ARRAY_SIZE == 1
    for (int part = 0; part < 3; ++part)
        uLightsReadOnce[part] = uLights[part];
#endif
    uSphereLightPiecesReadOnce = uSphereLightPieces;
}
#define uSphereLightPieces uSphereLightPiecesReadOnce

// --- accessors: where object, pigment, finish and light records are decoded --------------

int objectPigment(int object) { return OBJECT_RECORD(object).x; }
int objectFinish(int object) { return OBJECT_RECORD(object).y; }
int objectSphereLight(int object) { return OBJECT_RECORD(object).z; }
int objectShapeProgramStart(int object) { return OBJECT_RECORD(object).w; }

int pigmentKind(int pigment) { return int(PIGMENT_RECORD(pigment, 0).x); }
// A checker's cube edge, or a texture's tile size (world units per repeat).
float pigmentSize(int pigment) { return PIGMENT_RECORD(pigment, 0).y; }
float pigmentTextureLayer(int pigment) { return PIGMENT_RECORD(pigment, 0).z; }
vec3 pigmentFirstColor(int pigment) { return PIGMENT_RECORD(pigment, 1).rgb; }
vec3 pigmentSecondColor(int pigment) { return PIGMENT_RECORD(pigment, 2).rgb; }

vec3 finishEmission(int finish) { return FINISH_RECORD(finish, 0).rgb; }
float finishPhongExponent(int finish) { return FINISH_RECORD(finish, 0).w; }
int finishMaterial(int finish) { return int(FINISH_RECORD(finish, 1).x); }
float finishIor(int finish) { return FINISH_RECORD(finish, 1).y; }
float finishRoughness(int finish) { return FINISH_RECORD(finish, 1).z; }
#if HAS_ROUGH_CONDUCTOR
bool finishHasComplexIor(int finish) { return CONDUCTOR_RECORD(finish, 0).w > 0.0; }
vec3 finishConductorEta(int finish) { return CONDUCTOR_RECORD(finish, 0).rgb; }
vec3 finishConductorK(int finish) { return CONDUCTOR_RECORD(finish, 1).rgb; }
#endif

vec3 lightPosition(int light) { return LIGHT_RECORD(light, 0).xyz; }
float lightRadius(int light) { return LIGHT_RECORD(light, 0).w; }
vec3 lightEmission(int light) { return LIGHT_RECORD(light, 1).rgb; }
float lightSelectionProbability(int light) { return LIGHT_RECORD(light, 1).w; }
float lightCumulativeProbability(int light) { return LIGHT_RECORD(light, 2).x; }
int lightObject(int light) { return int(LIGHT_RECORD(light, 2).y); }
uint lightCullingBit(int light) { return uint(LIGHT_RECORD(light, 2).z); }
int lightKind(int light) { return int(LIGHT_RECORD(light, 2).w); }

// An object that refracts nothing: a dielectric of index exactly 1, between equal media.
// It has no interface, so light passes it unbent, tinted by its pigment. A constant false in
// scenes without one, so that the code handling them compiles away: llvmpipe executes both
// sides of every branch (masked), so code behind a branch that is never taken still costs.
bool isNullInterface(int object)
{
#if HAS_NULL_INTERFACES
    int finish = objectFinish(object);
    return finishMaterial(finish) == MATERIAL_DIELECTRIC && finishIor(finish) == 1.0;
#else
    return false;
#endif
}
