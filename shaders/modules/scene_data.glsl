// The scene's numbers, as uniforms: editing a value re-uploads them and never recompiles.
// The host (render/SceneUniforms.cpp) fills them, the generated preamble sizes them; the
// shape parameters (SHAPE_PARAMETERS) are addressed by slot by the generated code and the
// interpreter's program, the object, pigment, finish and light records are read through
// their accessors only.

// Their declarations, the read-once copies of a table of one record (llvmpipe gathers a
// uniform read inside a branch pixel by pixel: scene 1 gained 1.11x from its light's record
// read at a constant index alone) and the accessors that decode each record are generated
// from the records' layouts (shadergen/SceneRecords.h) into the uniforms' piece of the
// shader.

// The pigment, material and light codes (PIGMENT_*, MATERIAL_*, LIGHT_*) are generated
// #defines (shadergen/ShaderCodes.h), from the kinds' descriptions in scene/Pigments.h,
// scene/Materials.h and scene/Lights.h.

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
