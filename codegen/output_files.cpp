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

// Why `path` cannot be written or replaced ("" when it can). `st` is the path's own lstat
// (nullptr when nothing is there): a symbolic link is replaced by the new file, never
// followed, so where it points does not matter; an existing file must be a regular file not
// marked read-only (rename() would replace it whatever its mode, and root passes
// access(W_OK) for any file); a new one needs a folder that exists or can be made.
std::string whyNotWritable(const std::string& path, const struct stat* st) {
  if (path.empty()) return "cannot write: the output path is empty";
  if (path.back() == '/') return "cannot write: '" + path + "' names a folder, not a file";
  if (st && !S_ISLNK(st->st_mode)) {
    if (S_ISDIR(st->st_mode)) return "cannot replace: not a regular file (a folder)";
    if (!S_ISREG(st->st_mode)) return "cannot replace: not a regular file";
    if (::access(path.c_str(), W_OK) != 0 || (st->st_mode & (S_IWUSR | S_IWGRP | S_IWOTH)) == 0)
      return "cannot replace: the file is read-only";
  }
  // A missing folder is made when the file is written, as -o makes its folder: the nearest
  // existing ancestor (the current folder for a relative path) must be a folder we may
  // write into.
  std::filesystem::path parent = std::filesystem::path(path).parent_path();
  std::error_code ec;
  std::filesystem::path existing = parent;
  while (!existing.empty() && !std::filesystem::exists(std::filesystem::symlink_status(existing, ec)))
    existing = existing.parent_path();
  const bool folderExists = existing == parent;
  if (existing.empty()) existing = ".";
  if (folderExists) {
    if (!std::filesystem::is_directory(existing, ec)) return "cannot write: " + parent.string() + " is not a folder";
    if (::access(existing.c_str(), W_OK | X_OK) != 0) return "cannot write: the folder " + existing.string() + " is not writable";
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
  bool exists = !path.empty() && ::lstat(path.c_str(), &st) == 0;
  std::string why = whyNotWritable(path, exists ? &st : nullptr);
  if (why.empty()) return true;
  diags.error(DiagCode::FileWrite, SourceRef{path, 0, 0}, why);
  return false;
}

bool checkFolderWritable(const std::string& dir, Diagnostics& diags) {
  std::string why = dir.empty() ? "cannot write: the output folder is empty"
                                : whyNotWritable((std::filesystem::path(dir) / "file").string(), nullptr);
  if (why.empty()) return true;
  diags.error(DiagCode::FileWrite, SourceRef{dir, 0, 0}, why);
  return false;
}

std::string realPathForRewrite(const std::string& path) {
  std::error_code ec;
  std::filesystem::path real = std::filesystem::canonical(path, ec);
  return ec ? path : real.string();
}

bool writeFileAtomically(const std::string& path, const std::string& contents, Diagnostics& diags) {
  // The path's own entry (lstat): a symbolic link there is replaced by the rename below,
  // never written through (a link planted at an output name must not redirect the write);
  // never a FIFO, device or folder; never a file marked read-only; a regular file replaced
  // keeps its mode.
  struct stat st {};
  bool exists = !path.empty() && ::lstat(path.c_str(), &st) == 0;
  if (std::string why = whyNotWritable(path, exists ? &st : nullptr); !why.empty()) {
    diags.error(DiagCode::FileWrite, SourceRef{path, 0, 0}, why);
    return false;
  }
  std::filesystem::path target(path);
  if (!exists && target.has_parent_path()) {  // a folder whyNotWritable found it can make
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
  if (exists && S_ISREG(st.st_mode)) ::chmod(tmp.c_str(), st.st_mode & 07777);
  if (std::rename(tmp.c_str(), target.c_str()) != 0) {
    int err = errno;
    std::remove(tmp.c_str());
    diags.error(DiagCode::FileWrite, SourceRef{path, 0, 0}, std::string("cannot replace: ") + std::strerror(err));
    return false;
  }
  return true;
}

}  // namespace wg
