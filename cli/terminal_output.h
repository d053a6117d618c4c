#pragma once
// Everything watergraph prints through std::cout and std::cerr passes a filter that escapes
// what a terminal would act on, the way diagnostics escape it (core/shown_text.h): a file
// name or a description from a graph holding ESC or BEL cannot clear the screen or set the
// window title, whichever message it reaches. Line feeds and tabs pass; a carriage return
// (which would let a name overwrite the line) does not. Lines written with printf (the
// progress bar's own escapes, compile's summary) escape their strings themselves.
#include <iostream>
#include <memory>
#include <string>

namespace wg::cli {

class EscapingBuffer : public std::streambuf {
 public:
  explicit EscapingBuffer(std::streambuf* to) : to_(to) {}
  ~EscapingBuffer() override;

 protected:
  int_type overflow(int_type c) override;
  std::streamsize xsputn(const char* s, std::streamsize n) override;
  int sync() override;

 private:
  void write(const char* s, std::size_t n, bool final);
  std::streambuf* to_;
  std::string pending_;  // the start of a UTF-8 sequence split between two writes
};

// Installs the filter on std::cout and std::cerr for its lifetime.
class TerminalSafeOutput {
 public:
  TerminalSafeOutput();
  ~TerminalSafeOutput();

 private:
  std::streambuf* cout_;
  std::streambuf* cerr_;
  std::unique_ptr<EscapingBuffer> outFilter_, errFilter_;
};

}  // namespace wg::cli
