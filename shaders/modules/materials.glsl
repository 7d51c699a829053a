// Materials (the scene format's finishes) as BSDFs. Directions point away from the surface:
// `wo` towards where the path came from, `wi` towards where it goes next. Evaluations exclude
// the cosine; sample weights are f * cos / pdf.
//
// Each material's functions, named by its prefix in the material table (scene/Materials.h):
//   BsdfSample <prefix>Sample(Surface s, vec3 wo, float uLobe, vec2 uDirection)
//   vec3 <prefix>Evaluate(Surface s, vec3 wo, vec3 wi)   not for a delta (mirror, glass)
//   float <prefix>Pdf(Surface s, vec3 wo, vec3 wi)       not for a delta
// isDeltaMaterial and the dispatchers bsdfSample, bsdfEvaluate and bsdfPdf are generated
// from that table (render/KindDispatchers.cpp) and follow this module.

struct Surface {
    vec3 position;
    vec3 normal;         // outward normal of the object
    // The normal on the side the ray arrived from, tilted if need be so that wo is above
    // it: a ray that grazes a silhouette within the hit tolerance, without crossing it,
    // then reflects onwards (as a true near miss would continue) instead of scattering into
    // the solid it never entered.
    vec3 facingNormal;
    bool entering;       // the ray arrived from outside the solid
    vec3 color;          // the pigment at this point
    vec3 emission;
    int material;
    float phongExponent;
    float ior;
    int lightIndex;      // this object's sphere light, or -1
#if HAS_MICROFACET
    float roughness;     // GGX alpha
#endif
#if HAS_ROUGH_CONDUCTOR
    bool complexIor;     // the conductor's Fresnel: the complex index below, or else Schlick's
    vec3 conductorEta;
    vec3 conductorK;
#endif
};

struct BsdfSample {
    bool valid;
    vec3 direction;
    vec3 weight;   // f * |cos| / pdf
    float pdf;     // solid-angle density; meaningless for delta lobes
    bool isDelta;  // mirror and glass: a single direction, not reachable by light sampling
    // The radiance scaling (eta_o / eta_i)^2 included in `weight` by a refraction, 1
    // otherwise. It is no loss or gain of energy (leaving the medium undoes it), so Russian
    // roulette must not read it as one (PBRT 3e, section 16.1.3: etaScale).
    float radianceScale;
};

BsdfSample invalidSample()
{
    return BsdfSample(false, vec3(0.0), vec3(0.0), 0.0, false, 1.0);
}

// --- Blinn-Phong ---------------------------------------------------------------------------
// f = F * f_lobe + (1 - F) * color / pi, with Schlick's F at the viewing angle (R0 = the
// pigment) splitting energy between a glossy lobe and a diffuse base. The lobe is Blinn's
// half-vector distribution normalised as in Ashikhmin and Shirley (2000):
//   f_lobe = (n + 1) / (8 pi) * cos(theta_h)^n / ((wi.h) * max(cos_i, cos_o)).
// Its albedo is at most 1 (f_lobe * cos_i = pdf(wi) * cos_i / max(cos_i, cos_o)), so with a
// pigment of at most 1 the material never creates energy, whatever the exponent.

#if HAS_BLINN_PHONG
float blinnPhongSpecularProbability(vec3 fresnel)
{
    return clamp(averageComponent(fresnel), 0.0, 1.0);
}

vec3 blinnPhongEvaluate(Surface s, vec3 wo, vec3 wi)
{
    vec3 n = s.facingNormal;
    float cosO = dot(n, wo);
    float cosI = dot(n, wi);
    if (cosO <= 0.0 || cosI <= 0.0)
        return vec3(0.0);
    vec3 fresnel = schlickFresnel(s.color, cosO);
    vec3 h = normalize(wi + wo);
    float hDotI = dot(h, wi);
    float lobe = 0.0;
    if (hDotI > 1e-7)
        lobe = (s.phongExponent + 1.0) / (8.0 * PI) *
               pow(clamp(dot(n, h), 0.0, 1.0), s.phongExponent) / (hDotI * max(cosI, cosO));
    return fresnel * lobe + (1.0 - fresnel) * s.color * INV_PI;
}

float blinnPhongPdf(Surface s, vec3 wo, vec3 wi)
{
    vec3 n = s.facingNormal;
    float cosO = dot(n, wo);
    float cosI = dot(n, wi);
    if (cosO <= 0.0 || cosI <= 0.0)
        return 0.0;
    float specular = blinnPhongSpecularProbability(schlickFresnel(s.color, cosO));
    vec3 h = normalize(wi + wo);
    float hDotI = dot(h, wi);
    float lobePdf = hDotI > 1e-7
                        ? blinnPhongHalfVectorPdf(dot(n, h), s.phongExponent) / (4.0 * hDotI)
                        : 0.0;
    return specular * lobePdf + (1.0 - specular) * cosineHemispherePdf(cosI);
}

// Chooses the glossy lobe with the Fresnel's probability, else the cosine-weighted diffuse
// one; the weight uses the density of the mixture, so either choice is unbiased.
BsdfSample blinnPhongSample(Surface s, vec3 wo, float uLobe, vec2 uDirection)
{
    vec3 n = s.facingNormal;
    float cosO = dot(n, wo);
    if (cosO <= 0.0)
        return invalidSample();
    mat3 frame = basisAround(n);
    float specular = blinnPhongSpecularProbability(schlickFresnel(s.color, cosO));
    vec3 wi;
    if (uLobe < specular) {
        vec3 h = frame * sampleBlinnPhongHalfVector(uDirection, s.phongExponent);
        if (dot(h, wo) <= 0.0)
            return invalidSample();
        wi = reflect(-wo, h);
    } else {
        wi = frame * sampleCosineHemisphere(uDirection);
    }
    float cosI = dot(n, wi);
    if (cosI <= 0.0)
        return invalidSample();
    float pdf = blinnPhongPdf(s, wo, wi);
    if (!(pdf > 0.0))
        return invalidSample();
    return BsdfSample(true, wi, blinnPhongEvaluate(s, wo, wi) * cosI / pdf, pdf, false, 1.0);
}
#endif

// --- Lambertian ----------------------------------------------------------------------------

vec3 lambertianEvaluate(Surface s, vec3 wo, vec3 wi)
{
    return dot(s.facingNormal, wi) > 0.0 ? s.color * INV_PI : vec3(0.0);
}

float lambertianPdf(Surface s, vec3 wo, vec3 wi)
{
    return cosineHemispherePdf(dot(s.facingNormal, wi));
}

BsdfSample lambertianSample(Surface s, vec3 wo, float uLobe, vec2 uDirection)
{
    vec3 n = s.facingNormal;
    vec3 wi = basisAround(n) * sampleCosineHemisphere(uDirection);
    float cosI = dot(n, wi);
    if (cosI <= 0.0)
        return invalidSample();
    // f * cos / pdf = (color / pi) * cos / (cos / pi)
    return BsdfSample(true, wi, s.color, cosineHemispherePdf(cosI), false, 1.0);
}

// --- Mirror --------------------------------------------------------------------------------
// Perfect reflection weighted by Schlick's Fresnel with the pigment as R0.

#if HAS_MIRROR
BsdfSample mirrorSample(Surface s, vec3 wo, float uLobe, vec2 uDirection)
{
    vec3 n = s.facingNormal;
    float cosO = dot(n, wo);
    if (cosO <= 0.0)
        return invalidSample();
    return BsdfSample(true, reflect(-wo, n), schlickFresnel(s.color, cosO), 0.0, true, 1.0);
}
#endif

// --- Dielectric ----------------------------------------------------------------------------
// A smooth interface between air and a medium of index ior, tinted by the pigment on every
// event (as the seed does). Reflection or refraction is chosen with the Fresnel reflectance
// as probability, so the weight is only the tint, except for the radiance scaling
// (eta_o / eta_i)^2 on refraction (Veach 1997, section 5.2; PBRT 3e, section 16.1.3): light
// is compressed entering a denser medium, and the factors of entering and leaving cancel on
// a path through a solid. Total internal reflection reflects.

#if HAS_DIELECTRIC
BsdfSample dielectricSample(Surface s, vec3 wo, float uLobe, vec2 uDirection)
{
    float etaOutgoingSide = s.entering ? 1.0 : s.ior;
    float etaOtherSide = s.entering ? s.ior : 1.0;
    vec3 n = s.facingNormal;
    float cosIncident = dot(n, wo);

    float cosTransmitted;
    float reflectance = dielectricReflectance(cosIncident, etaOutgoingSide, etaOtherSide,
                                              cosTransmitted);
    if (uLobe < reflectance)
        return BsdfSample(true, reflect(-wo, n), s.color, 0.0, true, 1.0);

    float eta = etaOutgoingSide / etaOtherSide;
    vec3 refracted = -eta * wo + (eta * cosIncident - cosTransmitted) * n;
    return BsdfSample(true, normalize(refracted), s.color * (eta * eta), 0.0, true, eta * eta);
}
#endif

// --- Rough conductor ------------------------------------------------------------------------
// A GGX microfacet conductor (Walter et al. 2007, eq. 20): f = F(wo.m) D(m) G2 / (4 cos_o cos_i)
// with m the half vector, Smith's height-correlated G2 and directions drawn from the visible
// normals (microfacet.glsl), scaled by the energy compensation. F is Schlick's with the
// pigment as R0 (alpha -> 0 is then the mirror), or for a metal of complex index the exact
// conductor Fresnel, tinted by the pigment.

#if HAS_ROUGH_CONDUCTOR
vec3 roughConductorFresnel(Surface s, float cosine)
{
    return s.complexIor ? s.color * conductorReflectance(cosine, s.conductorEta, s.conductorK)
                        : schlickFresnel(s.color, cosine);
}

vec3 roughConductorCompensation(Surface s, float cosO, float alpha)
{
    return ggxEnergyCompensation(roughConductorFresnel(s, 1.0), cosO, alpha);
}

vec3 roughConductorEvaluate(Surface s, vec3 wo, vec3 wi)
{
    mat3 frame = basisAround(s.facingNormal);
    vec3 o = wo * frame;
    vec3 i = wi * frame;
    if (o.z <= 0.0 || i.z <= 0.0)
        return vec3(0.0);
    float alpha = ggxAlpha(s.roughness);
    vec3 m = normalize(o + i);
    float lobe = ggxDistribution(m, alpha) * ggxMaskingShadowing(o, i, alpha) / (4.0 * o.z * i.z);
    return roughConductorFresnel(s, dot(o, m)) * lobe * roughConductorCompensation(s, o.z, alpha);
}

// The density of the mirror direction of a visible normal: D_wo(m) / (4 wo.m).
float roughConductorPdf(Surface s, vec3 wo, vec3 wi)
{
    mat3 frame = basisAround(s.facingNormal);
    vec3 o = wo * frame;
    vec3 i = wi * frame;
    if (o.z <= 0.0 || i.z <= 0.0)
        return 0.0;
    vec3 m = normalize(o + i);
    float cosOM = dot(o, m);
    return cosOM > 0.0 ? ggxVisibleNormalPdf(o, m, ggxAlpha(s.roughness)) / (4.0 * cosOM) : 0.0;
}

// The weight f cos / pdf of a visible normal's mirror direction is F G2 / G1(wo): D and the
// cosines cancel.
BsdfSample roughConductorSample(Surface s, vec3 wo, float uLobe, vec2 uDirection)
{
    mat3 frame = basisAround(s.facingNormal);
    vec3 o = wo * frame;
    if (o.z <= 0.0)
        return invalidSample();
    float alpha = ggxAlpha(s.roughness);
    vec3 m = sampleGgxVisibleNormal(uDirection, o, alpha);
    float cosOM = dot(o, m);
    if (!(cosOM > 0.0))
        return invalidSample();
    vec3 i = reflect(-o, m);
    if (i.z <= 0.0)
        return invalidSample();
    float pdf = ggxVisibleNormalPdf(o, m, alpha) / (4.0 * cosOM);
    if (!(pdf > 0.0))
        return invalidSample();
    vec3 weight = roughConductorFresnel(s, cosOM) * ggxShadowingGivenMasking(o, i, alpha) *
                  roughConductorCompensation(s, o.z, alpha);
    return BsdfSample(true, frame * i, weight, pdf, false, 1.0);
}
#endif

// --- Rough dielectric -----------------------------------------------------------------------
// A GGX microfacet interface between air and a medium of index ior (Walter et al. 2007,
// "Microfacet Models for Refraction through Rough Surfaces"), tinted by the pigment on
// every event as the smooth dielectric is; alpha -> 0 is that dielectric. Each microfacet
// reflects with the dielectric Fresnel of its own normal m (Schlick's, or the exact one
// under --fresnel exact, as the smooth glass) and transmits the rest:
//   reflection    f = F D G2 / (4 |cos_o| |cos_i|), m the half vector;
//   transmission  f = (1 - F) D G2 |wo.m| |wi.m| eta_o^2 / (|cos_o| |cos_i| (eta_o wo.m + eta_i wi.m)^2),
// m the generalised half vector (eq. 16) and eta_o, eta_i the indices on wo's and wi's
// sides: eq. 21 with the radiance scaling (eta_o / eta_i)^2 of a refraction, as the smooth
// dielectric has it. Sampling draws a visible normal, then reflection with probability F,
// so that every weight is the tint times G2 / G1(wo) (times the radiance scaling on
// refraction). No energy compensation: what scatters between microfacets more than once is
// lost, most of it inside the medium, where most microfacets reflect totally (a clear sphere
// of index 1.5 in the white furnace reads 0.98, 0.75 and 0.35 at alpha 0.05, 0.3 and 1;
// FurnaceTest).

#if HAS_ROUGH_DIELECTRIC
// The indices of refraction on wo's side and on the other side.
vec2 roughDielectricIndices(Surface s)
{
    return s.entering ? vec2(1.0, s.ior) : vec2(s.ior, 1.0);
}

// The generalised half vector of a refraction between o (index etaO) and i (index etaI) on
// opposite sides, turned to o's side of the surface (z > 0).
vec3 refractionHalfVector(vec3 o, vec3 i, float etaO, float etaI)
{
    vec3 m = normalize(etaO * o + etaI * i);
    return m.z < 0.0 ? -m : m;
}

vec3 roughDielectricEvaluate(Surface s, vec3 wo, vec3 wi)
{
    mat3 frame = basisAround(s.facingNormal);
    vec3 o = wo * frame;
    vec3 i = wi * frame;
    if (o.z <= 0.0 || i.z == 0.0)
        return vec3(0.0);
    float alpha = ggxAlpha(s.roughness);
    vec2 eta = roughDielectricIndices(s);
    float cosTransmitted;
    if (i.z > 0.0) {
        vec3 m = normalize(o + i);
        float fresnel = dielectricReflectance(dot(o, m), eta.x, eta.y, cosTransmitted);
        return s.color * (fresnel * ggxDistribution(m, alpha) * ggxMaskingShadowing(o, i, alpha) /
                          (4.0 * o.z * i.z));
    }
    vec3 m = refractionHalfVector(o, i, eta.x, eta.y);
    float cosOM = dot(o, m);
    float cosIM = dot(i, m);
    if (cosOM <= 0.0 || cosIM >= 0.0)
        return vec3(0.0);
    float fresnel = dielectricReflectance(cosOM, eta.x, eta.y, cosTransmitted);
    float denominator = eta.x * cosOM + eta.y * cosIM;
    return s.color * ((1.0 - fresnel) * ggxDistribution(m, alpha) *
                      ggxMaskingShadowing(o, i, alpha) * abs(cosOM * cosIM) * eta.x * eta.x /
                      (o.z * abs(i.z) * denominator * denominator));
}

// Reflection: F D_wo(m) / (4 wo.m). Transmission: (1 - F) D_wo(m) times the Jacobian of the
// refraction, |dm / dwi| = eta_i^2 |wi.m| / (eta_o wo.m + eta_i wi.m)^2 (Walter, eq. 17).
float roughDielectricPdf(Surface s, vec3 wo, vec3 wi)
{
    mat3 frame = basisAround(s.facingNormal);
    vec3 o = wo * frame;
    vec3 i = wi * frame;
    if (o.z <= 0.0 || i.z == 0.0)
        return 0.0;
    float alpha = ggxAlpha(s.roughness);
    vec2 eta = roughDielectricIndices(s);
    float cosTransmitted;
    if (i.z > 0.0) {
        vec3 m = normalize(o + i);
        float cosOM = dot(o, m);
        if (cosOM <= 0.0)
            return 0.0;
        float fresnel = dielectricReflectance(cosOM, eta.x, eta.y, cosTransmitted);
        return fresnel * ggxVisibleNormalPdf(o, m, alpha) / (4.0 * cosOM);
    }
    vec3 m = refractionHalfVector(o, i, eta.x, eta.y);
    float cosOM = dot(o, m);
    float cosIM = dot(i, m);
    if (cosOM <= 0.0 || cosIM >= 0.0)
        return 0.0;
    float fresnel = dielectricReflectance(cosOM, eta.x, eta.y, cosTransmitted);
    float denominator = eta.x * cosOM + eta.y * cosIM;
    return (1.0 - fresnel) * ggxVisibleNormalPdf(o, m, alpha) * eta.y * eta.y * abs(cosIM) /
           (denominator * denominator);
}

BsdfSample roughDielectricSample(Surface s, vec3 wo, float uLobe, vec2 uDirection)
{
    mat3 frame = basisAround(s.facingNormal);
    vec3 o = wo * frame;
    if (o.z <= 0.0)
        return invalidSample();
    float alpha = ggxAlpha(s.roughness);
    vec2 eta = roughDielectricIndices(s);
    vec3 m = sampleGgxVisibleNormal(uDirection, o, alpha);
    float cosOM = dot(o, m);
    if (!(cosOM > 0.0))
        return invalidSample();
    float visible = ggxVisibleNormalPdf(o, m, alpha);
    float cosTransmitted;
    float fresnel = dielectricReflectance(cosOM, eta.x, eta.y, cosTransmitted);
    if (uLobe < fresnel) {
        vec3 i = reflect(-o, m);
        if (i.z <= 0.0)
            return invalidSample();
        float pdf = fresnel * visible / (4.0 * cosOM);
        if (!(pdf > 0.0))
            return invalidSample();
        return BsdfSample(true, frame * i, s.color * ggxShadowingGivenMasking(o, i, alpha), pdf,
                          false, 1.0);
    }
    // Snell's law about m, as the smooth dielectric refracts about n.
    float ratio = eta.x / eta.y;
    vec3 i = normalize(-ratio * o + (ratio * cosOM - cosTransmitted) * m);
    if (i.z >= 0.0)
        return invalidSample();
    float cosIM = dot(i, m);
    float denominator = eta.x * cosOM + eta.y * cosIM;
    float pdf = (1.0 - fresnel) * visible * eta.y * eta.y * abs(cosIM) /
                (denominator * denominator);
    if (!(pdf > 0.0))
        return invalidSample();
    float scale = ratio * ratio;
    return BsdfSample(true, frame * i, s.color * (ggxShadowingGivenMasking(o, i, alpha) * scale),
                      pdf, false, scale);
}
#endif
