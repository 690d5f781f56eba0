#pragma once
// SHA-256 (FIPS 180-4): the digest of a batch's result keys (io/case_hash.h)
// and of the inputs they cover. Checked against the FIPS examples and
// coreutils' sha256sum (tests/io/test_batch_hash.cpp).
#include <string>
#include <string_view>

namespace rollcheck
{
/// SHA-256 (FIPS 180-4) of `bytes`, as 64 lowercase hexadecimal digits.
std::string sha256_hex(std::string_view bytes);
} // namespace rollcheck
