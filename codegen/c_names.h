#pragma once
// The C identifiers of the generated C header (`compile --target query-c`, and its
// JavaScript twin's names), unique by construction.
//
// A name from a graph (a parameter's, a graph file's base name, which may be any bytes)
// becomes one C identifier by an injective map:
//   - a *plain* name stays as it is: it starts with a letter, holds only [A-Za-z0-9_],
//     has no "__" and does not end in '_', is no C/C++ keyword, no macro a C compiler
//     predefines or a standard C header defines (linux, unix, errno, stdin, complex ...),
//     not all in capitals (the macro convention: NAN, M_PI), and does not start with "zz"
//     or "wg" in any case (the escaped names' and watergraph's own);
//   - every other name is escaped: "zz" followed by the name with each byte outside
//     [A-Za-z0-9] written '_' and two lowercase hex digits ("int" -> "zzint",
//     "a-b" -> "zza_2db", "__x" -> "zz_5f_5fx", "int_" -> "zzint_5f").
// Plain names and escaped names are disjoint sets (only escaped ones start with "zz"), and
// the escape code is a prefix code, so two different names never give one identifier. No
// result contains "__", starts with '_' or a digit, or ends in '_' (C and C++ reserve the
// first two; the last keeps "wg_" + name + "_" free of "__").
//
// Global names are "wg_" + cIdentifier(graph) + "_" + suffix, one suffix per thing a
// header declares (cHeaderSuffixes()). The suffixes are tail-free: none ends in "_" + another
// one, so graph "a"'s "wg_a_displace_batch" can never be graph "a_displace"'s "wg_a_displace_"
// + a suffix. Include guards are "WG_" + cIdentifier(graph) + "_" + kind + "_H".
#include <string>
#include <string_view>
#include <vector>

namespace wg {

// The injective map above.
std::string cIdentifier(std::string_view name);

// Whether `name` stays as it is (the "plain" names above).
bool isPlainCName(std::string_view name);

// "wg_" + cIdentifier(graphName) + "_": what every global name of a graph's headers starts with.
std::string cGraphPrefix(std::string_view graphName);

// "WG_" + cIdentifier(graphName) + "_" + kind + "_H" ("QUERY").
std::string cIncludeGuard(std::string_view graphName, std::string_view kind);

// Every suffix a header appends to cGraphPrefix() (tests hold the header to this list and
// the list to the tail-free rule).
const std::vector<std::string_view>& cHeaderSuffixes();

}  // namespace wg

namespace wg {

// `text` (a graph or file name) safe inside a C or JavaScript block comment: bytes outside
// printable ASCII become '?', and "*/" becomes "*?".
std::string cCommentText(std::string_view text);

}  // namespace wg
