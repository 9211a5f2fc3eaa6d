#pragma once
// SHA-256 of bytes, as lower-case hex (OpenSSL's libcrypto does the hashing): what a package's
// manifest records for every entry and checks on opening.

#include <memory>
#include <string>
#include <string_view>

namespace thespis::core {

/// A running SHA-256: add() the bytes in as many pieces as they come, then hex().
class Sha256 {
public:
    Sha256();
    ~Sha256();
    Sha256(const Sha256&) = delete;
    Sha256& operator=(const Sha256&) = delete;

    void add(std::string_view bytes);
    /// The digest of everything added, as 64 lower-case hex digits; the hash starts again.
    std::string hex();

private:
    struct State;
    std::unique_ptr<State> m_state;
};

/// The SHA-256 of `bytes` in lower-case hex.
std::string sha256Hex(std::string_view bytes);

} // namespace thespis::core
