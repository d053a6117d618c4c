#pragma once
// Text that came from a file or the command line (a file name, a description, a node id),
// made safe for where it is shown. Every string that reaches a terminal goes through
// escapedForTerminal, as diagnostics always have: ESC, BEL and the other control characters
// would otherwise act on the terminal (clear the screen, set the window title) or forge
// lines. Every string that reaches JSON goes through validUtf8: JSON text is UTF-8, and a
// file name need not be (nlohmann::json refuses to write such a string at all).
#include <string>
#include <string_view>

namespace wg {

// One line with nothing a terminal acts on: \n, \r and \t as those escapes; other control
// characters (C0, DEL, and C1 as UTF-8 encodes them, U+0080..U+009F) and bytes that are not
// UTF-8 as \xNN (each byte); printable UTF-8 unchanged.
std::string escapedForTerminal(std::string_view text);

// Several lines shown as escapedForTerminal shows one: line feeds and tabs (the text's own
// layout) are kept, everything else is escaped the same way.
std::string escapedKeepingLines(std::string_view text);

// `text` with each byte that is not part of valid UTF-8 written as the four characters \xNN
// (as escapedForTerminal writes it); valid UTF-8 unchanged.
std::string validUtf8(std::string_view text);

// The length of the valid UTF-8 sequence starting at text[i], or 0 when there is none.
std::size_t utf8SequenceLength(std::string_view text, std::size_t i);

}  // namespace wg
