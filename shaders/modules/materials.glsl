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
