// SHA-256 against the test vectors of FIPS 180-2 (appendix B) and NIST's example values.
#include "io/Sha256.h"

#include <gtest/gtest.h>

#include <string>

namespace io_tests {
namespace {

std::string digestOf(const std::string& message)
{
    io::Sha256 digest;
    digest.add(message);
    return digest.hexDigest();
}

TEST(Sha256, OneBlockMessageMatchesFips180Vector)
{
    EXPECT_EQ(digestOf("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
}

TEST(Sha256, TwoBlockMessageMatchesFips180Vector)
{
    EXPECT_EQ(digestOf("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
              "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
}

TEST(Sha256, MillionAsGivenInPiecesMatchesFips180Vector)
{
    // Pieces of 997 bytes (a prime: they straddle every 64-byte block boundary).
    io::Sha256 digest;
    const std::string piece(997, 'a');
    std::size_t left = 1000000;
    for (; left >= piece.size(); left -= piece.size())
        digest.add(piece);
    digest.add(std::string(left, 'a'));
    EXPECT_EQ(digest.hexDigest(),
              "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST(Sha256, EmptyMessageMatchesKnownDigest)
{
    EXPECT_EQ(digestOf(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
}

}  // namespace
}  // namespace io_tests
