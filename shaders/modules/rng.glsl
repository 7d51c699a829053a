// Per-pixel random numbers: xoshiro128** (Blackman and Vigna, "Scrambled linear
// pseudorandom number generators", 2018). Its 128-bit state lives in the RNG texture
// between frames, so each pixel draws one long stream (period 2^128 - 1) across the whole
// render; the host seeds every pixel's state from a 64-bit hash of (seed, pixel), so no two
// pixels share a stream and no two frames reuse numbers.

// main sets it from the RNG texture before any number is drawn; the initialiser only spares
// a compiler that cannot see this (Mesa) its "used uninitialized" warnings.
uvec4 rngState = uvec4(0u);

uint rotateLeft(uint x, uint k)
{
    return (x << k) | (x >> (32u - k));
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

// Uniform in [0, 1): the top 24 bits, so every value is exact in float32 and 1.0 never
// occurs (the original's generator could return exactly 1).
float random01()
{
    return float(nextRandomWord() >> 8u) * (1.0 / 16777216.0);
}

vec2 random2()
{
    float first = random01();
    return vec2(first, random01());
}
