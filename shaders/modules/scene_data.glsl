// The scene's numbers, as uniforms: editing a value re-uploads them and never recompiles.
// The host (render/SceneUniforms.cpp) fills them; the generated preamble sizes them. Each
// record's layout is written here, and its records are decoded only by the accessors below.
// (The shape parameters are no records: the generated code and the interpreter's program
// address them by slot.)

// Shape parameters: one or more vec4 per primitive or transform.
uniform vec4 uShapeParameters[SHAPE_PARAMETER_ARRAY_SIZE];

// Per object: x = pigment, y = finish, z = sphere light index or -1, w = the start of its
// shape program (general shader only).
uniform ivec4 uObjects[OBJECT_ARRAY_SIZE];

// Per pigment, three vec4: (kind, size, texture layer, -), (colour, -), (second colour, -).
uniform vec4 uPigments[3 * PIGMENT_ARRAY_SIZE];

// Per finish, two vec4: (emitted radiance, Blinn-Phong exponent), (material, ior, -, -).
uniform vec4 uFinishes[2 * FINISH_ARRAY_SIZE];

// Per light, three vec4: (position or centre, radius), (intensity or radiance, selection
// probability), (cumulative selection probability, object index or -1 for a point light,
// the sphere's culling bit or 0, -). Lights are chosen in proportion to their emitted power.
uniform vec4 uLights[3 * LIGHT_ARRAY_SIZE];
// The culling bits of every sphere light that has one: rays leave those out of their marches
// and intersect the spheres exactly instead (ray_queries_traced.glsl).
uniform uint uSphereLightPieces;

// The pigment and material codes (PIGMENT_*, MATERIAL_*) are generated #defines
// (render/ShaderCodes.h), from the kinds' descriptions in scene/Pigments.h and
// scene/Materials.h.

// --- accessors: where object, pigment, finish and light records are decoded --------------

int objectPigment(int object) { return uObjects[object].x; }
int objectFinish(int object) { return uObjects[object].y; }
int objectSphereLight(int object) { return uObjects[object].z; }
int objectShapeProgramStart(int object) { return uObjects[object].w; }

int pigmentKind(int pigment) { return int(uPigments[3 * pigment].x); }
// A checker's cube edge, or a texture's tile size (world units per repeat).
float pigmentSize(int pigment) { return uPigments[3 * pigment].y; }
float pigmentTextureLayer(int pigment) { return uPigments[3 * pigment].z; }
vec3 pigmentFirstColor(int pigment) { return uPigments[3 * pigment + 1].rgb; }
vec3 pigmentSecondColor(int pigment) { return uPigments[3 * pigment + 2].rgb; }

vec3 finishEmission(int finish) { return uFinishes[2 * finish].rgb; }
float finishPhongExponent(int finish) { return uFinishes[2 * finish].w; }
int finishMaterial(int finish) { return int(uFinishes[2 * finish + 1].x); }
float finishIor(int finish) { return uFinishes[2 * finish + 1].y; }

vec3 lightPosition(int light) { return uLights[3 * light].xyz; }
float lightRadius(int light) { return uLights[3 * light].w; }
vec3 lightEmission(int light) { return uLights[3 * light + 1].rgb; }
float lightSelectionProbability(int light) { return uLights[3 * light + 1].w; }
float lightCumulativeProbability(int light) { return uLights[3 * light + 2].x; }
bool isPointLight(int light) { return uLights[3 * light + 2].y < 0.0; }
int lightObject(int light) { return int(uLights[3 * light + 2].y); }
uint lightCullingBit(int light) { return uint(uLights[3 * light + 2].z); }

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
