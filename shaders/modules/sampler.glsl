// The numbers each decision of a path is made with. Under --sampler sobol (the default) the
// decisions that carry most of the image, the point in the pixel and the first bounces'
// choices, take their numbers from Owen-scrambled Sobol points; the rest come from the
// sample's own random stream (rng.glsl), as every decision does under --sampler independent.
//
// The construction is Burley's ("Practical Hash-based Owen Scrambling", JCGT 2020), padded
// in two dimensions as pbrt-v4's PaddedSobolSampler is: every decision is a dimension, and
// every dimension draws the first two dimensions of the Sobol sequence (a (0,2)-sequence in
// base 2), with the sample index shuffled and the point scrambled by nested uniform (Owen)
// scrambling seeded from a hash of (seed, pixel, dimension). So
// - each point, alone, is uniform on the unit square: every estimate is unbiased, at any
//   sample count, not only at powers of two;
// - the first 2^k samples of a pixel are an aligned block of 2^k Sobol points (the shuffle
//   permutes the index's low k bits among themselves), hence a (0,k,2)-net: every prefix of
//   a power-of-two length is stratified in each decision, and the others nearly so;
// - different decisions and different pixels get independent scrambles and shuffles, so no
//   structure is shared between them (no pattern across the image, no correlation between
//   a bounce's light sample and its BSDF sample).
// The sample index is the pixel's count of samples so far (accumulated and discarded), so
// a render continued from its accumulated state continues the same sequence.

const int SAMPLE_PIXEL = 0;  // 2D: the point in the pixel

// A path's decisions. The point in the pixel is dimension 0; scattering event b (counted
// from 0 at the camera ray's hit) makes the decisions below, dimension 1 + 6 b + decision.
const int SAMPLE_LIGHT_SELECTION = 0;  // 1D: which light next-event estimation samples
const int SAMPLE_LIGHT_POINT = 1;      // 2D: the direction in the light's cone
const int SAMPLE_BSDF_LOBE = 2;        // 1D: Blinn-Phong's lobe, glass's reflect or refract
const int SAMPLE_BSDF_DIRECTION = 3;   // 2D: the scattered direction
const int SAMPLE_ROULETTE = 4;         // 1D: Russian roulette
const int SAMPLE_PATTERN = 5;          // 1D: a pigment's random choice (a texture's projection)
const int kDecisionsPerBounce = 6;
// Past this many scattering events the decisions use the random stream: the light that
// arrives after several diffuse bounces is smooth, and the stratification of one of many
// dimensions buys little there (docs/ACCURACY.md measures where the gain stops).
const int kStratifiedBounces = 4;
// 2D: the point on a thin lens (camera.glsl). After every bounce's dimensions, so that
// adding it moved none of theirs: a scene without a lens draws what it drew before.
const int SAMPLE_LENS = 1 + kDecisionsPerBounce * kStratifiedBounces;

uint samplePixelKey = 0u;
uint sampleIndex = 0u;

// What identifies a pixel's sequence for this seed.
uint pixelKey(ivec2 pixel)
{
    uint seedKey = hashCombine(hashWord(gSeed.x), gSeed.y);
    return hashCombine(seedKey, uint(pixel.x) | (uint(pixel.y) << 16));
}

// Starts sample number `index` of the pixel: its random stream, and the index that the
// stratified dimensions are taken at.
void beginSample(ivec2 pixel, uint index)
{
    samplePixelKey = pixelKey(pixel);
    sampleIndex = index;
    seedRandomStream(samplePixelKey, index);
}

uint reverseBits32(uint x)
{
    x = ((x & 0x55555555u) << 1) | ((x >> 1) & 0x55555555u);
    x = ((x & 0x33333333u) << 2) | ((x >> 2) & 0x33333333u);
    x = ((x & 0x0f0f0f0fu) << 4) | ((x >> 4) & 0x0f0f0f0fu);
    x = ((x & 0x00ff00ffu) << 8) | ((x >> 8) & 0x00ff00ffu);
    return (x << 16) | (x >> 16);
}

// A permutation of 32-bit words in which each bit is flipped according to the bits below
// it only (an addition, then xors with products by even constants): on bit-reversed values
// that is an Owen scramble, every digit permuted according to the digits before it. The
// constants are Burley's (2020, listing 2).
uint laineKarrasPermutation(uint x, uint seed)
{
    x += seed;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    return x;
}

// Owen's nested uniform scramble of a 32-bit fraction (bit 31 is the digit 1/2).
uint nestedUniformScramble(uint x, uint seed)
{
    return reverseBits32(laineKarrasPermutation(reverseBits32(x), seed));
}

// Sobol's second dimension in digit order: digit j + 1 of point `index` is the parity of
// the index's bits k whose positions contain j's bits (its generator matrix is Pascal's
// triangle mod 2: C(k, j) is odd exactly when j's bits are a subset of k's, Lucas's
// theorem). That is a superset-parity transform over the five bits of a bit position,
// five shift-and-xor steps; bit j of the result is digit j + 1 (bit-reversed order).
uint sobolSecondDimensionDigits(uint index)
{
    uint y = index;
    y ^= (y >> 1) & 0x55555555u;
    y ^= (y >> 2) & 0x33333333u;
    y ^= (y >> 4) & 0x0f0f0f0fu;
    y ^= (y >> 8) & 0x00ff00ffu;
    y ^= (y >> 16) & 0x0000ffffu;
    return y;
}

// Sobol's first two dimensions of point `index`, unscrambled, as 32-bit fractions. The
// first is van der Corput's radical inverse: the index's bits reversed.
uvec2 sobol2D(uint index)
{
    return uvec2(reverseBits32(index), reverseBits32(sobolSecondDimensionDigits(index)));
}

uint dimensionSeed(int dimension)
{
    return hashCombine(samplePixelKey, uint(dimension));
}

// The shuffled index of the current sample in `dimension` (Burley, section 4: an Owen
// scramble of the index, which maps every aligned block of 2^k indices onto one).
uint shuffledSampleIndex(uint seed)
{
    return nestedUniformScramble(sampleIndex, seed);
}

// The scrambled first Sobol coordinate of point `shuffled` is the nested scramble of its
// reversed bits; scrambling reverses them again, so the two reversals cancel.
float scrambledSobolFirst(uint shuffled, uint seed)
{
    return unitFloatFromWord(reverseBits32(laineKarrasPermutation(shuffled, seed)));
}

float scrambledSobolSecond(uint shuffled, uint seed)
{
    return unitFloatFromWord(
        reverseBits32(laineKarrasPermutation(sobolSecondDimensionDigits(shuffled), seed)));
}

float sobolSample1D(int dimension)
{
    uint seed = dimensionSeed(dimension);
    return scrambledSobolFirst(shuffledSampleIndex(seed), hashWord(seed ^ 0xa511e9b3u));
}

vec2 sobolSample2D(int dimension)
{
    uint seed = dimensionSeed(dimension);
    uint shuffled = shuffledSampleIndex(seed);
    return vec2(scrambledSobolFirst(shuffled, hashWord(seed ^ 0xa511e9b3u)),
                scrambledSobolSecond(shuffled, hashWord(seed ^ 0x63d83595u)));
}

// The dimension of `decision` at scattering event `bounce`, or -1 where it is not stratified.
int bounceDimension(int bounce, int decision)
{
    return bounce < kStratifiedBounces ? 1 + kDecisionsPerBounce * bounce + decision : -1;
}

float sample1D(int dimension)
{
    return gSampler == SAMPLER_SOBOL && dimension >= 0 ? sobolSample1D(dimension) : random01();
}

vec2 sample2D(int dimension)
{
    return gSampler == SAMPLER_SOBOL && dimension >= 0 ? sobolSample2D(dimension) : random2();
}

float bounceSample1D(int bounce, int decision)
{
    return sample1D(bounceDimension(bounce, decision));
}

vec2 bounceSample2D(int bounce, int decision)
{
    return sample2D(bounceDimension(bounce, decision));
}
