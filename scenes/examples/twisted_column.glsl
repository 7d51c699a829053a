// The user SDF of user-sdf-lipschitz.in: a square column of half-side 0.3 and half-height
// 0.9, twisted about its axis (y) by 1.2 radians per unit of height.
//
// Twisting is not an isometry, so sdBox of the twisted point is not a bound. The twist's
// Jacobian at distance r from the axis is a rotation times [[I, v], [0, 1]] with |v| = 1.2 r,
// whose largest singular value is (1.2 r + sqrt((1.2 r)^2 + 4)) / 2: the field may
// overestimate the distance by that factor. Within the bound below (r <= 1.05) it is
// at most 1.81, so 2 is safe.
// @bound 1.05
// @lipschitz 2

float twisted_column(vec3 p, vec3 x)
{
    vec3 q = p - x;
    float angle = 1.2 * q.y;
    float c = cos(angle);
    float s = sin(angle);
    q.xz = mat2(c, -s, s, c) * q.xz;
    return sdBox(q, vec3(0.3, 0.9, 0.3));
}
