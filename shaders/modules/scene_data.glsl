// The scene's numbers, as uniforms: editing a value re-uploads them and never recompiles.
// The host (render/SceneUniforms.cpp) defines the array sizes and fills them; the layout of
// each record is documented there and repeated at the accessors below.

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
// -, -). Lights are chosen in proportion to their emitted power.
uniform vec4 uLights[3 * LIGHT_ARRAY_SIZE];

const int PIGMENT_SOLID = 0;
const int PIGMENT_CHECKER = 1;
const int PIGMENT_TEXTURE = 2;

const int MATERIAL_LAMBERTIAN = 0;
const int MATERIAL_BLINN_PHONG = 1;
const int MATERIAL_MIRROR = 2;
const int MATERIAL_DIELECTRIC = 3;
