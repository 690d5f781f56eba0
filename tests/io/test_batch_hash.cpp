// The batch's result key: SHA-256 against the FIPS 180-2 examples and against
// the system's sha256sum (coreutils) on every message length across the
// padding boundaries; and case_hash's dependence on values, not on order.
#include "io/case_hash.h"
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

using namespace rollcheck;

namespace
{
/// sha256sum's digest of `bytes`: an independent implementation.
std::string coreutils_sha256(const std::string& bytes)
{
  const std::filesystem::path dir = std::filesystem::path(ROLLCHECK_TEST_TMP) / "batch_hash";
  std::filesystem::create_directories(dir);
  const std::filesystem::path file = dir / "message.bin";
  std::ofstream(file, std::ios::binary) << bytes;
  FILE* pipe = popen(("sha256sum " + file.string()).c_str(), "r");
  char digest[65] = {};
  const std::size_t read = pipe ? std::fread(digest, 1, 64, pipe) : 0;
  if (pipe)
    pclose(pipe);
  return std::string(digest, read);
}
} // namespace

TEST(Sha256, MatchesTheFipsExamples)
{
  EXPECT_EQ(io::sha256_hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(io::sha256_hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(io::sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  EXPECT_EQ(io::sha256_hex(std::string(1000000, 'a')),
            "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST(Sha256, AgreesWithSha256sumAcrossThePaddingBoundaries)
{
  // Lengths 0..200 cover one and two padding blocks (55, 56, 63, 64, 119, 120 bytes ...).
  std::string message;
  for (int n = 0; n <= 200; ++n)
  {
    ASSERT_EQ(io::sha256_hex(message), coreutils_sha256(message)) << "length " << n;
    message.push_back(static_cast<char>((n * 37 + 11) % 256));
  }
}

TEST(CaseHash, DependsOnTheValuesNotOnTheirOrder)
{
  nlohmann::json a = {{"kind", "mesh"}, {"body", "oloid"}, {"points", 400}, {"radius_m", 1.0}};
  nlohmann::json b;
  b["radius_m"] = 1.0;
  b["points"] = 400;
  b["body"] = "oloid";
  b["kind"] = "mesh";
  EXPECT_EQ(io::case_hash(a), io::case_hash(b));
  EXPECT_EQ(io::case_hash(a).size(), 16u);
  nlohmann::json c = a;
  c["radius_m"] = 1.0 + 1e-15;
  EXPECT_NE(io::case_hash(a), io::case_hash(c));
  nlohmann::json d = a;
  d["body"] = "paper-oloid";
  EXPECT_NE(io::case_hash(a), io::case_hash(d));
}
