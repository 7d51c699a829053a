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

// Everything of the scene's that grows with its objects is read from buffer textures
// (render/SceneDataBuffers.h uploads them; a uniform array holds a few thousand vec4s at most):
//   uShapeParameterBuffer  the shape parameters (SHAPE_PARAMETER, the uniforms' block)
//   uObjectRecords         the object records (OBJECT_RECORD, the uniforms' block)
//   uShapeProgram          the shape programs, one instruction a texel
//   uHierarchyBoxes        per object its bounding sphere (centre, radius; radius < 0 for
//                          none), then per node of the hierarchy its box's lower and upper
//                          corner (HIERARCHY_BOXES_START)
//   uHierarchyLinks        the objects' list, four a texel: the unbounded objects
//                          (HIERARCHY_UNBOUNDED_COUNT) then each leaf's, each entry the
//                          object's index where rays meet it exactly (isExactObject, decided
//                          on the host alike) and -1 - index where they march it; then per node
//                          (skip, first, count, holds a marched object) from
//                          HIERARCHY_LINKS_START
// The hierarchy (shadergen/ObjectHierarchy.h) is flattened depth first: a query that meets a
// node's box goes on to the next node (its first child, or the node after a leaf), one that
// misses it to its skip, which is -1 after the last subtree. No stack: llvmpipe spills
// arrays indexed at run time.
uniform isamplerBuffer uShapeProgram;
uniform samplerBuffer uHierarchyBoxes;
uniform isamplerBuffer uHierarchyLinks;
#define SHAPE_INSTRUCTION(pc) texelFetch(uShapeProgram, pc)
#define HIERARCHY_BOXES_START OBJECT_COUNT
#define HIERARCHY_LINKS_START ((OBJECT_COUNT + 3) / 4)

// The loop over the unbounded objects counts against the loop budget (constants.glsl) only
// where it may run more than four times; a leaf's loop never does (kMostObjectsPerLeaf is 4).
bool unboundedIterationAllowed()
{
    return HIERARCHY_UNBOUNDED_COUNT <= 4 || loopIterationAllowed();
}

// The k-th entry of the objects' list (see above: >= 0 for an object met exactly).
int listedObject(int k)
{
    return texelFetch(uHierarchyLinks, k >> 2)[k & 3];
}

int objectOfEntry(int entry)
{
    return entry >= 0 ? entry : -1 - entry;
}

ivec4 hierarchyLink(int node)
{
    return texelFetch(uHierarchyLinks, HIERARCHY_LINKS_START + node);
}

// Per object, a bounding sphere (centre, radius) for expensive shapes, radius < 0 for none:
// the object is skipped where its sphere is no nearer than what is already known.
bool mayBeNearer(int object, vec3 p, float known)
{
    vec4 bound = texelFetch(uHierarchyBoxes, object);
    return bound.w < 0.0 || sdSphere(p - bound.xyz, bound.w) < known;
}

// Where the ray crosses node's box: the interval of its parameter, empty (x > y) where it
// misses; a ray along a face crosses it. A direction component below 1e-30 counts as zero
// (hierarchyInverse): that slab holds the ray all along or never (its planes' parameters would
// be 0 for an origin on a face, and the interval [0, 0] lose the ray).
// shadergen/ObjectHierarchy.cpp's rayMeetsBox is the same test.
vec2 rayNodeInterval(int node, vec3 origin, vec3 inverseDirection, vec3 parallel)
{
    vec3 lower = texelFetch(uHierarchyBoxes, HIERARCHY_BOXES_START + 2 * node).xyz;
    vec3 upper = texelFetch(uHierarchyBoxes, HIERARCHY_BOXES_START + 2 * node + 1).xyz;
    vec3 t0 = (lower - origin) * inverseDirection;
    vec3 t1 = (upper - origin) * inverseDirection;
    vec3 inside = step(lower, origin) * step(origin, upper);
    vec3 near = mix(min(t0, t1), mix(vec3(FLOAT_MAX), vec3(-FLOAT_MAX), inside), parallel);
    vec3 far = mix(max(t0, t1), mix(vec3(-FLOAT_MAX), vec3(FLOAT_MAX), inside), parallel);
    return vec2(max(max(near.x, near.y), near.z), min(min(far.x, far.y), far.z));
}

// Whether the ray crosses node's box within [tMin, tMax].
bool rayMeetsNode(int node, vec3 origin, vec3 inverseDirection, vec3 parallel, float tMin,
                  float tMax)
{
    vec2 crossing = rayNodeInterval(node, origin, inverseDirection, parallel);
    return max(crossing.x, tMin) <= min(crossing.y, tMax);
}

// 1 where the direction's component counts as zero.
vec3 hierarchyParallel(vec3 direction)
{
    return vec3(lessThan(abs(direction), vec3(1e-30)));
}

vec3 hierarchyInverse(vec3 direction, vec3 parallel)
{
    return 1.0 / mix(direction, vec3(1.0), parallel);
}

// The distance from p to node's box (0 inside it).
float nodeDistance(int node, vec3 p)
{
    vec3 lower = texelFetch(uHierarchyBoxes, HIERARCHY_BOXES_START + 2 * node).xyz;
    vec3 upper = texelFetch(uHierarchyBoxes, HIERARCHY_BOXES_START + 2 * node + 1).xyz;
    return length(max(max(lower - p, p - upper), 0.0));
}

// Leaving a frame maps the point back by the forward transform instead of keeping a stack
// of points: local arrays indexed at run time are slow on software rasterisers.
vec3 toParentPoint(vec3 local, int first)
{
    vec4 translationAndScale = SHAPE_PARAMETER(first + 3);
    mat3 rotation = mat3(SHAPE_PARAMETER(first).xyz, SHAPE_PARAMETER(first + 1).xyz,
                         SHAPE_PARAMETER(first + 2).xyz);
    return rotation * (translationAndScale.w * local) + translationAndScale.xyz;
}

float runShapeProgram(int start, vec3 p)
{
    float distances[SHAPE_STACK_DEPTH];
    int distanceCount = 0;
    vec3 point = p;
    for (int pc = start; pc < SHAPE_PROGRAM_ARRAY_SIZE && loopIterationAllowed(); ++pc) {
        ivec4 instruction = SHAPE_INSTRUCTION(pc);
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
            float parameter = SHAPE_PARAMETER(instruction.w).x;
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
    ivec4 first = SHAPE_INSTRUCTION(start);
    // Most objects are one primitive: evaluate it directly, without the interpreter's stack.
    if (first.x == OPCODE_PRIMITIVE && SHAPE_INSTRUCTION(start + 1).x == OPCODE_END)
        return primitiveDistance(first.y, first.z, first.w, p);
    return runShapeProgram(start, p);
}

// Whether the marched objects of `mask` hold `object`: those k < 32 whose bit is set, and
// every one from 32 on.
bool objectInMask(int object, uint mask)
{
    return object >= 32 || (mask & (1u << uint(object))) != 0u;
}

// An object that is one untransformed primitive whose kind rays meet by exact intersection
// (primitiveMetExactly, generated from scene/Primitives.h), but a sphere light: rays meet it
// exactly (exactSurfacesIntersect), and never march it. The specialised shader meets
// transformed ones exactly too. (The host decides the same for the hierarchy's list of
// objects: SceneShaderGenerator.cpp, interpreterMeetsExactly.)
bool isExactObject(int object)
{
    int start = objectShapeProgramStart(object);
    ivec4 first = SHAPE_INSTRUCTION(start);
    bool single = first.x == OPCODE_PRIMITIVE && SHAPE_INSTRUCTION(start + 1).x == OPCODE_END;
    return single && primitiveMetExactly(first.y, first.z) &&
           (first.y != PRIMITIVE_SPHERE || objectSphereLight(object) < 0);
}

// The scene's distance at p and the nearest object (-1 for none), through the hierarchy: a
// node is entered only where its box is nearer than the nearest distance so far, or holds p
// (a point inside a solid still finds the solid it is deepest in). The same minimum as a loop
// over every object: an object's distance is never below its box's.
void considerObject(int entry, vec3 p, inout float d, inout int nearest)
{
    int object = objectOfEntry(entry);
    if (!mayBeNearer(object, p, d))
        return;
    float candidate = objectDistance(object, p);
    if (candidate < d) {
        d = candidate;
        nearest = object;
    }
}

float hierarchyDistance(vec3 p, out int nearest)
{
    float d = FLOAT_MAX;
    nearest = -1;
    for (int k = 0; k < HIERARCHY_UNBOUNDED_COUNT && unboundedIterationAllowed(); ++k)
        considerObject(listedObject(k), p, d, nearest);
    int node = HIERARCHY_HAS_NODES != 0 ? 0 : -1;
    while (node >= 0 && loopIterationAllowed()) {
        ivec4 link = hierarchyLink(node);
        float boxDistance = nodeDistance(node, p);
        if (!(boxDistance < d || boxDistance <= 0.0)) {
            node = link.x;
            continue;
        }
        for (int k = link.y; k < link.y + link.z; ++k)  // at most kMostObjectsPerLeaf: uncounted
            considerObject(listedObject(k), p, d, nearest);
        node = link.z > 0 ? link.x : node + 1;
    }
    return d;
}

float sceneDistance(vec3 p)
{
    int nearest;
    return hierarchyDistance(p, nearest);
}

float sceneDistanceAndObject(vec3 p, out int nearest)
{
    return hierarchyDistance(p, nearest);
}

// The general shader culls nothing by these bounds (ray_culling.glsl): the hierarchy leaves
// out what a point is far from, and a ray marches each object only within its own bound
// (nextMarchedObject). The masks only leave out the objects k < 32 whose bit k a caller
// cleared (the sphere lights rays meet exactly).
RayCulling sceneRayCulling(vec3 origin, vec3 direction, float tolerance0, float toleranceGrowth)
{
    return noRayCulling();
}

// `entry`: an entry of the objects' list.
void exactObjectIntersect(int entry, vec3 origin, vec3 direction, float tMin, inout ExactHit hit)
{
    if (entry < 0)
        return;
    int object = entry;
    ivec4 primitive = SHAPE_INSTRUCTION(objectShapeProgramStart(object));
    exactPrimitiveIntersect(primitive.y, primitive.z, primitive.w, origin, direction, tMin,
                            object, hit);
}

// The nearest exact crossing in (tMin, hit.t), through the hierarchy: only leaves whose box
// the ray crosses before the nearest crossing so far are opened. `only` >= 0: that object
// alone (a ray inside it).
void exactSurfacesIntersect(vec3 origin, vec3 direction, float tMin, int only, inout ExactHit hit)
{
    if (only >= 0) {
        exactObjectIntersect(isExactObject(only) ? only : -1 - only, origin, direction, tMin,
                             hit);
        return;
    }
    for (int k = 0; k < HIERARCHY_UNBOUNDED_COUNT && unboundedIterationAllowed(); ++k)
        exactObjectIntersect(listedObject(k), origin, direction, tMin, hit);
    vec3 parallel = hierarchyParallel(direction);
    vec3 inverseDirection = hierarchyInverse(direction, parallel);
    int node = HIERARCHY_HAS_NODES != 0 ? 0 : -1;
    while (node >= 0 && loopIterationAllowed()) {
        ivec4 link = hierarchyLink(node);
        if (!rayMeetsNode(node, origin, inverseDirection, parallel, tMin, hit.t)) {
            node = link.x;
            continue;
        }
        for (int k = link.y; k < link.y + link.z; ++k)  // at most kMostObjectsPerLeaf: uncounted
            exactObjectIntersect(listedObject(k), origin, direction, tMin, hit);
        node = link.z > 0 ? link.x : node + 1;
    }
}

// Marched objects are marched one at a time, each only along the stretch of the ray within
// its own bound (ray_queries_traced.glsl, marchObjectByObject and marchedObjectsTransmittance):
// a ray's walk through the hierarchy (nextMarchedObject) finds them front to back, and the
// distances a march evaluates (the culled forms, which the sphere tracer, the move onto the
// surface and the normal call) are that one object's, gMarchedObject's, not the scene's. A
// march step used to walk the whole hierarchy, and every call site of the sphere tracer
// inlined that walk: a scene of 1,000 objects, a fifth of them rounded boxes, set up in 4 s
// and rendered 0.006 Mpaths/s at 160x120; now 1 s and 0.08 (docs/PERFORMANCE.md, "Scenes of
// many objects").
// The normal is the gradient of the hit object's distance, not of the union of every marched
// object's: they differ only where another marched object comes within the stencil's step
// (a quarter of the tolerance) of the hit.
#define MARCHES_OBJECT_BY_OBJECT 1
int gMarchedObject = -1;

// What the culled forms answer with no object to march: a large finite distance, on which a
// march steps out of the scene (FLOAT_MAX, over-relaxed, would overflow, and the march spin
// through its budget on NaN).
const float kNothingMarched = 1e30;

float sceneDistanceAndObjectCulled(vec3 p, uint mask, out int nearest)
{
    nearest = gMarchedObject;
    return gMarchedObject >= 0 ? objectDistance(gMarchedObject, p) : kNothingMarched;
}

float sceneDistanceCulled(vec3 p, uint mask)
{
    int nearest;
    return sceneDistanceAndObjectCulled(p, mask, nearest);
}

// The stretch of the ray (unit direction from origin) where it may come within its tolerance
// (tolerance0 + growth t) of `object`: where it crosses the object's bounding sphere widened by
// that tolerance (as cullByBall, ray_culling.glsl), within `box` (where it crosses the leaf's
// box; everything for an unbounded object). Empty (x > y) where it comes near nothing.
vec2 marchedObjectStretch(int object, vec3 origin, vec3 direction, float tolerance0,
                          float growth, vec2 box)
{
    vec4 ball = texelFetch(uHierarchyBoxes, object);
    if (ball.w < 0.0 || growth >= kMaxCullableToleranceGrowth)
        return box;
    vec3 toCenter = ball.xyz - origin;
    float along = dot(toCenter, direction);
    float margin = 1.25 * (tolerance0 + growth * (max(along, 0.0) + ball.w)) / (1.0 - growth);
    float reach = ball.w + margin;
    vec3 offAxis = toCenter - along * direction;
    float halfChordSquared = reach * reach - dot(offAxis, offAxis);
    if (halfChordSquared < 0.0)
        return vec2(FLOAT_MAX, -FLOAT_MAX);
    float halfChord = sqrt(halfChordSquared);
    // The leaf's box holds the object, not its tolerance: widened by the margin along the ray.
    return vec2(max(along - halfChord, box.x - margin), min(along + halfChord, box.y + margin));
}

// Whether the marched object of `entry` (an entry of the objects' list) comes first in the
// ray's order after (afterT, afterObject) and before (next's stretch, next): the order of
// the stretches' starts, ties by index.
void considerMarchedObject(int entry, vec2 box, vec3 origin, vec3 direction, float tolerance0,
                           float growth, uint mask, float tMin, float tMax, float afterT,
                           int afterObject, inout int next, inout vec2 stretch)
{
    int object = -1 - entry;
    if (entry >= 0 || !objectInMask(object, mask))
        return;
    vec2 candidate = marchedObjectStretch(object, origin, direction, tolerance0, growth, box);
    candidate = vec2(max(candidate.x, tMin), min(candidate.y, tMax));
    if (candidate.x > candidate.y)
        return;
    bool after = candidate.x > afterT || (candidate.x == afterT && object > afterObject);
    bool before = candidate.x < stretch.x || (candidate.x == stretch.x && object < next);
    if (after && before) {
        next = object;
        stretch = candidate;
    }
}

// The marched object of `mask` (objects k < 32 whose bit is clear are left out) that the ray
// (unit direction) comes near first within [tMin, tMax] after (afterT, afterObject), in the
// order of where it comes near them: called again with the answer, it gives the next, so the
// ray's marches go front to back, and a caller that keeps the nearest hit as tMax stops as
// soon as no object begins before it. One walk of the hierarchy (slab tests only) per object;
// -1 when there are no more. `stretch` receives the object's stretch within [tMin, tMax].
// Nodes that hold no marched object are skipped, and so are nodes the ray crosses only
// before afterT (an object there cannot be crossed after it) or after the best so far.
int nextMarchedObject(vec3 origin, vec3 direction, float tolerance0, float growth, uint mask,
                      float tMin, float tMax, float afterT, int afterObject, out vec2 stretch)
{
    int next = -1;
    stretch = vec2(FLOAT_MAX, -FLOAT_MAX);
    vec2 everywhere = vec2(-FLOAT_MAX, FLOAT_MAX);
    for (int k = 0; k < HIERARCHY_UNBOUNDED_COUNT && unboundedIterationAllowed(); ++k)
        considerMarchedObject(listedObject(k), everywhere, origin, direction, tolerance0,
                              growth, mask, tMin, tMax, afterT, afterObject, next, stretch);
    vec3 parallel = hierarchyParallel(direction);
    vec3 inverseDirection = hierarchyInverse(direction, parallel);
    int node = HIERARCHY_HAS_NODES != 0 ? 0 : -1;
    while (node >= 0 && loopIterationAllowed()) {
        ivec4 link = hierarchyLink(node);
        vec2 box = rayNodeInterval(node, origin, inverseDirection, parallel);
        // A tolerance's margin around the box (marchedObjectStretch): at most this much.
        float margin = 1.25 * (tolerance0 + growth * max(box.y, 0.0)) / (1.0 - min(growth, 0.5));
        if (link.w == 0 || max(box.x - margin, max(tMin, afterT)) >
                               min(box.y + margin, min(tMax, stretch.x))) {
            node = link.x;
            continue;
        }
        for (int k = link.y; k < link.y + link.z; ++k)  // at most kMostObjectsPerLeaf: uncounted
            considerMarchedObject(listedObject(k), box, origin, direction, tolerance0, growth,
                                  mask, tMin, tMax, afterT, afterObject, next, stretch);
        node = link.z > 0 ? link.x : node + 1;
    }
    return next;
}
