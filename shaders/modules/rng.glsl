// Random numbers for the dimensions of a path that the sampler does not stratify (and for
// every dimension under --sampler independent): xoshiro128** (Blackman and Vigna,
// "Scrambled linear pseudorandom number generators", 2018), one stream per sample. Each
// sample's stream is seeded afresh from a hash of (seed, pixel, sample index)
// (seedRandomStream), so a sample's numbers depend on nothing but those three: no state is
// carried between frames, a render can be resumed from its accumulated count alone, and two
// renders that differ only in geometry draw the same numbers for the same sample.

// seedRandomStream sets it before any number is drawn; the initialiser only spares a
// compiler that cannot see this (Mesa) its "used uninitialized" warnings.
uvec4 rngState = uvec4(0u);

uint rotateLeft(uint x, uint k)
{
    return (x << k) | (x >> (32u - k));
}

// A 32-bit integer hash with good avalanche (Wellons's "lowbias32", from his
// hash-prospector search, 2020): every output bit depends on every input bit.
uint hashWord(uint x)
{
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}

// Mixes `value` into the running hash `key` (the boost hash_combine pattern, over a strong
// hash of the value, so that nearby values give unrelated keys).
uint hashCombine(uint key, uint value)
{
    return key ^ (hashWord(value) + 0x9e3779b9u + (key << 6) + (key >> 2));
}

void seedRandomStream(uint pixelKey, uint sampleIndex)
{
    uint key = hashCombine(pixelKey, sampleIndex);
    rngState = uvec4(hashWord(key ^ 0x2c1b3c6du), hashWord(key ^ 0x297a2d39u),
                     hashWord(key ^ 0x43a1f5b1u), hashWord(key ^ 0x8f0d7e13u));
    if (rngState == uvec4(0u))
        rngState.x = 1u;  // xoshiro's one forbidden state
}

uint nextRandomWord()
{
    uint result = rotateLeft(rngState.y * 5u, 7u) * 9u;
    uint shifted = rngState.y << 9u;
    rngState.z ^= rngState.x;
    rngState.w ^= rngState.y;
    rngState.y ^= rngState.z;
    rngState.x ^= rngState.w;
    rngState.z ^= shifted;
    rngState.w = rotateLeft(rngState.w, 11u);
    return result;
}

// Uniform in [0, 1) from a 32-bit word: its top 24 bits, so every value is exact in float32
// and 1.0 never occurs (the original's generator could return exactly 1).
float unitFloatFromWord(uint word)
{
    return float(word >> 8u) * (1.0 / 16777216.0);
}

float random01()
{
    return unitFloatFromWord(nextRandomWord());
}

vec2 random2()
{
    float first = random01();
    return vec2(first, random01());
}
