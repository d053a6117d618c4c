#pragma once
// Reading an input file (a graph, an import, a texture, a configuration) so that what is
// checked is what is read. Checking a path and then opening it again by name is a race: a
// file swapped for a symbolic link between the two is read from wherever the link points.
// Here the file is opened once; whether it is a regular file, its size and where it really
// lies (the path of the opened descriptor, every link resolved) are checked on that open
// file, and its bytes are read from the same descriptor.
#include <cstddef>
#include <optional>
#include <string>

namespace wg {

struct FileReadRule {
  std::size_t maxBytes = 0;       // more than this is refused (TooLarge)
  bool regularOnly = true;        // false: a FIFO or a device is read too (a graph from a pipe)
  std::string insideFolder;       // non-empty (a canonical folder): the file must really lie under it
  std::string mustResolveTo;      // non-empty (a canonical path): the file must really be this one
  std::size_t readAtMost = 0;     // non-zero: read only the first this many bytes (a header)
};

struct FileReadFailure {
  enum class Kind { Open, NotRegular, TooLarge, Outside, Read } kind = Kind::Open;
  int error = 0;  // the errno for Open and Read
  // One phrase saying why: "No such file or directory", "it is not a regular file", ...
  std::string why() const;
};

struct FileText {
  std::string bytes;
  std::string realPath;  // the opened file's own path, every link resolved ("" for a pipe)
};

// Opens `path` once (following links, which the folder rule then judges by where they
// lead), checks it against `rule` through the descriptor and reads it whole from that same
// descriptor. A regular-only read opens with O_NONBLOCK, so a FIFO swapped in is refused
// instead of blocking the open.
std::optional<FileText> readFileChecked(const std::string& path, const FileReadRule& rule, FileReadFailure* failure);

// The real path of an open descriptor (/proc/self/fd), or "" when it cannot be told.
std::string realPathOfDescriptor(int fd);

// Whether `path` lies strictly under `folder`, both canonical (no links, no "..").
bool pathLiesUnder(const std::string& path, const std::string& folder);

}  // namespace wg
