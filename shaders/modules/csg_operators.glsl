// Constructive solid geometry on distances. Union of exact distances is exact outside the
// solid; every other operator gives a BOUND. All keep the Lipschitz factor of their operands
// (at most 1 here), so sphere tracing stays safe.

float opUnion(float a, float b)
{
    return min(a, b);
}

float opIntersection(float a, float b)
{
    return max(a, b);
}

float opDifference(float a, float b)
{
    return max(a, -b);
}

// The seed's exponential smooth minimum, -log(exp(-k a) + exp(-k b)) / k, rewritten as
// min(a, b) - log(1 + exp(-k |a - b|)) / k: the same value, but no exponential can overflow
// or underflow to a log(0) whatever the sharpness k (1e-4 or 1e4) and the distances. Its
// gradient is a convex combination of the operands' gradients, so it is 1-Lipschitz.
float opSmoothUnionExp(float a, float b, float k)
{
    return min(a, b) - log(1.0 + exp(-k * abs(a - b))) / k;
}

float opSmoothIntersectionExp(float a, float b, float k)
{
    return -opSmoothUnionExp(-a, -b, k);
}

float opSmoothDifferenceExp(float a, float b, float k)
{
    return opSmoothIntersectionExp(a, -b, k);
}

// Polynomial smooth minimum with blend radius r (Quilez, "smooth minimum", quadratic
// kernel): equal to min(a, b) where the operands differ by more than r.
float opSmoothUnionPoly(float a, float b, float radius)
{
    if (radius <= 0.0)
        return min(a, b);
    float h = max(radius - abs(a - b), 0.0) / radius;
    return min(a, b) - h * h * radius * 0.25;
}

float opSmoothIntersectionPoly(float a, float b, float radius)
{
    return -opSmoothUnionPoly(-a, -b, radius);
}

float opSmoothDifferencePoly(float a, float b, float radius)
{
    return opSmoothIntersectionPoly(a, -b, radius);
}
