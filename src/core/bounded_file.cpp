#include "core/bounded_file.h"
#include "core/error.h"
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

namespace rollcheck::core
{
namespace
{
/// What a non-regular file is, for the message.
std::string kind_of(mode_t mode)
{
  if (S_ISDIR(mode)) return "is a directory";
  if (S_ISCHR(mode)) return "is a character device";
  if (S_ISBLK(mode)) return "is a block device";
  if (S_ISFIFO(mode)) return "is a fifo (named pipe)";
  if (S_ISSOCK(mode)) return "is a socket";
  return "is not a regular file";
}

/// The file descriptor, closed on every path out.
struct Descriptor
{
  int fd;
  ~Descriptor()
  {
    if (fd >= 0)
      ::close(fd);
  }
};
} // namespace

std::string read_bounded_file(const std::filesystem::path& path, std::string_view what, std::size_t max_bytes)
{
  const std::string name = path.string();
  auto refuse = [&](const std::string& why) { return InputError(fmt::format("{} '{}': {}", what, name, why)); };
  if (name.empty())
    throw InputError(fmt::format("{}: the path is empty", what));
  // stat first: opening a fifo would block until a writer comes, even with
  // O_NONBLOCK on some systems for other special files.
  struct stat st{};
  if (::stat(name.c_str(), &st) != 0)
  {
    if (errno == ELOOP)
      throw refuse("is a symbolic link loop");
    if (errno == ENOENT || errno == ENOTDIR)
      throw refuse("does not exist");
    throw refuse(fmt::format("cannot be opened ({})", std::strerror(errno)));
  }
  if (!S_ISREG(st.st_mode))
    throw refuse(kind_of(st.st_mode) + ", not a regular file");
  const Descriptor file{::open(name.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)};
  if (file.fd < 0)
    throw refuse(fmt::format("cannot be opened ({})", std::strerror(errno)));
  if (::fstat(file.fd, &st) != 0 || !S_ISREG(st.st_mode))
    throw refuse("is not a regular file");
  if (static_cast<unsigned long long>(st.st_size) > max_bytes)
    throw refuse(fmt::format("holds {} bytes, more than the {} this input may have", st.st_size, max_bytes));
  std::string bytes;
  bytes.resize(std::min<std::size_t>(static_cast<std::size_t>(st.st_size), max_bytes) + 1);
  std::size_t used = 0;
  for (;;)
  {
    if (used == bytes.size())
    {
      if (used > max_bytes)
        throw refuse(fmt::format("holds more than the {} bytes this input may have", max_bytes));
      bytes.resize(std::min(2 * bytes.size(), max_bytes + 1));
    }
    const ssize_t n = ::read(file.fd, bytes.data() + used, bytes.size() - used);
    if (n < 0 && errno == EINTR)
      continue;
    if (n < 0)
      throw refuse(fmt::format("cannot be read ({})", std::strerror(errno)));
    if (n == 0)
      break;
    used += static_cast<std::size_t>(n);
  }
  if (used > max_bytes)
    throw refuse(fmt::format("holds more than the {} bytes this input may have", max_bytes));
  bytes.resize(used);
  return bytes;
}

void check_line_caps(std::string_view text, const std::filesystem::path& path, std::string_view what,
                     std::size_t max_lines, std::size_t max_line_bytes)
{
  std::size_t lines = 0, start = 0;
  while (start < text.size())
  {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    ++lines;
    if (lines > max_lines)
      throw InputError(fmt::format("{} '{}': more than {} lines", what, path.string(), max_lines));
    if (end - start > max_line_bytes)
      throw InputError(fmt::format("{} '{}': line {} is longer than {} bytes", what, path.string(), lines,
                                   max_line_bytes));
    start = end + 1;
  }
}
} // namespace rollcheck::core
