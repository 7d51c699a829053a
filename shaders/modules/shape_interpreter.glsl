// The general shader's scene: every object's shape is a small postfix program read from
// uniforms and run by this interpreter, so the same code serves any structure. The
// specialised shader replaces all of this with straight-line code generated for the scene
// (render/SceneShaderGenerator.cpp), which is what `--no-specialize` is measured against.
//
// Instructions, ivec4(opcode, a, b, c):
//   PRIMITIVE  a = primitive kind, b = first parameter, c = planes (polyhedron) or user SDF
//   PUSH_FRAME a = first transform parameter: continue in the shape's local frame
//   POP_FRAME  a = first transform parameter: back to the parent frame, distance rescaled
//   COMBINE    a = CSG operator, b = operand count, c = parameter slot (smooth operators)
//   END        the object's distance is on the stack
// The opcodes (OPCODE_*), the primitive and CSG codes (PRIMITIVE_*, CSG_*) and the switches
// over those kinds, primitiveDistance, combine, primitiveMetExactly and
// exactPrimitiveIntersect, are generated (shadergen/InterpretedSceneCode.cpp) from the kinds'
// descriptions in scene/Primitives.h and scene/CsgOperators.h.

uniform ivec4 uShapeProgram[SHAPE_PROGRAM_ARRAY_SIZE];
// Per object, a bounding sphere (centre, radius) for expensive shapes, radius < 0 for none:
// the object is skipped where its sphere is no nearer than what is already known.
uniform vec4 uObjectBounds[OBJECT_ARRAY_SIZE];

bool mayBeNearer(int object, vec3 p, float known)
{
    vec4 bound = uObjectBounds[object];
    return bound.w < 0.0 || sdSphere(p - bound.xyz, bound.w) < known;
}

// Leaving a frame maps the point back by the forward transform instead of keeping a stack
// of points: local arrays indexed at run time are slow on software rasterisers.
vec3 toParentPoint(vec3 local, int first)
{
    vec4 translationAndScale = SHAPE_PARAMETERS[first + 3];
    mat3 rotation = mat3(SHAPE_PARAMETERS[first].xyz, SHAPE_PARAMETERS[first + 1].xyz,
                         SHAPE_PARAMETERS[first + 2].xyz);
    return rotation * (translationAndScale.w * local) + translationAndScale.xyz;
}

float runShapeProgram(int start, vec3 p)
{
    float distances[SHAPE_STACK_DEPTH];
    int distanceCount = 0;
    vec3 point = p;
    for (int pc = start; pc < SHAPE_PROGRAM_ARRAY_SIZE && loopIterationAllowed(); ++pc) {
        ivec4 instruction = uShapeProgram[pc];
        if (instruction.x == OPCODE_END)
            break;
        if (instruction.x == OPCODE_PRIMITIVE) {
            distances[distanceCount++] =
                primitiveDistance(instruction.y, instruction.z, instruction.w, point);
        } else if (instruction.x == OPCODE_PUSH_FRAME) {
            point = toLocalPoint(point, instruction.y);
        } else if (instruction.x == OPCODE_POP_FRAME) {
            point = toParentPoint(point, instruction.y);
            distances[distanceCount - 1] =
                toWorldDistance(distances[distanceCount - 1], instruction.y);
        } else {
            int operands = instruction.z;
            int first = distanceCount - operands;
            float parameter = SHAPE_PARAMETERS[instruction.w].x;
            float d = distances[first];
            for (int i = 1; i < operands && loopIterationAllowed(); ++i)
                d = combine(instruction.y, d, distances[first + i], parameter);
            distanceCount = first;
            distances[distanceCount++] = d;
        }
    }
    return distances[0];
}

float objectDistance(int object, vec3 p)
{
    int start = objectShapeProgramStart(object);
    ivec4 first = uShapeProgram[start];
    // Most objects are one primitive: evaluate it directly, without the interpreter's stack.
    if (first.x == OPCODE_PRIMITIVE && uShapeProgram[start + 1].x == OPCODE_END)
        return primitiveDistance(first.y, first.z, first.w, p);
    return runShapeProgram(start, p);
}

float sceneDistance(vec3 p)
{
    float d = FLOAT_MAX;
    for (int object = 0; object < OBJECT_COUNT && loopIterationAllowed(); ++object)
        if (mayBeNearer(object, p, d))
            d = min(d, objectDistance(object, p));
    return d;
}

float sceneDistanceAndObject(vec3 p, out int nearest)
{
    float d = FLOAT_MAX;
    nearest = -1;
    for (int object = 0; object < OBJECT_COUNT && loopIterationAllowed(); ++object) {
        if (!mayBeNearer(object, p, d))
            continue;
        float candidate = objectDistance(object, p);
        if (candidate < d) {
            d = candidate;
            nearest = object;
        }
    }
    return d;
}

// The general shader culls nothing by bounds (ray_culling.glsl); the culled forms only leave
// out the objects k < 32 whose mask bit k a caller cleared (the sphere lights rays meet
// exactly).
RayCulling sceneRayCulling(vec3 origin, vec3 direction, float tolerance0, float toleranceGrowth)
{
    return noRayCulling();
}

bool objectInMask(int object, uint mask)
{
    return object >= 32 || (mask & (1u << uint(object))) != 0u;
}

// An object that is one untransformed primitive whose kind rays meet by exact intersection
// (primitiveMetExactly, generated from scene/Primitives.h), but a sphere light: rays meet it
// exactly (exactSurfacesIntersect), so the culled forms, which rays march, leave it out. The
// specialised shader meets transformed ones exactly too.
bool isExactObject(int object)
{
    int start = objectShapeProgramStart(object);
    ivec4 first = uShapeProgram[start];
    bool single = first.x == OPCODE_PRIMITIVE && uShapeProgram[start + 1].x == OPCODE_END;
    return single && primitiveMetExactly(first.y, first.z) &&
           (first.y != PRIMITIVE_SPHERE || objectSphereLight(object) < 0);
}

void exactSurfacesIntersect(vec3 origin, vec3 direction, float tMin, int only, inout ExactHit hit)
{
    for (int object = 0; object < OBJECT_COUNT && loopIterationAllowed(); ++object) {
        if (!isExactObject(object) || (only >= 0 && object != only))
            continue;
        ivec4 primitive = uShapeProgram[objectShapeProgramStart(object)];
        exactPrimitiveIntersect(primitive.y, primitive.z, primitive.w, origin, direction, tMin,
                                object, hit);
    }
}

float sceneDistanceCulled(vec3 p, uint mask)
{
    float d = FLOAT_MAX;
    for (int object = 0; object < OBJECT_COUNT && loopIterationAllowed(); ++object)
        if (objectInMask(object, mask) && !isExactObject(object) && mayBeNearer(object, p, d))
            d = min(d, objectDistance(object, p));
    return d;
}

float sceneDistanceAndObjectCulled(vec3 p, uint mask, out int nearest)
{
    float d = FLOAT_MAX;
    nearest = -1;
    for (int object = 0; object < OBJECT_COUNT && loopIterationAllowed(); ++object) {
        if (!objectInMask(object, mask) || isExactObject(object) ||
            !mayBeNearer(object, p, d))
            continue;
        float candidate = objectDistance(object, p);
        if (candidate < d) {
            d = candidate;
            nearest = object;
        }
    }
    return d;
}
