// What the crossing walks of CSG solids (shadergen/ExactCsgIntersection.h, generated into the
// --exact-geometry shader) share: where the search for the next leaf crossing starts, a point
// beyond every crossing, and the outward normal.

// The next crossing is searched for a few units in the last place beyond this one: a leaf
// met in its own frame finds the same root again from a tMin that rounding moved a little
// below it. Crossings closer than that are taken together, as one.
float exactCsgNextStart(float t)
{
    return t + max(4e-7 * abs(t), 0.01 * gMinimumHitDistance);
}

// A point of the ray past its last leaf crossing, where the ray stays on one side of every
// leaf: a scene's size (1e5 gMinimumHitDistance) or t further on.
float exactCsgBeyondEveryCrossing(float t)
{
    return t + max(t, 1e5 * gMinimumHitDistance);
}

// The solid's outward normal where the ray enters it (against the ray) or leaves it (along
// the ray), from the crossed leaf's normal, which points out of that leaf: out of the solid
// where the leaf adds to it, into it where the leaf is subtracted.
vec3 exactCsgOutward(vec3 leafNormal, vec3 direction, bool entering)
{
    return (dot(leafNormal, direction) < 0.0) == entering ? leafNormal : -leafNormal;
}
