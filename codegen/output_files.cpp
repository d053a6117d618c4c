#include "codegen/output_files.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace wg {
namespace {

std::string tempNameFor(const std::filesystem::path& target) {
  return (target.parent_path() / ("." + target.filename().string() + ".tmp" + std::to_string(getpid()))).string();
}

bool writeWhole(const std::string& path, const std::string& contents) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) return false;
  out.write(contents.data(), static_cast<std::streamsize>(contents.size()));
  out.flush();
  return static_cast<bool>(out);
}

}  // namespace

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
    std::string tmp = tempNameFor(target);
    if (!writeWhole(tmp, f.contents)) {
      int err = errno;
      std::remove(tmp.c_str());
      cleanup();
      diags.error(DiagCode::FileWrite, SourceRef{target.string(), 0, 0},
                  std::string("cannot write output file: ") + std::strerror(err ? err : EIO));
      return false;
    }
    staged.emplace_back(tmp, target.string());
  }
  for (const auto& [tmp, fin] : staged) {
    if (std::rename(tmp.c_str(), fin.c_str()) != 0) {
      int err = errno;
      cleanup();
      diags.error(DiagCode::FileWrite, SourceRef{fin, 0, 0}, std::string("cannot rename output file: ") + std::strerror(err));
      return false;
    }
  }
  return true;
}

bool writeFileAtomically(const std::string& path, const std::string& contents, Diagnostics& diags) {
  std::filesystem::path target(path);
  std::string tmp = tempNameFor(target);
  if (!writeWhole(tmp, contents)) {
    int err = errno;
    std::remove(tmp.c_str());
    diags.error(DiagCode::FileWrite, SourceRef{path, 0, 0}, std::string("cannot write: ") + std::strerror(err ? err : EIO));
    return false;
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    int err = errno;
    std::remove(tmp.c_str());
    diags.error(DiagCode::FileWrite, SourceRef{path, 0, 0}, std::string("cannot replace: ") + std::strerror(err));
    return false;
  }
  return true;
}

}  // namespace wg
