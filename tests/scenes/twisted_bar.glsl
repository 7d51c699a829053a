// A test user SDF: a square bar along y, twisted about its axis by 1.5 radians per unit of
// height. Twisting stretches the field sideways by up to sqrt(1 + (1.5 r)^2) at radius r;
// the bar's corners lie within r = 0.35 * sqrt(2) of the axis, so the factor is below 1.5.
// @bound 1.2
// @lipschitz 1.5

float twisted_bar(vec3 p, vec3 x)
{
    vec3 q = p - x;
    float angle = 1.5 * q.y;
    float c = cos(angle);
    float s = sin(angle);
    q.xz = mat2(c, -s, s, c) * q.xz;
    return sdBox(q, vec3(0.35, 0.8, 0.35));
}
