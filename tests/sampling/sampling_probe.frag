// The test's own main(), appended to the renderer's modules (constants, rng, sampler,
// sampling, scene_data, fresnel, ggx_albedo_table, microfacet, materials, environment): it runs the real sampling and pdf routines, one
// per fragment, and writes what they returned into an RGBA32F target read back by the test.
//
//   uMode 0: draw one sample per fragment; rgb = the direction, a = its pdf (-1: no sample)
//   uMode 1: evaluate the pdf at the centre of grid cell (theta, phi) = fragment (x, y);
//            rgb = the direction, a = the pdf
//   uMode 2: draw one sample per fragment; rgb = its weight f cos / pdf, a = 1 if valid
//   uMode 3: evaluate f cos at the centre of grid cell (theta, phi); rgb = f cos
//   uMode 4: the sampler's own numbers: rg = sample2D(uDimension), b = sample1D(uDimension)
//   uMode 5: rg = Sobol's first two dimensions of point number fragment.x, unscrambled
//
// The numbers come from the renderer's sampler (uSampler, uSeed), as a path's do. Under
// uSequence 0 every fragment is a pixel of its own, taking its sample number uSampleIndex
// (so fragments are independent draws); under uSequence 1 the fragments are consecutive
// samples of one pixel, sample index = uSampleIndex + the fragment's row-major number.
//
// Routines (uRoutine): 0 cosine hemisphere, 1 uniform cone, 2 Blinn-Phong half vector (all
// in the local frame, +z up), 3 the Blinn-Phong material, 4 the rough conductor, 5 the rough
// dielectric, 6 the environment map (world directions; a material's f cos takes |cos|, for
// transmission).

uniform int uMode;
uniform int uRoutine;
uniform int uSequence;
uniform int uSampleIndex;
uniform int uDimension;
uniform float uExponent;
uniform float uOneMinusCosThetaMax;
uniform vec3 uNormal;
uniform vec3 uOutgoing;
uniform vec3 uPigment;
uniform mat3 uGridFrame;   // local (theta, phi) directions to world
uniform vec2 uGridCells;   // theta cells, phi cells
uniform float uGridThetaMax;
uniform float uImageWidth;
uniform float uRoughness;
uniform float uIor;
uniform int uEntering;

layout(location = 0) out vec4 outValue;

Surface probeSurface()
{
    Surface s;
    s.position = vec3(0.0);
    s.normal = uNormal;
    s.facingNormal = uNormal;
    s.entering = uEntering != 0;
    s.color = uPigment;
    s.emission = vec3(0.0);
    s.material = uRoutine == 4 ? MATERIAL_ROUGH_CONDUCTOR
                               : uRoutine == 5 ? MATERIAL_ROUGH_DIELECTRIC : MATERIAL_BLINN_PHONG;
    s.phongExponent = uExponent;
    s.ior = uIor;
    s.lightIndex = -1;
    s.roughness = uRoughness;
    s.complexIor = false;
    s.conductorEta = vec3(1.0);
    s.conductorK = vec3(0.0);
    return s;
}

BsdfSample materialSample(float uLobe, vec2 u)
{
    if (uRoutine == 4)
        return roughConductorSample(probeSurface(), uOutgoing, uLobe, u);
    if (uRoutine == 5)
        return roughDielectricSample(probeSurface(), uOutgoing, uLobe, u);
    return blinnPhongSample(probeSurface(), uOutgoing, uLobe, u);
}

vec3 materialEvaluate(vec3 direction)
{
    if (uRoutine == 4)
        return roughConductorEvaluate(probeSurface(), uOutgoing, direction);
    if (uRoutine == 5)
        return roughDielectricEvaluate(probeSurface(), uOutgoing, direction);
    return blinnPhongEvaluate(probeSurface(), uOutgoing, direction);
}

float routinePdf(vec3 direction)
{
    if (uRoutine == 0)
        return cosineHemispherePdf(direction.z);
    if (uRoutine == 1) {
        // The cone's support: directions within thetaMax of +z, compared as 1 - cos.
        float oneMinusCos = dot(direction.xy, direction.xy) / (1.0 + direction.z);
        return direction.z > 0.0 && oneMinusCos <= uOneMinusCosThetaMax
                   ? uniformConePdf(uOneMinusCosThetaMax)
                   : 0.0;
    }
    if (uRoutine == 2)
        return blinnPhongHalfVectorPdf(direction.z, uExponent);
    if (uRoutine == 4)
        return roughConductorPdf(probeSurface(), uOutgoing, direction);
    if (uRoutine == 5)
        return roughDielectricPdf(probeSurface(), uOutgoing, direction);
    if (uRoutine == 6)
        return environmentMapPdf(direction);
    return blinnPhongPdf(probeSurface(), uOutgoing, direction);
}

void main()
{
    // The modules read their uniforms through copies, which main() fills
    // (shadergen/UniformBlock.h).
    readUniformsOnce();
    ivec2 fragment = ivec2(gl_FragCoord.xy);
    if (uMode == 1 || uMode == 3) {
        float theta = gl_FragCoord.x / uGridCells.x * uGridThetaMax;
        float phi = gl_FragCoord.y / uGridCells.y * TWO_PI;
        vec3 local = vec3(sin(theta) * cos(phi), sin(theta) * sin(phi), cos(theta));
        vec3 direction = uGridFrame * local;
        if (uMode == 1) {
            outValue = vec4(direction, routinePdf(direction));
        } else {
            Surface s = probeSurface();
            float cosine = abs(dot(s.facingNormal, direction));
            outValue = vec4(materialEvaluate(direction) * cosine, 1.0);
        }
        return;
    }

    if (uSequence == 0)
        beginSample(fragment, uint(uSampleIndex));
    else
        beginSample(ivec2(0), uint(uSampleIndex + fragment.y * int(uImageWidth) + fragment.x));
    if (uMode == 5) {
        uvec2 point = sobol2D(uint(fragment.x));
        outValue = vec4(unitFloatFromWord(point.x), unitFloatFromWord(point.y), 0.0, 1.0);
        return;
    }
    if (uMode == 4) {
        outValue = vec4(sample2D(uDimension), sample1D(uDimension), 1.0);
        return;
    }
    float uLobe = sample1D(uDimension + 1);
    vec2 u = sample2D(uDimension);
    if (uMode == 2) {
        BsdfSample scattered = materialSample(uLobe, u);
        outValue = scattered.valid ? vec4(scattered.weight, 1.0) : vec4(0.0);
        return;
    }
    if (uRoutine == 0) {
        vec3 direction = sampleCosineHemisphere(u);
        outValue = vec4(direction, cosineHemispherePdf(direction.z));
    } else if (uRoutine == 1) {
        vec3 direction = sampleUniformCone(u, uOneMinusCosThetaMax);
        outValue = vec4(direction, uniformConePdf(uOneMinusCosThetaMax));
    } else if (uRoutine == 2) {
        vec3 direction = sampleBlinnPhongHalfVector(u, uExponent);
        outValue = vec4(direction, blinnPhongHalfVectorPdf(direction.z, uExponent));
    } else if (uRoutine == 6) {
        EnvironmentMapSample chosen = sampleEnvironmentMap(u);
        outValue = chosen.pdf > 0.0 ? vec4(chosen.direction, chosen.pdf)
                                    : vec4(0.0, 0.0, 0.0, -1.0);
    } else {
        BsdfSample scattered = materialSample(uLobe, u);
        outValue = scattered.valid ? vec4(scattered.direction, scattered.pdf)
                                   : vec4(0.0, 0.0, 0.0, -1.0);
    }
}
