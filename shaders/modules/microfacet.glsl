// GGX microfacets: the distribution of normals, Smith's masking-shadowing and the sampling
// of visible normals that the rough materials (materials.glsl) are built from. Isotropic,
// of roughness alpha (the width of the slope distribution: alpha -> 0 is a smooth surface).
// Vectors are in a local frame whose z is the macro surface's normal (basisAround); the
// view `wo` is above it (wo.z > 0).
//
// Compiled only into shaders of scenes with a microfacet material (HAS_MICROFACET).

#if HAS_MICROFACET

// Below this alpha the distribution's peak, 1 / (pi alpha^2), and the sampled normals lose
// their digits in float; a finish may ask for less (the parser takes any alpha > 0), and is
// then as sharp as this.
const float kMinimumGgxAlpha = 1e-4;

// gMasking (--masking): MASKING_SEPARABLE for Smith's separable masking-shadowing
// G1(wo) G1(wi), to compare with renderers that use it (Mitsuba 3); MASKING_CORRELATED for
// the height-correlated one (the default, below). gEnergyCompensation (rough conductors
// only): false for single scattering only.

float ggxAlpha(float roughness)
{
    return max(roughness, kMinimumGgxAlpha);
}

// D(m), the GGX (Trowbridge-Reitz) density of microfacet normals per projected area (Walter
// et al. 2007, eq. 33): alpha^2 / (pi cos^4 (alpha^2 + tan^2)^2), written as
// alpha^2 / (pi (x^2 + y^2 + alpha^2 z^2)^2) for unit m, which keeps its digits near the
// normal when alpha is small (sin^2 = x^2 + y^2 is not computed as 1 - cos^2).
float ggxDistribution(vec3 m, float alpha)
{
    if (m.z <= 0.0)
        return 0.0;
    float alpha2 = alpha * alpha;
    float t = dot(m.xy, m.xy) + alpha2 * m.z * m.z;
    return alpha2 / (PI * t * t);
}

// Smith's Lambda for GGX (Heitz 2014, "Understanding the Masking-Shadowing Function", eq.
// 72): (sqrt(1 + alpha^2 tan^2) - 1) / 2, written as x / (2 (1 + sqrt(1 + x))) with
// x = alpha^2 tan^2, which does not cancel for small x. w on either side of the surface.
float ggxLambda(vec3 w, float alpha)
{
    float cos2 = w.z * w.z;
    if (cos2 == 0.0)
        return FLOAT_MAX;
    float x = alpha * alpha * dot(w.xy, w.xy) / cos2;
    return x / (2.0 * (1.0 + sqrt(1.0 + x)));
}

// G1(w): the fraction of the microfacets' projected area that direction w sees.
float ggxMasking(vec3 w, float alpha)
{
    return 1.0 / (1.0 + ggxLambda(w, alpha));
}

// G2(wo, wi), height-correlated masking-shadowing (Heitz 2014, eq. 99): a point hidden from
// wo is likelier hidden from wi too, which the separable G1 G1 (eq. 98) ignores, so the
// separable form darkens rough surfaces at grazing angles (an alpha = 1 silver ball by 11 %
// near its rim; docs/ACCURACY.md).
float ggxMaskingShadowing(vec3 wo, vec3 wi, float alpha)
{
    float lambdaO = ggxLambda(wo, alpha);
    float lambdaI = ggxLambda(wi, alpha);
    return gMasking == MASKING_SEPARABLE ? 1.0 / ((1.0 + lambdaO) * (1.0 + lambdaI))
                                  : 1.0 / (1.0 + lambdaO + lambdaI);
}

// G2 / G1(wo): the weight of a direction sampled from the visible normals of wo, written
// without the two divisions of the quotient.
float ggxShadowingGivenMasking(vec3 wo, vec3 wi, float alpha)
{
    float lambdaO = ggxLambda(wo, alpha);
    float lambdaI = ggxLambda(wi, alpha);
    return gMasking == MASKING_SEPARABLE ? 1.0 / (1.0 + lambdaI)
                                  : (1.0 + lambdaO) / (1.0 + lambdaO + lambdaI);
}

// A normal m from the distribution of normals visible from wo, D_wo(m) =
// G1(wo) max(0, wo.m) D(m) / wo.z (Heitz 2018, "Sampling the GGX Distribution of Visible
// Normals", JCGT 7(4)): wo is stretched into the configuration of alpha = 1, whose visible
// normals are those of a hemisphere; they are drawn there as Dupuy and Benyoub do ("Sound
// and Complete Visible Normal Sampling", 2023, section 3): a point c uniform on the
// spherical cap z >= -v.z of the unit sphere, and m = normalize(c + v), which is the
// hemisphere's visible normal with the right density; then m is stretched back. `u` is
// uniform on [0, 1)^2. Returns a zero vector in the rare case (c = -v) with no normal.
vec3 sampleGgxVisibleNormal(vec2 u, vec3 wo, float alpha)
{
    vec3 v = normalize(vec3(alpha * wo.xy, wo.z));
    float phi = TWO_PI * u.x;
    float z = (1.0 - u.y) * (1.0 + v.z) - v.z;
    float sinTheta = sqrt(clamp(1.0 - z * z, 0.0, 1.0));
    vec3 m = vec3(sinTheta * cos(phi), sinTheta * sin(phi), z) + v;
    vec3 unstretched = vec3(alpha * m.xy, max(m.z, 0.0));
    float length2 = dot(unstretched, unstretched);
    return length2 > 0.0 ? unstretched * inversesqrt(length2) : vec3(0.0);
}

// The density D_wo(m) with which sampleGgxVisibleNormal draws m, per solid angle of m.
float ggxVisibleNormalPdf(vec3 wo, vec3 m, float alpha)
{
    float cosOM = dot(wo, m);
    if (cosOM <= 0.0 || wo.z <= 0.0)
        return 0.0;
    return ggxMasking(wo, alpha) * cosOM * ggxDistribution(m, alpha) / wo.z;
}

#if HAS_ROUGH_CONDUCTOR
// --- energy compensation ---------------------------------------------------------------
// A GGX surface reflects only the light that leaves after one bounce between microfacets;
// what bounces more is lost, up to 69 % at alpha = 1 and normal incidence for a white
// conductor (ggx_albedo_table.glsl). Turquin ("Practical multiple scattering compensation
// for microfacet models", 2019, eq. 15-16) scales the lobe by 1 + F0 (1 - E(mu_o)) / E(mu_o),
// with E the albedo of the lobe with a Fresnel of 1: a white conductor then reflects all
// it receives, and a coloured one gains in proportion to its colour, as the light that
// bounces more is reflected more times. The factor depends on wo only, so sampling and
// densities are unchanged.

// E(mu, alpha), bilinear in the table; beyond its first and last mu nodes, their values.
float ggxDirectionalAlbedo(float cosTheta, float alpha)
{
    const int n = kGgxAlbedoSize;
    vec2 x = vec2(clamp(cosTheta * float(n) - 0.5, 0.0, float(n - 1)),
                  clamp(alpha, 0.0, 1.0) * float(n - 1));
    ivec2 i = min(ivec2(x), ivec2(n - 2));
    vec2 f = x - vec2(i);
    int at = i.y * n + i.x;
    float low = mix(kGgxAlbedo[at], kGgxAlbedo[at + 1], f.x);
    float high = mix(kGgxAlbedo[at + n], kGgxAlbedo[at + n + 1], f.x);
    return mix(low, high, f.y);
}

// The factor of the lobe, for a view at cosine cosO and the reflectance `normalReflectance`
// at normal incidence.
vec3 ggxEnergyCompensation(vec3 normalReflectance, float cosO, float alpha)
{
    if (!gEnergyCompensation)
        return vec3(1.0);
    float albedo = ggxDirectionalAlbedo(cosO, alpha);
    return 1.0 + normalReflectance * ((1.0 - albedo) / albedo);
}
#endif
#endif


