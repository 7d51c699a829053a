// The scene's numbers, as uniforms: editing a value re-uploads them and never recompiles.
// The host (render/SceneUniforms.cpp) fills them; the generated preamble sizes them. Each
// record's layout is written here, and its records are decoded only by the accessors below.
// (The shape parameters are no records: the generated code and the interpreter's program
// address them by slot.)

// Shape parameters: one or more vec4 per primitive or transform.
uniform vec4 uShapeParameters[SHAPE_PARAMETER_ARRAY_SIZE];

#if SHAPE_PARAMETERS_READ_ONCE
// llvmpipe reads a uniform with one load for all pixels of a SIMD group only where every
// pixel of the group is known to run (no branch or loop that some pixel may have left);
// elsewhere it gathers it pixel by pixel, with a bounds check, as if the index varied. The
// generated shape code runs inside the path loop and the marches, so every parameter of every
// step was gathered. The specialised shader reads them at constant indices: they are copied
// once per pixel into variables at the start of main(), and the shape code reads those (the
// name below). Scene 6: 1.16x (docs/PERFORMANCE.md). The copy is element by element: a whole-
// array assignment is propagated back to the uniform by the compiler.
vec4 shapeParametersReadOnce[SHAPE_PARAMETER_ARRAY_SIZE];
void readShapeParametersOnce()
{
    for (int i = 0; i < SHAPE_PARAMETER_ARRAY_SIZE; ++i)
        shapeParametersReadOnce[i] = uShapeParameters[i];
}
#define uShapeParameters shapeParametersReadOnce
#else
void readShapeParametersOnce() {}
#endif

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
// A table of one record (one light, as in every classic scene) is read at a constant index:
// llvmpipe then loads it once for all pixels of its SIMD group, where an index that varies
// per pixel is gathered pixel by pixel, with a bounds check, for every field read (scene 1
// gained 1.11x from its light alone, docs/PERFORMANCE.md). The index is then ignored, as an
// index out of range was clamped before.
#define TABLE_RECORD(t, size, stride, i, part) t[(size) == 1 ? (part) : (stride) * (i) + (part)]

int objectPigment(int object) { return TABLE_RECORD(uObjects, OBJECT_ARRAY_SIZE, 1, object, 0).x; }
int objectFinish(int object) { return TABLE_RECORD(uObjects, OBJECT_ARRAY_SIZE, 1, object, 0).y; }
int objectSphereLight(int object)
{
    return TABLE_RECORD(uObjects, OBJECT_ARRAY_SIZE, 1, object, 0).z;
}
int objectShapeProgramStart(int object)
{
    return TABLE_RECORD(uObjects, OBJECT_ARRAY_SIZE, 1, object, 0).w;
}

#define PIGMENT_RECORD(pigment, part) TABLE_RECORD(uPigments, PIGMENT_ARRAY_SIZE, 3, pigment, part)
int pigmentKind(int pigment) { return int(PIGMENT_RECORD(pigment, 0).x); }
// A checker's cube edge, or a texture's tile size (world units per repeat).
float pigmentSize(int pigment) { return PIGMENT_RECORD(pigment, 0).y; }
float pigmentTextureLayer(int pigment) { return PIGMENT_RECORD(pigment, 0).z; }
vec3 pigmentFirstColor(int pigment) { return PIGMENT_RECORD(pigment, 1).rgb; }
vec3 pigmentSecondColor(int pigment) { return PIGMENT_RECORD(pigment, 2).rgb; }

#define FINISH_RECORD(finish, part) TABLE_RECORD(uFinishes, FINISH_ARRAY_SIZE, 2, finish, part)
vec3 finishEmission(int finish) { return FINISH_RECORD(finish, 0).rgb; }
float finishPhongExponent(int finish) { return FINISH_RECORD(finish, 0).w; }
int finishMaterial(int finish) { return int(FINISH_RECORD(finish, 1).x); }
float finishIor(int finish) { return FINISH_RECORD(finish, 1).y; }

#define LIGHT_RECORD(light, part) TABLE_RECORD(uLights, LIGHT_ARRAY_SIZE, 3, light, part)
vec3 lightPosition(int light) { return LIGHT_RECORD(light, 0).xyz; }
float lightRadius(int light) { return LIGHT_RECORD(light, 0).w; }
vec3 lightEmission(int light) { return LIGHT_RECORD(light, 1).rgb; }
float lightSelectionProbability(int light) { return LIGHT_RECORD(light, 1).w; }
float lightCumulativeProbability(int light) { return LIGHT_RECORD(light, 2).x; }
bool isPointLight(int light) { return LIGHT_RECORD(light, 2).y < 0.0; }
int lightObject(int light) { return int(LIGHT_RECORD(light, 2).y); }
uint lightCullingBit(int light) { return uint(LIGHT_RECORD(light, 2).z); }

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
