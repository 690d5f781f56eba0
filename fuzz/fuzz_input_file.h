#pragma once
// The readers under test open files by path, so a fuzzer's bytes are written
// to a file of this process's own (libFuzzer's -fork and -jobs run several
// processes) with the extension that picks the reader.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <unistd.h>

namespace rollcheck::fuzz
{
inline std::filesystem::path write_input_file(std::string_view bytes, std::string_view extension)
{
  const std::filesystem::path path = std::filesystem::temp_directory_path()
                                     / ("rollcheck-fuzz-" + std::to_string(::getpid()) + std::string(extension));
  std::ofstream(path, std::ios::binary | std::ios::trunc).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  return path;
}
} // namespace rollcheck::fuzz
