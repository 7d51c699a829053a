// The user SDF of user-sdf-against-wall.in: a square column of half-side 0.3 and half-height
// 0.9, twisted about its axis (y) by 1 radian per unit of height. Twisting is no isometry:
// at distance r from the axis the field may overestimate the distance by the largest
// singular value of the twist's Jacobian, (r + sqrt(r^2 + 4)) / 2, at most 1.7 within the
// bound below (r <= 1.05), so 2 is safe (see scenes/examples/twisted_column.glsl).
// @bound 1.05
// @lipschitz 2

float twisted_pillar(vec3 p, vec3 x)
{
    vec3 q = p - x;
    float angle = q.y;
    float c = cos(angle);
    float s = sin(angle);
    q.xz = mat2(c, -s, s, c) * q.xz;
    return sdBox(q, vec3(0.3, 0.9, 0.3));
}
