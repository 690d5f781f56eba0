#pragma once
// Which build of rollcheck is running: the GNU build-id the linker stamps
// into the executable (a hash of its code and data, `readelf -n`), so that a
// result keyed by it (io/case_hash.h) is never reused by a different build
// of the same version. Without that note (a linker told --build-id=none), the
// SHA-256 of the executable file itself.
#include <string>

namespace rollcheck
{
/// The running executable's build-id as lowercase hex (computed once).
const std::string& build_id();
} // namespace rollcheck
