#pragma once
// Columns inside a JSON string value: an error found in a formula (an `expression` node's
// option) names the byte of the decoded string, while the diagnostic must name the
// column in the file, where escapes (\", \\, \n, \u00e9, surrogate pairs) take more bytes
// than the characters they stand for. Columns count bytes, as everywhere in diagnostics.
#include <cstddef>
#include <string_view>

namespace wg {

// The 1-based file column of byte `decoded` of the string whose opening quote is at
// 1-based column `quoteColumn` of `line` (the text of the file's line). Past the string's
// end, or on a line that does not hold the string, the closing quote's column (or the
// line's end).
int jsonStringByteColumn(std::string_view line, int quoteColumn, std::size_t decoded);

}  // namespace wg
