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
