#include "editor/layout_patch.h"

#include <algorithm>
#include <cctype>
#include <vector>

#include "core/graph_io.h"
#include "core/number_format.h"

namespace wg::editor {
namespace {

// The canonical text of `g` without any node position or frame: equal for two graphs that
// differ only in their layout.
std::string withoutLayout(Graph g) {
  for (Node& n : g.nodes) n.editorPosition.reset();
  g.frames.clear();
  return saveGraph(g);
}

std::string quotedLayoutString(const std::string& s) {
  return nlohmann::json(s).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

bool sameFrames(const std::vector<Frame>& a, const std::vector<Frame>& b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](const Frame& x, const Frame& y) {
    return x.id == y.id && x.title == y.title && x.comment == y.comment && x.nodes == y.nodes;
  });
}

// The graph's "editor" value with `frames`, one frame per line (an empty "frames" when none).
std::string layoutText(const std::vector<Frame>& frames) {
  std::string s = "{\"frames\": {";
  for (size_t i = 0; i < frames.size(); ++i) {
    const Frame& f = frames[i];
    s += (i ? ",\n    " : "\n    ") + quotedLayoutString(f.id) + ": {";
    if (!f.title.empty()) s += "\"title\": " + quotedLayoutString(f.title) + ", ";
    if (!f.comment.empty()) s += "\"comment\": " + quotedLayoutString(f.comment) + ", ";
    s += "\"nodes\": [";
    for (size_t j = 0; j < f.nodes.size(); ++j) s += (j ? ", " : "") + quotedLayoutString(f.nodes[j]);
    s += "]}";
  }
  return s + (frames.empty() ? "}}" : "\n  }}");
}

std::optional<size_t> offsetOf(const std::string& text, const SourceRef& at) {
  if (at.line < 1 || at.col < 1) return std::nullopt;
  size_t offset = 0;
  for (int line = 1; line < at.line; ++line) {
    offset = text.find('\n', offset);
    if (offset == std::string::npos) return std::nullopt;
    ++offset;
  }
  offset += static_cast<size_t>(at.col - 1);
  return offset < text.size() ? std::optional<size_t>(offset) : std::nullopt;
}

// Past the JSON string starting at text[i] == '"'.
size_t skipString(const std::string& text, size_t i) {
  for (++i; i < text.size(); ++i) {
    if (text[i] == '\\') ++i;
    else if (text[i] == '"') return i + 1;
  }
  return text.size();
}

struct NodeObjectSpans {
  size_t editorValueBegin = std::string::npos, editorValueEnd = std::string::npos;  // the "editor" value
  size_t close = std::string::npos;  // the object's '}'
};

// The node object starting at text[open] == '{': where its "editor" value and its end are.
// (The graph's root object is scanned the same way for its own "editor" value, the frames.)
std::optional<NodeObjectSpans> scanNodeObject(const std::string& text, size_t open) {
  if (open >= text.size() || text[open] != '{') return std::nullopt;
  NodeObjectSpans spans;
  int depth = 0;
  bool expectKey = true;
  size_t valueStart = std::string::npos;
  std::string lastKey;
  for (size_t i = open; i < text.size();) {
    char c = text[i];
    if (c == '"') {
      size_t end = skipString(text, i);
      if (depth == 1 && expectKey) lastKey = text.substr(i + 1, end - i - 2), expectKey = false;
      i = end;
      continue;
    }
    if (c == ':' && depth == 1) {
      valueStart = i + 1;
      while (valueStart < text.size() && std::isspace(static_cast<unsigned char>(text[valueStart]))) ++valueStart;
      if (lastKey == "editor") spans.editorValueBegin = valueStart;
    } else if (c == '{' || c == '[') {
      ++depth;
    } else if (c == '}' || c == ']') {
      --depth;
      if (depth == 1 && lastKey == "editor" && spans.editorValueBegin != std::string::npos &&
          spans.editorValueEnd == std::string::npos)
        spans.editorValueEnd = i + 1;
      if (depth == 0) {
        spans.close = i;
        return spans;
      }
    } else if (c == ',' && depth == 1) {
      expectKey = true;
    }
    ++i;
  }
  return std::nullopt;
}

std::string positionText(const std::array<double, 2>& p) {
  return "{\"x\": " + formatNumber(p[0]) + ", \"y\": " + formatNumber(p[1]) + "}";
}

}  // namespace

std::optional<std::string> patchLayoutOnly(const std::string& diskText, const Graph& onDisk, const Graph& edited) {
  // A canonical file (positions aside: the layout fills in missing ones) stays canonical.
  Diagnostics asWrittenErrors;
  auto asWritten = parseGraph(diskText, onDisk.file, asWrittenErrors);
  if (!asWritten || saveGraph(*asWritten) == diskText) return std::nullopt;
  if (onDisk.nodes.size() != edited.nodes.size() || withoutLayout(onDisk) != withoutLayout(edited)) return std::nullopt;
  struct Replacement {
    size_t begin, end;
    std::string text;
  };
  std::vector<Replacement> replacements;
  for (size_t i = 0; i < edited.nodes.size(); ++i) {
    const Node& now = edited.nodes[i];
    const Node& was = onDisk.nodes[i];
    if (now.id != was.id || !now.editorPosition) return std::nullopt;
    auto open = offsetOf(diskText, was.where);
    auto spans = open ? scanNodeObject(diskText, *open) : std::nullopt;
    if (!spans) return std::nullopt;
    if (spans->editorValueBegin != std::string::npos) {
      if (now.editorPosition == was.editorPosition) continue;
      if (spans->editorValueEnd == std::string::npos) return std::nullopt;
      replacements.push_back({spans->editorValueBegin, spans->editorValueEnd, positionText(*now.editorPosition)});
    } else {
      // A node laid out when loaded: its position joins the object, as a save always wrote it.
      size_t last = spans->close;
      while (last > *open && std::isspace(static_cast<unsigned char>(diskText[last - 1]))) --last;
      bool empty = diskText[last - 1] == '{';
      replacements.push_back({last, last, std::string(empty ? "" : ", ") + "\"editor\": " + positionText(*now.editorPosition)});
    }
  }
  if (!sameFrames(onDisk.frames, edited.frames)) {
    // The frames changed: the root's "editor" value is written again, or added last.
    size_t root = diskText.find_first_not_of(" \t\r\n");
    auto spans = root == std::string::npos ? std::nullopt : scanNodeObject(diskText, root);
    if (!spans) return std::nullopt;
    if (spans->editorValueBegin != std::string::npos) {
      if (spans->editorValueEnd == std::string::npos) return std::nullopt;
      replacements.push_back({spans->editorValueBegin, spans->editorValueEnd, layoutText(edited.frames)});
    } else {
      size_t last = spans->close;
      while (last > root && std::isspace(static_cast<unsigned char>(diskText[last - 1]))) --last;
      replacements.push_back({last, last, ",\n  \"editor\": " + layoutText(edited.frames)});
    }
  }
  std::string text = diskText;
  std::sort(replacements.begin(), replacements.end(), [](const Replacement& a, const Replacement& b) { return a.begin > b.begin; });
  for (const Replacement& r : replacements) text.replace(r.begin, r.end - r.begin, r.text);
  // Only what reads back as the edited graph is written this way.
  Diagnostics d;
  auto reread = parseGraph(text, onDisk.file, d);
  if (!reread) return std::nullopt;
  if (saveGraph(*reread) != saveGraph(edited)) return std::nullopt;
  return text;
}

}  // namespace wg::editor
