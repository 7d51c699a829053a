// Fresnel reflectance.

// Schlick, "An inexpensive BRDF model for physically-based rendering", 1994. The base is
// clamped to [0, 1]: a cosine that rounds above 1 must not give pow() a negative base
// (llvmpipe returns NaN for that), and the fifth power is written out for the same reason.
vec3 schlickFresnel(vec3 normalReflectance, float cosTheta)
{
    float m = clamp(1.0 - cosTheta, 0.0, 1.0);
    float m2 = m * m;
    return normalReflectance + (1.0 - normalReflectance) * (m2 * m2 * m);
}

float schlickFresnel(float normalReflectance, float cosTheta)
{
    float m = clamp(1.0 - cosTheta, 0.0, 1.0);
    float m2 = m * m;
    return normalReflectance + (1.0 - normalReflectance) * (m2 * m2 * m);
}

// Reflectance of a smooth dielectric interface for light arriving at cosine cosIncident
// (> 0) in the medium of index etaIncident, bound for etaTransmitted. Writes the cosine of
// the refracted direction; returns 1 under total internal reflection.
float dielectricReflectance(float cosIncident, float etaIncident, float etaTransmitted,
                            out float cosTransmitted)
{
    float eta = etaIncident / etaTransmitted;
    float sin2Transmitted = eta * eta * max(0.0, 1.0 - cosIncident * cosIncident);
    if (sin2Transmitted >= 1.0) {
        cosTransmitted = 0.0;
        return 1.0;
    }
    cosTransmitted = sqrt(1.0 - sin2Transmitted);
    // Equal indices: there is no interface, whatever Schlick's formula would say at grazing.
    if (etaIncident == etaTransmitted)
        return 0.0;
    if (gDielectricFresnel == FRESNEL_EXACT) {
        float perpendicular = (etaIncident * cosIncident - etaTransmitted * cosTransmitted) /
                              (etaIncident * cosIncident + etaTransmitted * cosTransmitted);
        float parallel = (etaTransmitted * cosIncident - etaIncident * cosTransmitted) /
                         (etaTransmitted * cosIncident + etaIncident * cosTransmitted);
        return 0.5 * (perpendicular * perpendicular + parallel * parallel);
    }
    float r0 = (etaIncident - etaTransmitted) / (etaIncident + etaTransmitted);
    r0 *= r0;
    // Schlick's cosine is the one on the optically thinner side: leaving glass, that is the
    // transmitted angle, not the incident one (the original used the wrong one).
    float cosThinnerSide = etaIncident <= etaTransmitted ? cosIncident : cosTransmitted;
    return schlickFresnel(r0, cosThinnerSide);
}

#if HAS_ROUGH_CONDUCTOR
// Reflectance of a smooth conductor of complex index eta + i k (relative to the outside),
// per channel, for unpolarised light arriving at cosine cosIncident (> 0): the mean of the
// s- and p-polarised reflectances of the Fresnel equations for an absorbing medium (Born
// and Wolf, "Principles of Optics", section 14.2; in this form PBRT 3e, section 8.2.1),
//   Rs = (a^2 + b^2 - 2 a cos + cos^2) / (a^2 + b^2 + 2 a cos + cos^2),
//   Rp = Rs (cos^2 (a^2 + b^2) - 2 a cos sin^2 + sin^4) / (cos^2 (a^2 + b^2) + 2 a cos sin^2 + sin^4),
// with a^2 + b^2 = sqrt((eta^2 - k^2 - sin^2)^2 + 4 eta^2 k^2) and
// a = sqrt((a^2 + b^2 + eta^2 - k^2 - sin^2) / 2).
vec3 conductorReflectance(float cosIncident, vec3 eta, vec3 k)
{
    float cos2 = clamp(cosIncident * cosIncident, 0.0, 1.0);
    float sin2 = 1.0 - cos2;
    vec3 eta2 = eta * eta;
    vec3 k2 = k * k;
    vec3 t0 = eta2 - k2 - sin2;
    vec3 a2PlusB2 = sqrt(t0 * t0 + 4.0 * eta2 * k2);
    vec3 a = sqrt(max(0.5 * (a2PlusB2 + t0), 0.0));
    vec3 twoACos = 2.0 * a * sqrt(cos2);
    vec3 rs = (a2PlusB2 + cos2 - twoACos) / (a2PlusB2 + cos2 + twoACos);
    vec3 t3 = cos2 * a2PlusB2 + sin2 * sin2;
    vec3 t4 = twoACos * sin2;
    vec3 rp = rs * (t3 - t4) / (t3 + t4);
    return 0.5 * (rs + rp);
}
#endif
