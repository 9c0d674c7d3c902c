// hapstab/study/sha256.hpp -- SHA-256 (FIPS 180-4) of a byte string, as 64 lowercase hex digits:
// the identity of a sweep spec, so that shards of different specs are never merged.
#pragma once

#include <string>
#include <string_view>

namespace hapstab::study {

/// SHA-256 of `bytes` in lowercase hex, e.g. sha256_hex("abc") = "ba7816bf...f20015ad".
std::string sha256_hex(std::string_view bytes);

}  // namespace hapstab::study
