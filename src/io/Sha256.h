#pragma once
#include <cstddef>
#include <memory>
#include <string>

namespace io {

// SHA-256 (FIPS 180-4) of bytes given in any number of pieces, through OpenSSL's libcrypto:
// a digest that two machines agree on, for telling whether two renders saw the same scene.
class Sha256 {
public:
    Sha256();
    ~Sha256();
    Sha256(Sha256&&) noexcept;
    Sha256& operator=(Sha256&&) noexcept;
    Sha256(const Sha256&) = delete;
    Sha256& operator=(const Sha256&) = delete;

    void add(const void* bytes, std::size_t count);
    void add(const std::string& bytes) { add(bytes.data(), bytes.size()); }

    // The digest of everything added, as 64 lower-case hexadecimal digits. Ends the hash:
    // nothing may be added after it.
    std::string hexDigest();

private:
    struct Context;
    std::unique_ptr<Context> context_;
};

}  // namespace io
