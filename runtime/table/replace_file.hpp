// Replacing a file with new contents so that a crash, a full disk or a kill -9 at any moment
// leaves either the old file or the new one, never a mix: the bytes go to a temporary file in
// the target's directory, are synced, renamed over the target, and the directory is synced.
#pragma once
#include <cstddef>
#include <string>

#include "asperity/interrupt.hpp"

namespace asperity {

// Throws asperity::Error (and leaves the target as it was, with no temporary file behind) if
// the target is not a regular file (a symbolic link, device, FIFO or directory: refused, never
// replaced), is read-only, or anything fails. A replaced file keeps its permission bits; a new
// one gets 0666 less the umask. Before writing, temporaries left in that directory by writers
// that died (kill -9, power loss) are removed: only ours (name pattern, this host, this user),
// whose process is gone, untouched for 10 minutes.
void replace_file(const std::string& path, const void* data, std::size_t size);

// The temporary-file name prefix in the target's directory (the output policy's).
inline constexpr const char* temporary_prefix = ".asperity-";

}  // namespace asperity
