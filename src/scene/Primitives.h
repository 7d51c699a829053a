#pragma once
// The primitive kinds, each described once: its values, its keyword in the scene format and
// how they are read, its bounding sphere, how its numbers are laid out for the GPU (vec4s in
// uShapeParameters) and its distance in GLSL, written over those vec4s. Everything else
// derives from these descriptions (scene/PrimitiveKinds.h): the parser's words, the
// primitive codes the shaders receive as generated #defines, the generated distance calls
// and the general shader's interpreter switch.
//
// Adding a primitive: its struct and its Primitive<> description here, its name in
// PrimitiveTypes, and its distance function in shaders/modules/sdf_primitives.glsl (and its
// exact intersection in exact_shapes.glsl, where it has one). A kind listed without a
// description does not compile; tests/scene/PrimitiveKindsTest.cpp walks every kind for the
// rest (keyword, GLSL function, parameter slots).
#include "scene/TokenCursor.h"
#include "scene/Transform.h"

#include <glm/glm.hpp>

#include <array>
#include <cmath>
#include <vector>

namespace scene {

template <typename... Types>
struct TypeList {
};

// Bounding sphere of one shape; infinite shapes (planes, cones) have none.
struct ShapeBound {
    bool finite = false;
    glm::vec3 center{0.0f};
    float radius = 0.0f;
};

inline ShapeBound finiteBound(const glm::vec3& center, float radius)
{
    return {true, center, radius};
}

// The description of primitive kind P, with these members:
//   keyword      the word that starts it in a scene file
//   read         reads the numbers after the keyword, checking them
//   bound        its bounding sphere in its own frame (ShapeBound{} where it is infinite)
//   parameters   its numbers as the shaders read them: a std::array of vec4s, or a
//                std::vector of them for a kind that is the union of one term per vec4
//   distance     the GLSL distance at p, in which $0, $1, ... stand for its vec4s (for a
//                union of terms, $0 for each term's own)
// and, for a kind that rays may meet by exact intersection instead of marching it
// (shaders/modules/exact_shapes.glsl), these:
//   exact        the GLSL call that meets it, up to its tMin argument, over the ray (o, d)
//                in its parameters' frame and its vec4s $0, $1, ...; the generators complete
//                it with `tMin, object, hit)`. The call returns whether it met the shape.
//   exactSetup, exactTerm   for a union of terms: a declaration before the terms, and the
//                statement each term's vec4 ($0) adds before `exact`
//   parametersInWorld(P, Transform)   where a similarity maps the shape to one of its kind:
//                its parameters in world space, where rays then meet it. A kind without it
//                is met in its own frame, the ray taken there and the hit brought back.
//   metExactly(P), metExactlyGlsl, exactLimit   where the closed form is not to be trusted
//                for some of the kind's shapes: whether it is for this one, in C++ and in
//                GLSL over $k, and for messages the shapes it is not
//   marchedOnRequest   true: ShaderBuild::marchBoxesCylindersAndDisks marches it instead,
//                so that the sphere tracer can be judged against its exact intersection
// Only declared: a kind without a description fails to compile.
template <typename P>
struct Primitive;

struct Sphere {
    glm::vec3 center{0.0f};
    float radius = 1.0f;
};

template <>
struct Primitive<Sphere> {
    static constexpr const char* keyword = "sphere";
    static constexpr const char* distance = "sdSphere(p - $0.xyz, $0.w)";
    static Sphere read(TokenCursor& in)
    {
        Sphere sphere;
        sphere.center = in.vector3("sphere centre");
        // A sphere of radius 0 has no surface: it could only show as a speck the size of the
        // hit tolerance, so it is refused rather than drawn wrongly.
        sphere.radius = in.positiveNumber("sphere radius");
        return sphere;
    }
    static ShapeBound bound(const Sphere& sphere)
    {
        return finiteBound(sphere.center, sphere.radius);
    }
    static std::array<glm::vec4, 1> parameters(const Sphere& sphere)
    {
        return {glm::vec4(sphere.center, sphere.radius)};
    }
    static constexpr const char* exact = "exactSphere(o, d, $0, ";
    static std::array<glm::vec4, 1> parametersInWorld(const Sphere& sphere, const Transform& t)
    {
        return {glm::vec4(applyTransform(t, sphere.center), t.scale * sphere.radius)};
    }
};

// Union of the solid half-spaces dot(normal, x) + offset <= 0, as written (not normalised).
struct Polyhedron {
    std::vector<glm::vec4> planes;
};

template <>
struct Primitive<Polyhedron> {
    static constexpr const char* keyword = "polyhedron";
    static constexpr const char* distance = "sdHalfSpace(p, $0)";
    static Polyhedron read(TokenCursor& in)
    {
        Polyhedron polyhedron;
        const std::size_t countToken = in.mark();
        const int planes = in.count("number of polyhedron planes");
        if (planes == 0)
            in.failAtMark(countToken, "at least one plane in the polyhedron");
        for (int j = 0; j < planes; ++j) {
            const std::string plane =
                "plane " + std::to_string(j + 1) + " of " + std::to_string(planes);
            const std::size_t first = in.mark();
            const glm::vec3 normal = in.vector3(plane + " normal (a b c)");
            const float offset = in.number(plane + " offset d");
            if (!(glm::length(normal) > 0.0f))
                in.failAtMark(first, "a plane normal (a b c) that is not zero");
            polyhedron.planes.emplace_back(normal, offset);
        }
        return polyhedron;
    }
    static ShapeBound bound(const Polyhedron&) { return {}; }
    // Unit normals: the distance to a plane is then one dot product.
    static std::vector<glm::vec4> parameters(const Polyhedron& polyhedron)
    {
        std::vector<glm::vec4> planes;
        for (const glm::vec4& plane : polyhedron.planes)
            planes.push_back(plane / glm::length(glm::vec3(plane)));
        return planes;
    }
    // The ray's interval outside every half-space is clipped plane by plane.
    static constexpr const char* exactSetup = "ConvexInterval outside = wholeRay();";
    static constexpr const char* exactTerm = "clipOutsideHalfSpace(outside, o, d, $0);";
    static constexpr const char* exact = "exactHalfSpaceUnion(outside, ";
    static std::vector<glm::vec4> parametersInWorld(const Polyhedron& polyhedron,
                                                    const Transform& t)
    {
        std::vector<glm::vec4> planes;
        for (const glm::vec4& plane : parameters(polyhedron))
            planes.push_back(applyTransformToPlane(t, plane));
        return planes;
    }
};

struct Box {
    glm::vec3 center{0.0f};
    glm::vec3 halfExtents{1.0f};
};

template <>
struct Primitive<Box> {
    static constexpr const char* keyword = "box";
    static constexpr const char* distance = "sdBox(p - $0.xyz, $1.xyz)";
    static Box read(TokenCursor& in)
    {
        Box box;
        box.center = in.vector3("box centre");
        const std::size_t first = in.mark();
        box.halfExtents.x = in.numberAtLeast("box half-extent x", 0.0f);
        box.halfExtents.y = in.numberAtLeast("box half-extent y", 0.0f);
        box.halfExtents.z = in.numberAtLeast("box half-extent z", 0.0f);
        // One zero extent leaves a rectangle, a surface; two leave a line, which has none.
        const int zeros =
            (box.halfExtents.x == 0.0f) + (box.halfExtents.y == 0.0f) + (box.halfExtents.z == 0.0f);
        if (zeros > 1)
            in.failAtMark(first, "box half-extents of which at most one is zero");
        return box;
    }
    static ShapeBound bound(const Box& box)
    {
        return finiteBound(box.center, glm::length(box.halfExtents));
    }
    static std::array<glm::vec4, 2> parameters(const Box& box)
    {
        return {glm::vec4(box.center, 0.0f), glm::vec4(box.halfExtents, 0.0f)};
    }
    static constexpr const char* exact = "exactBox(o, d, $0.xyz, $1.xyz, ";
    static constexpr bool marchedOnRequest = true;
};

struct Torus {
    glm::vec3 center{0.0f};
    float majorRadius = 1.0f;
    float minorRadius = 0.25f;
};

template <>
struct Primitive<Torus> {
    static constexpr const char* keyword = "torus";
    static constexpr const char* distance = "sdTorus(p - $0.xyz, $0.w, $1.x)";
    static Torus read(TokenCursor& in)
    {
        Torus torus;
        torus.center = in.vector3("torus centre");
        torus.majorRadius = in.numberAtLeast("torus major radius", 0.0f);
        torus.minorRadius = in.positiveNumber("torus minor radius");
        return torus;
    }
    static ShapeBound bound(const Torus& torus)
    {
        return finiteBound(torus.center, torus.majorRadius + torus.minorRadius);
    }
    static std::array<glm::vec4, 2> parameters(const Torus& torus)
    {
        return {glm::vec4(torus.center, torus.majorRadius),
                glm::vec4(torus.minorRadius, 0.0f, 0.0f, 0.0f)};
    }
    static constexpr const char* exact = "exactTorus(o, d, $0.xyz, $0.w, $1.x, ";
    // Tori thinner than this (minor over major radius) are not met exactly: float32 leaves
    // their quartic too few digits (roots off by up to half the minor radius at 0.002, and
    // some missed; at most 1.7 % of it from 0.05 to 0.1, 0.7 % from 0.1 to 0.2, and none
    // missed, over 3000 rays from up to 200 sizes away). THINNEST_EXACT_TORUS in GLSL.
    static constexpr float kThinnestExact = 0.1f;
    static bool metExactly(const Torus& torus)
    {
        return torus.minorRadius >= kThinnestExact * torus.majorRadius;
    }
    static constexpr const char* metExactlyGlsl = "$1.x >= THINNEST_EXACT_TORUS * $0.w";
    static constexpr const char* exactLimit =
        "its minor radius is under a tenth of its major radius (its quartic loses too many "
        "digits in float32)";
};

// Infinite cone, apex at `apex`, axis y, opening towards -y; `slope` is the format's (a, b).
struct Cone {
    glm::vec3 apex{0.0f};
    glm::vec2 slope{1.0f, 1.0f};
};

template <>
struct Primitive<Cone> {
    static constexpr const char* keyword = "cone";
    static constexpr const char* distance = "sdConeBound(p - $0.xyz, $1.xy)";
    static Cone read(TokenCursor& in)
    {
        Cone cone;
        cone.apex = in.vector3("cone apex");
        const std::size_t first = in.mark();
        cone.slope.x = in.number("cone slope a");
        cone.slope.y = in.number("cone slope b");
        if (!(glm::length(cone.slope) > 0.0f))
            in.failAtMark(first, "a cone slope (a b) that is not zero");
        return cone;
    }
    static ShapeBound bound(const Cone&) { return {}; }
    static std::array<glm::vec4, 2> parameters(const Cone& cone)
    {
        const glm::vec2 unit = glm::normalize(cone.slope);
        return {glm::vec4(cone.apex, 0.0f), glm::vec4(unit.x, unit.y, 0.0f, 0.0f)};
    }
    static constexpr const char* exact = "exactCone(o, d, $0.xyz, $1.xy, ";
};

struct Cylinder {
    glm::vec3 center{0.0f};
    float radius = 1.0f;
    float halfHeight = 1.0f;
};

template <>
struct Primitive<Cylinder> {
    static constexpr const char* keyword = "cylinder";
    static constexpr const char* distance = "sdCappedCylinder(p - $0.xyz, $0.w, $1.x)";
    static Cylinder read(TokenCursor& in)
    {
        Cylinder cylinder;
        cylinder.center = in.vector3("cylinder centre");
        cylinder.radius = in.positiveNumber("cylinder radius");
        cylinder.halfHeight = in.numberAtLeast("cylinder half-height", 0.0f);
        return cylinder;
    }
    static ShapeBound bound(const Cylinder& cylinder)
    {
        return finiteBound(cylinder.center, std::sqrt(cylinder.radius * cylinder.radius +
                                                      cylinder.halfHeight * cylinder.halfHeight));
    }
    static std::array<glm::vec4, 2> parameters(const Cylinder& cylinder)
    {
        return {glm::vec4(cylinder.center, cylinder.radius),
                glm::vec4(cylinder.halfHeight, 0.0f, 0.0f, 0.0f)};
    }
    static constexpr const char* exact = "exactCappedCylinder(o, d, $0.xyz, $0.w, $1.x, ";
    static constexpr bool marchedOnRequest = true;
};

struct Disk {
    glm::vec3 center{0.0f};
    glm::vec3 normal{0.0f, 1.0f, 0.0f};  // as written, not normalised
    float radius = 1.0f;
};

template <>
struct Primitive<Disk> {
    static constexpr const char* keyword = "disk";
    static constexpr const char* distance = "sdDisk(p - $0.xyz, $1.xyz, $0.w)";
    static Disk read(TokenCursor& in)
    {
        Disk disk;
        disk.center = in.vector3("disk centre");
        const std::size_t first = in.mark();
        disk.normal = in.vector3("disk normal");
        if (!(glm::length(disk.normal) > 0.0f))
            in.failAtMark(first, "a disk normal that is not zero");
        disk.radius = in.positiveNumber("disk radius");
        return disk;
    }
    static ShapeBound bound(const Disk& disk) { return finiteBound(disk.center, disk.radius); }
    static std::array<glm::vec4, 2> parameters(const Disk& disk)
    {
        return {glm::vec4(disk.center, disk.radius), glm::vec4(glm::normalize(disk.normal), 0.0f)};
    }
    static constexpr const char* exact = "exactDisk(o, d, $0, $1.xyz, ";
    static std::array<glm::vec4, 2> parametersInWorld(const Disk& disk, const Transform& t)
    {
        return {glm::vec4(applyTransform(t, disk.center), t.scale * disk.radius),
                glm::vec4(t.rotation * glm::normalize(disk.normal), 0.0f)};
    }
    static constexpr bool marchedOnRequest = true;
};

// A box whose edges and corners are rounded with `radius`: the set of points within `radius`
// of the box shrunk by `radius`, so that it still fits the box of `halfExtents`.
struct RoundedBox {
    glm::vec3 center{0.0f};
    glm::vec3 halfExtents{1.0f};
    float radius = 0.0f;
};

template <>
struct Primitive<RoundedBox> {
    static constexpr const char* keyword = "rounded_box";
    static constexpr const char* distance = "sdRoundedBox(p - $0.xyz, $1.xyz, $0.w)";
    static RoundedBox read(TokenCursor& in)
    {
        RoundedBox box;
        box.center = in.vector3("rounded box centre");
        box.halfExtents.x = in.positiveNumber("rounded box half-extent x");
        box.halfExtents.y = in.positiveNumber("rounded box half-extent y");
        box.halfExtents.z = in.positiveNumber("rounded box half-extent z");
        const std::size_t radiusToken = in.mark();
        box.radius = in.numberAtLeast("rounded box edge radius", 0.0f);
        const float smallest =
            glm::min(box.halfExtents.x, glm::min(box.halfExtents.y, box.halfExtents.z));
        if (box.radius > smallest)
            in.failAtMark(radiusToken, "an edge radius of at most the smallest half-extent, " +
                                           TokenCursor::formatNumber(smallest));
        return box;
    }
    static ShapeBound bound(const RoundedBox& box)
    {
        return finiteBound(box.center, glm::length(box.halfExtents));
    }
    static std::array<glm::vec4, 2> parameters(const RoundedBox& box)
    {
        return {glm::vec4(box.center, box.radius), glm::vec4(box.halfExtents, 0.0f)};
    }
};

// Every primitive kind, in the order of their codes.
using PrimitiveTypes = TypeList<Sphere, Polyhedron, Box, Torus, Cone, Cylinder, Disk, RoundedBox>;

}  // namespace scene
