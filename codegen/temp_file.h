#pragma once
// Temporary files beside an output file, for writing it whole and then renaming it into
// place. The output folder may be shared with someone hostile, who can plant a symbolic
// link under any name they can predict: a temporary is therefore created under a random
// name with O_CREAT | O_EXCL | O_NOFOLLOW, so it is always a new regular file of ours and a
// link at that name is never followed (the name is then drawn again).
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace wg {

// Writes `contents` to a new file ".NAME.XXXXXXXX.tmp" in `target`'s folder (mode 0666 less
// the umask) and returns its path; nullopt with *error set (an errno value) on failure,
// leaving nothing behind.
std::optional<std::string> writeTemporaryBeside(const std::filesystem::path& target, std::string_view contents,
                                                int* error);

}  // namespace wg
