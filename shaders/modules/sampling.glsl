// Sampling routines, each with its probability density (pbrt's Sample*/ *Pdf pairs). Local
// frames have the normal along +z.

// Orthonormal basis whose third column is the unit vector n, without a singularity: Duff et
// al., "Building an Orthonormal Basis, Revisited", JCGT 2017.
mat3 basisAround(vec3 n)
{
    float s = n.z >= 0.0 ? 1.0 : -1.0;
    float a = -1.0 / (s + n.z);
    float b = n.x * n.y * a;
    vec3 tangent = vec3(1.0 + s * n.x * n.x * a, s * b, -s * n.x);
    vec3 bitangent = vec3(b, s + n.y * n.y * a, -n.y);
    return mat3(tangent, bitangent, n);
}

// Cosine-weighted hemisphere by Malley's method: a uniform point on the unit disk lifted
// onto the hemisphere (PBRT 3e, section 13.6.3).
vec3 sampleCosineHemisphere(vec2 u)
{
    float radius = sqrt(u.x);
    float phi = TWO_PI * u.y;
    return vec3(radius * cos(phi), radius * sin(phi), sqrt(max(0.0, 1.0 - u.x)));
}

float cosineHemispherePdf(float cosTheta)
{
    return max(cosTheta, 0.0) * INV_PI;
}

// Uniform direction in the cone of half-angle thetaMax around +z, given 1 - cos(thetaMax)
// rather than cos(thetaMax): for a tiny or distant sphere light the cone is so narrow that
// 1 - cos would round to zero (PBRT 3e, section 14.2.2, with the subtraction avoided).
vec3 sampleUniformCone(vec2 u, float oneMinusCosThetaMax)
{
    float oneMinusCos = u.x * oneMinusCosThetaMax;
    float cosTheta = 1.0 - oneMinusCos;
    float sinTheta = sqrt(max(0.0, oneMinusCos * (2.0 - oneMinusCos)));
    float phi = TWO_PI * u.y;
    return vec3(sinTheta * cos(phi), sinTheta * sin(phi), cosTheta);
}

float uniformConePdf(float oneMinusCosThetaMax)
{
    return 1.0 / (TWO_PI * oneMinusCosThetaMax);
}

// Blinn-Phong half vector: cos(theta_h) = u^(1 / (n + 1)), uniform azimuth, so that
// pdf(h) = (n + 1) / (2 pi) * cos(theta_h)^n over solid angle (PBRT 2e, section 14.5.1).
vec3 sampleBlinnPhongHalfVector(vec2 u, float exponent)
{
    float cosTheta = pow(u.x, 1.0 / (exponent + 1.0));
    float sinTheta = sqrt(max(0.0, 1.0 - cosTheta * cosTheta));
    float phi = TWO_PI * u.y;
    return vec3(sinTheta * cos(phi), sinTheta * sin(phi), cosTheta);
}

float blinnPhongHalfVectorPdf(float cosThetaH, float exponent)
{
    return (exponent + 1.0) * INV_TWO_PI * pow(clamp(cosThetaH, 0.0, 1.0), exponent);
}

// Veach's power heuristic (beta = 2) for the strategy with pdf `chosen` against `other`,
// written as a ratio so that an infinite density gives 1 instead of inf/inf.
float powerHeuristic(float chosen, float other)
{
    if (chosen <= 0.0)
        return 0.0;
    float ratio = other / chosen;
    return 1.0 / (1.0 + ratio * ratio);
}
