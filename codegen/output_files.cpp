#include "codegen/output_files.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <sys/stat.h>
#include <unistd.h>

#include "codegen/temp_file.h"

namespace wg {

bool writeOutputFiles(const std::string& dir, const std::vector<OutputFile>& files, Diagnostics& diags) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) {
    diags.error(DiagCode::FileWrite, SourceRef{dir, 0, 0}, "cannot create output folder: " + ec.message());
    return false;
  }
  std::vector<std::pair<std::string, std::string>> staged;  // temp, final
  auto cleanup = [&] {
    for (const auto& [tmp, fin] : staged) std::remove(tmp.c_str());
  };
  for (const auto& f : files) {
    std::filesystem::path target = std::filesystem::path(dir) / f.name;
    int err = 0;
    auto tmp = writeTemporaryBeside(target, f.contents, &err);
    if (!tmp) {
      cleanup();
      diags.error(DiagCode::FileWrite, SourceRef{target.string(), 0, 0},
                  std::string("cannot write output file: ") + std::strerror(err));
      return false;
    }
    staged.emplace_back(*tmp, target.string());
  }
  // A name that cannot be replaced by a file (a folder in the way) would fail its rename
  // after earlier files had been renamed: refuse before renaming any.
  for (const auto& [tmp, fin] : staged) {
    std::error_code sec;
    auto st = std::filesystem::symlink_status(fin, sec);
    if (!sec && std::filesystem::exists(st) && std::filesystem::is_directory(st)) {
      cleanup();
      diags.error(DiagCode::FileWrite, SourceRef{fin, 0, 0}, "cannot write output file: a folder of that name is in the way");
      return false;
    }
  }
  std::vector<std::string> renamed;
  for (const auto& [tmp, fin] : staged) {
    if (std::rename(tmp.c_str(), fin.c_str()) != 0) {
      int err = errno;
      cleanup();
      // Never leave a mixed set of new and old files: the ones already renamed go too.
      for (const auto& done : renamed) std::remove(done.c_str());
      diags.error(DiagCode::FileWrite, SourceRef{fin, 0, 0}, std::string("cannot rename output file: ") + std::strerror(err));
      return false;
    }
    renamed.push_back(fin);
  }
  return true;
}

namespace {

// Why `path` cannot be written or replaced ("" when it can): an existing file must be a
// regular file not marked read-only; a new one needs a folder that exists.
std::string whyNotWritable(const std::string& path, const struct stat* st) {
  if (st) {
    if (!S_ISREG(st->st_mode)) return "cannot replace: not a regular file";
    if (::access(path.c_str(), W_OK) != 0 || (st->st_mode & (S_IWUSR | S_IWGRP | S_IWOTH)) == 0)
      return "cannot replace: the file is read-only";
    return "";
  }
  // A missing folder is made when the file is written, as -o makes its folder: the nearest
  // existing ancestor must be a folder we may write into.
  std::filesystem::path parent = std::filesystem::path(path).parent_path();
  std::error_code ec;
  std::filesystem::path existing = parent;
  while (!existing.empty() && !std::filesystem::exists(std::filesystem::symlink_status(existing, ec)))
    existing = existing.parent_path();
  if (existing.empty() || existing == parent) {
    if (!parent.empty() && !std::filesystem::is_directory(parent, ec))
      return "cannot write: " + parent.string() + " is not a folder";
    return "";
  }
  if (!std::filesystem::is_directory(existing, ec))
    return "cannot write: the folder " + parent.string() + " cannot be made (" + existing.string() + " is not a folder)";
  if (::access(existing.c_str(), W_OK | X_OK) != 0)
    return "cannot write: the folder " + parent.string() + " cannot be made (" + existing.string() + " is not writable)";
  return "";
}

}  // namespace

bool checkWritable(const std::string& path, Diagnostics& diags) {
  struct stat st {};
  bool exists = ::stat(path.c_str(), &st) == 0;
  std::string why = whyNotWritable(path, exists ? &st : nullptr);
  if (why.empty()) return true;
  diags.error(DiagCode::FileWrite, SourceRef{path, 0, 0}, why);
  return false;
}

bool writeFileAtomically(const std::string& path, const std::string& contents, Diagnostics& diags) {
  std::filesystem::path target(path);
  // Replacing an existing file: through a symlink to the file it names; never a FIFO,
  // device or folder; never a file marked read-only (rename() would replace it whatever its
  // mode, and root passes access(W_OK) for any file); the new file keeps the old one's mode.
  struct stat st {};
  bool exists = ::stat(path.c_str(), &st) == 0;
  if (exists) {
    std::error_code ec;
    auto real = std::filesystem::canonical(target, ec);
    if (!ec) target = real;
    std::string why = whyNotWritable(path, &st);
    if (!why.empty()) {
      diags.error(DiagCode::FileWrite, SourceRef{path, 0, 0}, why);
      return false;
    }
  }
  if (!exists && target.has_parent_path()) {  // a folder checkWritable found it can make
    std::error_code ec;
    std::filesystem::create_directories(target.parent_path(), ec);
    if (ec) {
      diags.error(DiagCode::FileWrite, SourceRef{path, 0, 0},
                  "cannot write: the folder " + target.parent_path().string() + " cannot be made: " + ec.message());
      return false;
    }
  }
  int werr = 0;
  auto written = writeTemporaryBeside(target, contents, &werr);
  if (!written) {
    diags.error(DiagCode::FileWrite, SourceRef{path, 0, 0}, std::string("cannot write: ") + std::strerror(werr));
    return false;
  }
  const std::string& tmp = *written;
  if (exists) ::chmod(tmp.c_str(), st.st_mode & 07777);
  if (std::rename(tmp.c_str(), target.c_str()) != 0) {
    int err = errno;
    std::remove(tmp.c_str());
    diags.error(DiagCode::FileWrite, SourceRef{path, 0, 0}, std::string("cannot replace: ") + std::strerror(err));
    return false;
  }
  return true;
}

}  // namespace wg
