#include "core/build_id.h"
#include "core/child_process.h"
#include "core/sha256.h"
#include <elf.h>
#include <fmt/format.h>
#include <fstream>
#include <link.h>
#include <string_view>

namespace rollcheck
{
namespace
{
/// The NT_GNU_BUILD_ID note among the program headers of the first object
/// dl_iterate_phdr reports, the executable.
int read_build_id(dl_phdr_info* info, std::size_t, void* data)
{
  std::string& id = *static_cast<std::string*>(data);
  for (int i = 0; i < info->dlpi_phnum; ++i)
  {
    const ElfW(Phdr)& header = info->dlpi_phdr[i];
    if (header.p_type != PT_NOTE)
      continue;
    const char* note = reinterpret_cast<const char*>(info->dlpi_addr + header.p_vaddr);
    const char* end = note + header.p_memsz;
    while (note + sizeof(ElfW(Nhdr)) <= end)
    {
      const auto* n = reinterpret_cast<const ElfW(Nhdr)*>(note);
      const char* name = note + sizeof(ElfW(Nhdr));
      const char* desc = name + ((n->n_namesz + 3) & ~3u);
      if (n->n_type == NT_GNU_BUILD_ID && n->n_namesz == 4 && std::string_view(name, 3) == "GNU")
      {
        for (std::size_t k = 0; k < n->n_descsz; ++k)
          id += fmt::format("{:02x}", static_cast<unsigned char>(desc[k]));
        return 1;
      }
      note = desc + ((n->n_descsz + 3) & ~3u);
    }
  }
  return 1; // only the executable, the first object
}
} // namespace

const std::string& build_id()
{
  static const std::string id = [] {
    std::string found;
    dl_iterate_phdr(read_build_id, &found);
    if (!found.empty())
      return found;
    std::ifstream in(process::own_executable(), std::ios::binary);
    return sha256_hex(std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()));
  }();
  return id;
}
} // namespace rollcheck
