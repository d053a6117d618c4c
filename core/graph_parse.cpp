// Graph format v1 (docs/graph-format.md): one file's JSON events -> Graph, with no DOM of the
// file. Reports as many problems as it can in one pass; any error makes the result empty.
// The imports the graph names are not followed here (core/graph_load.h does that).
#include "core/graph_parse.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <string>

#include "core/file_read.h"
#include "core/graph_parser.h"
#include "core/json_events.h"
#include "core/load_limits.h"
#include "core/number_format.h"
#include "core/view_transform.h"

namespace wg {
namespace parsing {

std::optional<Graph> GraphParser::load() {
  const size_t before = diags_.errorCount();
  Graph g;
  g.file = file_;
  const DraftValue& root = this->root();
  if (root.type != json::value_t::object) {
    diags_.error(DiagCode::WrongJsonType, ref(root.at),
                 "the graph must be a JSON object, found " + jsonTypeName(root.type));
    return std::nullopt;
  }
  diags_.append(limits_);

  checkKeys(root, "the graph",
            {"$schema", "version", "name", "description", "view", "imports", "interface", "parameters", "presets",
             "nodes", "outputs", "editor"});

  if (!loadVersion(root, g)) return std::nullopt;  // a newer format: the rest is moot

  if (auto* v = field(root, "$schema", json::value_t::string, "'$schema'"))
    g.schema = v->value.get<std::string>();

  if (!root.member("name")) {
    missing(root, "the graph is missing \"name\"");
  } else if (auto* v = field(root, "name", json::value_t::string, "'name'")) {
    g.name = v->value.get<std::string>();
    if (!isIdentifier(g.name))
      diags_.error(DiagCode::InvalidIdentifier, ref(v->at),
                   "graph name '" + g.name + "' is not an identifier " + kIdentifierRule);
  }
  if (auto* v = field(root, "description", json::value_t::string, "'description'"))
    g.description = v->value.get<std::string>();

  if (auto* v = field(root, "view", json::value_t::object, "'view'")) loadView(*v, g);
  if (auto* v = field(root, "imports", json::value_t::object, "'imports'")) loadImportList(*v, g);
  if (auto* v = field(root, "parameters", json::value_t::object, "'parameters'")) loadParameters(*v, g);
  if (auto* v = field(root, "presets", json::value_t::object, "'presets'")) loadPresets(*v, g);

  if (!root.member("nodes")) {
    missing(root, "the graph is missing \"nodes\"");
  } else if (auto* v = field(root, "nodes", json::value_t::array, "'nodes'")) {
    if (nodeCount() > kMaxNodes) {
      diags_.error(DiagCode::LimitExceeded, ref(v->at),
                   "the graph has " + std::to_string(nodeCount()) + " nodes; the limit is " +
                       std::to_string(kMaxNodes));
    } else {
      diags_.append(nodeDiags_);
      g.nodes = std::move(nodes_);
    }
  }

  // A function graph needs no output slots: it is used through its interface (and may
  // still connect slots, to be previewed on its own).
  if (!root.member("outputs")) {
    if (!root.member("interface")) missing(root, "the graph is missing \"outputs\"");
    g.outputsWhere = ref(root.at);
  } else if (auto* v = field(root, "outputs", json::value_t::object, "'outputs'")) {
    loadOutputs(*v, g);
  }
  if (auto* v = field(root, "interface", json::value_t::object, "'interface'")) loadInterface(*v, g);
  if (auto* v = field(root, "editor", json::value_t::object, "'editor'")) loadEditorLayout(*v, g);

  if (diags_.errorCount() > before) return std::nullopt;
  return g;
}

// Every string (and key) within the length limit, every number finite float32.
void GraphParser::seenScalar(const JsonScalar& v, JsonPosition at) {
  if (v.type == json::value_t::string) {
    if (v.string->size() > kMaxStringBytes)
      limits_.error(DiagCode::LimitExceeded, ref(at),
                    "string of " + std::to_string(v.string->size()) + " bytes is longer than the limit of " +
                        std::to_string(kMaxStringBytes));
  } else if (v.type == json::value_t::number_float) {
    // 64-bit integers are far inside float32's range (about 3.4e38).
    if (!std::isfinite(v.number) || std::fabs(v.number) > kFloat32Max)
      limits_.error(DiagCode::NonFiniteLiteral, ref(at), "number " + formatNumber(v.number) + " is outside float32 range");
  }
}

void GraphParser::seenKey(const std::string& name, JsonPosition at) {
  if (name.size() > kMaxStringBytes)
    limits_.error(DiagCode::LimitExceeded, ref(at),
                  "key of " + std::to_string(name.size()) + " bytes is longer than the limit of " +
                      std::to_string(kMaxStringBytes));
}

// Every member key of the object `obj` is one of `allowed`; an error per other key.
void GraphParser::checkKeys(const DraftValue& obj, std::string_view what, std::initializer_list<std::string_view> allowed,
               const std::string& node, Diagnostics* to) {
  Diagnostics& out = to ? *to : diags_;
  std::string expected;
  for (const DraftValue& member : obj.members) {
    bool ok = false;
    for (std::string_view a : allowed) ok = ok || member.name == a;
    if (ok) continue;
    if (expected.empty())
      for (std::string_view a : allowed) {
        if (!expected.empty()) expected += ", ";
        expected += a;
      }
    out.error(DiagCode::UnknownField, ref(member.key),
              "unknown field '" + member.name + "' in " + std::string(what) + " (expected " + expected + ")", node);
  }
}

void GraphParser::missing(const DraftValue& obj, const std::string& message, const std::string& node,
             Diagnostics* to) {
  (to ? *to : diags_).error(DiagCode::MissingField, ref(obj.at), message, node);
}

bool GraphParser::loadVersion(const DraftValue& root, Graph& g) {
  const DraftValue* it = root.member("version");
  const std::string expect = "this is graph format " + std::to_string(kGraphFormatVersion);
  if (!it) {
    diags_.error(DiagCode::UnsupportedVersion, ref(root.at), "missing \"version\": " + expect);
    return true;
  }
  if (!it->value.is_number_integer()) {
    diags_.error(DiagCode::UnsupportedVersion, ref(it->at),
                 "\"version\" must be an integer, found " + describeValue(it->value) + ": " + expect);
    return true;
  }
  long long v = it->value.is_number_unsigned()
                    ? static_cast<long long>(std::min<unsigned long long>(it->value.get<unsigned long long>(), 1ull << 62))
                    : it->value.get<long long>();
  if (v > kGraphFormatVersion) {
    diags_.error(DiagCode::UnsupportedVersion, ref(it->at),
                 "graph format version " + std::to_string(v) + " is newer than this watergraph supports (" +
                     std::to_string(kGraphFormatVersion) + ")");
    return false;
  }
  if (v < 1) {
    diags_.error(DiagCode::UnsupportedVersion, ref(it->at),
                 "graph format version " + std::to_string(v) + " does not exist: " + expect);
    return true;
  }
  g.version = static_cast<int>(v);
  return true;
}

// "imports": {"foam": "lib/shore_foam.json"}: names (identifiers) for graph files, which
// core/graph_imports.h loads; whether a name is free of node types is resolve's to say.
// "view": {"tonemap": "agx", "exposure": 0.5}, both optional (none, 0 EV).
void GraphParser::loadView(const DraftValue& vv, Graph& g) {
  checkKeys(vv, "'view'", {"tonemap", "exposure"});
  ViewTransform view;
  if (auto* t = field(vv, "tonemap", json::value_t::string, "the view's 'tonemap'")) {
    const std::string name = t->value.get<std::string>();
    if (auto mapper = parseToneMapper(name)) view.toneMapper = *mapper;
    else
      diags_.error(DiagCode::InvalidView, ref(t->at),
                   "unknown tone mapper '" + name + "' in 'view' (expected " + toneMapperList() + ")");
  }
  if (auto* e = field(vv, "exposure", json::value_t::number_float, "the view's 'exposure'")) {
    view.exposureEv = e->value.get<double>();
    if (!(view.exposureEv >= kMinExposureEv && view.exposureEv <= kMaxExposureEv))
      diags_.error(DiagCode::InvalidView, ref(e->at),
                   "exposure " + formatNumber(view.exposureEv) + " EV in 'view' is outside [" +
                       formatNumber(kMinExposureEv) + ", " + formatNumber(kMaxExposureEv) + "]");
  }
  g.view = view;
}

void GraphParser::loadImportList(const DraftValue& imports, Graph& g) {
  for (const DraftValue& iv : imports.members) {
    Import im;
    im.name = iv.name;
    im.where = ref(iv.key);
    im.pathWhere = ref(iv.at);
    if (!isIdentifier(im.name))
      diags_.error(DiagCode::InvalidIdentifier, im.where,
                   "import name '" + im.name + "' is not an identifier " + kIdentifierRule);
    if (iv.type != json::value_t::string) {
      diags_.error(DiagCode::WrongJsonType, ref(iv.at),
                   "import '" + im.name + "' must be a path (a string), found " + jsonTypeName(iv.type));
      continue;
    }
    im.path = iv.value.get<std::string>();
    if (im.path.empty()) {
      diags_.error(DiagCode::ImportMissing, im.pathWhere, "import '" + im.name + "' names no file (an empty path)");
      continue;
    }
    g.imports.push_back(std::move(im));
  }
}

}  // namespace parsing

namespace {

constexpr char kTypeKeyText[] = "\"type\"";

// How many nodes to make room for before the events say: every node has a "type" key (so
// do parameters, a few). Growing the vector instead moved every Node built so far, into
// fresh pages, at each doubling: a quarter of a 1,000-node load. One scan of the text costs
// about a hundredth of its parse.
std::size_t expectedNodes(std::string_view text) {
  static const std::boyer_moore_horspool_searcher<const char*> kTypeKey(kTypeKeyText, kTypeKeyText + 6);
  std::size_t count = 0;
  for (auto at = text.begin(); count <= kMaxNodes; ++count) {
    at = std::search(at, text.end(), kTypeKey);
    if (at == text.end()) break;
    at += 6;
  }
  return count;
}


// WG035 for a text over the file limit, before anything is copied or parsed.
bool withinFileLimit(std::string_view text, const std::string& file, Diagnostics& diags) {
  if (text.size() <= kMaxFileBytes) return true;
  diags.error(DiagCode::LimitExceeded, SourceRef{file, 0, 0},
              "the file is " + std::to_string(text.size()) + " bytes; the limit is 16 MiB");
  return false;
}

}  // namespace

std::optional<Graph> parseGraph(std::shared_ptr<const std::string> shared, const std::string& file, Diagnostics& diags) {
  std::string_view text = *shared;
  if (!withinFileLimit(text, file, diags)) return std::nullopt;
  // Positions after parsing need the lines (an expression's formula error is placed by the
  // escapes before it; SARIF counts UTF-16 columns): the text parsed is kept, never read twice.
  diags.keepSource(file, std::move(shared));
  parsing::GraphParser loader(file, diags, expectedNodes(text));
  if (!parseJsonEvents(text, file, diags, loader)) return std::nullopt;
  return loader.load();
}

std::optional<Graph> parseGraph(std::string_view text, const std::string& file, Diagnostics& diags) {
  if (!withinFileLimit(text, file, diags)) return std::nullopt;
  return parseGraph(std::make_shared<const std::string>(text), file, diags);
}

std::optional<std::string> readGraphFile(const std::string& path, Diagnostics& diags) {
  // Opened once and read from that descriptor (core/file_read.h); a graph may come from a
  // pipe, so a FIFO is read too (a folder is refused).
  FileReadRule rule;
  rule.maxBytes = kMaxFileBytes;
  rule.regularOnly = false;
  FileReadFailure failure;
  auto text = readFileChecked(path, rule, &failure);
  if (text) return std::move(text->bytes);
  SourceRef where{path, 0, 0};
  if (failure.kind == FileReadFailure::Kind::TooLarge)
    diags.error(DiagCode::LimitExceeded, where, "'" + path + "' is larger than the limit of 16 MiB");
  else
    diags.error(DiagCode::FileRead, where, "cannot read '" + path + "': " + failure.why());
  return std::nullopt;
}

}  // namespace wg
