#pragma once
// The limits a graph file must keep to load (docs/robustness.md), in one place: the loader
// enforces them on a file, and the edit model on every value it accepts, so that what the
// editor saves always loads again.
#include <cstddef>
#include <string>

#include <nlohmann/json_fwd.hpp>

namespace wg {

inline constexpr std::size_t kMaxFileBytes = 16u * 1024u * 1024u;
inline constexpr std::size_t kMaxNodes = 200000;  // in a file, and in a graph with its subgraphs inlined
inline constexpr int kMaxImportDepth = 16;         // graphs importing graphs, the top-level one not counted
inline constexpr std::size_t kMaxImportedBytes = 64u * 1024u * 1024u;  // all imported files of one graph together
inline constexpr std::size_t kMaxStringBytes = 4096;  // every string and key
// A graph's inlined size: each node of the graph with every subgraph instance replaced by
// its nodes, counted as the length of its full id ("shore/foam/mix": what every op it makes
// and its manifest entry hold) plus kInlinedNodeBytes for the rest of them. Predicted from
// the import tree before anything is inlined (counts multiply, so sixteen small files can
// stand for gigabytes), and checked again on the ops resolve makes (an expression's formula
// becomes many ops). Sized so that what is accepted compiles within about a minute and
// 2 GiB on a 2-core machine (docs/robustness.md).
inline constexpr std::size_t kInlinedNodeBytes = 64;
inline constexpr std::size_t kMaxInlinedBytes = 32u * 1024u * 1024u;
// The ops resolve may make for one graph: a node makes one, a few more for a node that
// derives inputs, an expression one per operation of its formula.
inline constexpr std::size_t kMaxOps = 2 * kMaxNodes;
inline constexpr double kFloat32Max = 3.4028234663852886e38;
inline constexpr int kMaxJsonDepth = 64;  // nested arrays and objects, the file's top level included
// A node option's value sits inside the top-level object, "nodes", the node and "options".
inline constexpr int kOptionValueDepth = 4;

// Finite, and inside float32's range: what a graph number must be.
bool fitsFloat32(double x);

// "" when a JSON value opened `depth` levels deep in a file keeps the limits every value of
// a graph file keeps (string and key lengths, numbers finite in float32, nesting), else why not.
std::string checkJsonLimits(const nlohmann::json& value, int depth);

}  // namespace wg
