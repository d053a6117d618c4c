#include "cli/terminal_output.h"

#include "core/shown_text.h"

namespace wg::cli {
namespace {

// The bytes a UTF-8 sequence starting with `lead` has, or 0 for a byte that starts none.
std::size_t expectedLength(unsigned char lead) {
  if (lead >= 0xc2 && lead <= 0xdf) return 2;
  if (lead >= 0xe0 && lead <= 0xef) return 3;
  if (lead >= 0xf0 && lead <= 0xf4) return 4;
  return 0;
}

}  // namespace

EscapingBuffer::~EscapingBuffer() { write("", 0, true); }

EscapingBuffer::int_type EscapingBuffer::overflow(int_type c) {
  if (traits_type::eq_int_type(c, traits_type::eof())) return traits_type::not_eof(c);
  char ch = traits_type::to_char_type(c);
  write(&ch, 1, false);
  return c;
}

std::streamsize EscapingBuffer::xsputn(const char* s, std::streamsize n) {
  write(s, static_cast<std::size_t>(n), false);
  return n;
}

int EscapingBuffer::sync() { return to_->pubsync(); }

void EscapingBuffer::write(const char* s, std::size_t n, bool final) {
  std::string text = pending_ + std::string(s, n);
  pending_.clear();
  // A sequence cut at the end of this write waits for the rest (unless nothing more comes).
  std::size_t keep = text.size();
  for (std::size_t back = 1; back <= 3 && back <= text.size(); ++back) {
    auto u = static_cast<unsigned char>(text[text.size() - back]);
    if (u < 0x80 || u >= 0xc0) {
      if (!final && expectedLength(u) > back) keep = text.size() - back;
      break;
    }
  }
  pending_ = text.substr(keep);
  // Line feeds and tabs are the program's own layout: written as they are.
  std::string out = escapedKeepingLines(std::string_view(text).substr(0, keep));
  to_->sputn(out.data(), static_cast<std::streamsize>(out.size()));
}

TerminalSafeOutput::TerminalSafeOutput() : cout_(std::cout.rdbuf()), cerr_(std::cerr.rdbuf()) {
  outFilter_ = std::make_unique<EscapingBuffer>(cout_);
  errFilter_ = std::make_unique<EscapingBuffer>(cerr_);
  std::cout.rdbuf(outFilter_.get());
  std::cerr.rdbuf(errFilter_.get());
}

TerminalSafeOutput::~TerminalSafeOutput() {
  std::cout.flush();
  std::cerr.flush();
  std::cout.rdbuf(cout_);
  std::cerr.rdbuf(cerr_);
  outFilter_.reset();  // writes what it still held
  errFilter_.reset();
}

}  // namespace wg::cli
