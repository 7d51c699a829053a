#include "io/Sha256.h"

#include <openssl/evp.h>

#include <stdexcept>

namespace io {

struct Sha256::Context {
    EVP_MD_CTX* digest = nullptr;
    bool finished = false;
    ~Context() { EVP_MD_CTX_free(digest); }
};

Sha256::Sha256() : context_(std::make_unique<Context>())
{
    context_->digest = EVP_MD_CTX_new();
    if (context_->digest == nullptr ||
        EVP_DigestInit_ex(context_->digest, EVP_sha256(), nullptr) != 1)
        throw std::runtime_error("cannot start a SHA-256 digest (OpenSSL)");
}

Sha256::~Sha256() = default;
Sha256::Sha256(Sha256&&) noexcept = default;
Sha256& Sha256::operator=(Sha256&&) noexcept = default;

void Sha256::add(const void* bytes, std::size_t count)
{
    if (context_->finished)
        throw std::logic_error("Sha256::add after hexDigest");
    if (count > 0 && EVP_DigestUpdate(context_->digest, bytes, count) != 1)
        throw std::runtime_error("SHA-256 digest failed (OpenSSL)");
}

std::string Sha256::hexDigest()
{
    if (context_->finished)
        throw std::logic_error("Sha256::hexDigest called twice");
    unsigned char digest[EVP_MAX_MD_SIZE];
    unsigned int length = 0;
    if (EVP_DigestFinal_ex(context_->digest, digest, &length) != 1)
        throw std::runtime_error("SHA-256 digest failed (OpenSSL)");
    context_->finished = true;
    static const char* const kDigits = "0123456789abcdef";
    std::string text;
    for (unsigned int i = 0; i < length; ++i) {
        text += kDigits[digest[i] >> 4];
        text += kDigits[digest[i] & 0xf];
    }
    return text;
}

}  // namespace io
