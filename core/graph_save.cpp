// The canonical graph text (`watergraph fmt`): fixed key order, 2-space indent, numbers via
// formatNumber, number arrays on one line, containers on one line where they fit within 100
// columns, LF line endings, a final newline.
#include <algorithm>
#include <string>
#include <vector>

#include "core/graph_save.h"
#include "core/instance_options.h"
#include "core/number_format.h"

namespace wg {

namespace {

using nlohmann::json;

std::string quote(std::string_view s) {
  return json(std::string(s)).dump(-1, ' ', false, json::error_handler_t::replace);
}

void indent(std::string& out, int level) { out.append(static_cast<std::size_t>(level) * 2, ' '); }

// The widest line a value is folded onto (when it has no line breaks of its own).
constexpr std::size_t kMaxColumns = 100;

// A value to be written: an atom (already formatted), or an object or array of values. The
// layout is decided when writing: a container goes on one line where it fits within
// kMaxColumns, counted from where it starts (so an editor position or a node's literal
// inputs stay on one line, as people write them), else one member per line. The choice
// depends only on the values, so the text is canonical and fmt is idempotent.
struct Doc {
  enum class Kind { Atom, Object, Array } kind = Kind::Atom;
  std::string atom;
  std::vector<std::string> keys;  // an object's quoted keys, one per item
  std::vector<Doc> items;         // an array's elements, or an object's values
  bool alwaysFlat = false;     // number arrays: one line however long (a colour, a vector)
  bool neverFlat = false;      // the tables a file is read by: one entry per line

  static Doc of(std::string text) {
    Doc d;
    d.atom = std::move(text);
    return d;
  }
};

// The one-line form of `d`.
std::string flat(const Doc& d) {
  switch (d.kind) {
    case Doc::Kind::Atom: return d.atom;
    case Doc::Kind::Object: {
      std::string s = "{";
      for (std::size_t i = 0; i < d.items.size(); ++i) {
        if (i) s += ", ";
        s += d.keys[i] + ": " + flat(d.items[i]);
      }
      return s + "}";
    }
    case Doc::Kind::Array: {
      std::string s = "[";
      for (std::size_t i = 0; i < d.items.size(); ++i) {
        if (i) s += ", ";
        s += flat(d.items[i]);
      }
      return s + "]";
    }
  }
  return {};
}

bool mayBeFlat(const Doc& d) {
  if (d.neverFlat) return false;
  for (const auto& item : d.items)
    if (!mayBeFlat(item)) return false;
  return true;
}

// Writes `d` at nesting `level`, starting at `column` (the caller has written the indent
// and key before it).
void write(std::string& out, const Doc& d, int level, std::size_t column) {
  const bool empty = d.items.empty();
  if (d.kind == Doc::Kind::Atom || empty || d.alwaysFlat) {
    out += flat(d);
    return;
  }
  if (mayBeFlat(d)) {
    std::string one = flat(d);
    if (column + one.size() + 1 <= kMaxColumns) {  // + 1: a comma may follow
      out += one;
      return;
    }
  }
  const bool object = d.kind == Doc::Kind::Object;
  out += object ? "{\n" : "[\n";
  const std::size_t n = d.items.size();
  for (std::size_t i = 0; i < n; ++i) {
    indent(out, level + 1);
    std::size_t at = static_cast<std::size_t>(level + 1) * 2;
    if (object) {
      out += d.keys[i];
      out += ": ";
      at += d.keys[i].size() + 2;
    }
    write(out, d.items[i], level + 1, at);
    out += i + 1 < n ? ",\n" : "\n";
  }
  indent(out, level);
  out += object ? '}' : ']';
}

Doc numberArray(const std::vector<double>& xs) {
  Doc d;
  d.kind = Doc::Kind::Array;
  d.alwaysFlat = true;
  for (double x : xs) d.items.push_back(Doc::of(formatNumber(x)));
  return d;
}

Doc numbers(const std::vector<double>& xs) { return xs.size() == 1 ? Doc::of(formatNumber(xs[0])) : numberArray(xs); }

// A JSON value of the file as it was read (options, preset option values).
Doc jsonDoc(const json& v) {
  switch (v.type()) {
    case json::value_t::null: return Doc::of("null");
    case json::value_t::boolean: return Doc::of(v.get<bool>() ? "true" : "false");
    case json::value_t::number_integer: return Doc::of(std::to_string(v.get<json::number_integer_t>()));
    case json::value_t::number_unsigned: return Doc::of(std::to_string(v.get<json::number_unsigned_t>()));
    case json::value_t::number_float: return Doc::of(formatNumber(v.get<double>()));
    case json::value_t::string: return Doc::of(quote(v.get_ref<const std::string&>()));
    case json::value_t::array: {
      Doc d;
      d.kind = Doc::Kind::Array;
      d.alwaysFlat = !v.empty() && std::all_of(v.begin(), v.end(), [](const json& e) { return e.is_number(); });
      for (const auto& e : v) d.items.push_back(jsonDoc(e));
      return d;
    }
    case json::value_t::object: {
      Doc d;
      d.kind = Doc::Kind::Object;
      for (auto it = v.begin(); it != v.end(); ++it)  // nlohmann's objects are sorted
        d.keys.push_back(quote(it.key())), d.items.push_back(jsonDoc(it.value()));
      return d;
    }
    default: return Doc::of("null");  // binary/discarded never come from a graph file
  }
}

Doc sourceDoc(const InputSource& s) {
  switch (s.kind) {
    case InputSource::Kind::NodeOutput: return Doc::of(quote(s.name + "." + s.port));
    case InputSource::Kind::Parameter: return Doc::of(quote("$" + s.name));
    case InputSource::Kind::Literal: return numbers(s.literal);
  }
  return Doc::of("null");
}

// Collects "key": value members of one object.
class ObjectWriter {
 public:
  void member(std::string_view key, Doc value) {
    doc_.keys.push_back(quote(key));
    doc_.items.push_back(std::move(value));
  }
  void member(std::string_view key, std::string atom) { member(key, Doc::of(std::move(atom))); }
  Doc finish(bool neverFlat = false) {
    doc_.kind = Doc::Kind::Object;
    doc_.neverFlat = neverFlat;
    return std::move(doc_);
  }

 private:
  Doc doc_;
};

Doc parameterDoc(const Parameter& p) {
  ObjectWriter w;
  w.member("type", quote(typeName(p.type)));
  w.member("default", numbers(p.defaultValue));
  if (p.min) w.member("min", formatNumber(*p.min));
  if (p.max) w.member("max", formatNumber(*p.max));
  if (!p.hint.empty()) w.member("hint", quote(p.hint));
  if (!p.description.empty()) w.member("description", quote(p.description));
  if (p.isStatic) w.member("static", "true");
  return w.finish();
}

// A preset's values in file order (the author's grouping).
Doc presetDoc(const Preset& preset) {
  ObjectWriter w;
  for (const auto& v : preset.values) {
    if (v.isOption()) {
      w.member(v.node + "." + v.option, jsonDoc(v.optionValue));
      continue;
    }
    w.member(v.parameter, numbers(v.value));
  }
  return w.finish();
}

Doc nodeDoc(const Node& n) {
  ObjectWriter w;
  w.member("id", quote(n.id));
  w.member("type", quote(n.type));
  if (!n.options.empty()) {
    std::vector<const NodeOption*> opts;
    for (const auto& o : n.options) opts.push_back(&o);
    std::stable_sort(opts.begin(), opts.end(),
                     [](const NodeOption* a, const NodeOption* b) { return a->name < b->name; });
    ObjectWriter ow;
    for (const auto* o : opts) ow.member(o->name, jsonDoc(o->value));
    w.member("options", ow.finish());
  }
  if (!n.inputs.empty()) {
    std::vector<const NodeInput*> ins;
    for (const auto& in : n.inputs) ins.push_back(&in);
    std::stable_sort(ins.begin(), ins.end(),
                     [](const NodeInput* a, const NodeInput* b) { return a->port < b->port; });
    ObjectWriter iw;
    for (const auto* in : ins) iw.member(in->port, sourceDoc(in->source));
    w.member("inputs", iw.finish());
  }
  if (n.editorPosition) {
    ObjectWriter ew;
    ew.member("x", formatNumber((*n.editorPosition)[0]));
    ew.member("y", formatNumber((*n.editorPosition)[1]));
    w.member("editor", ew.finish());
  }
  return w.finish();
}

Doc outputsDoc(const Graph& g) {
  std::vector<const GraphOutput*> outs;
  for (const auto& o : g.outputs) outs.push_back(&o);
  std::stable_sort(outs.begin(), outs.end(),
                   [](const GraphOutput* a, const GraphOutput* b) { return a->slot < b->slot; });
  ObjectWriter w;
  // One object per stage, in table order (the rows of a stage are adjacent).
  std::string_view stage;
  for (const auto& row : outputSlotTable()) {
    if (row.stageName == stage) continue;
    stage = row.stageName;
    ObjectWriter sw;
    bool any = false;
    for (const auto* o : outs) {
      const OutputSlotRow& slot = outputSlotRow(o->slot);
      if (slot.stageName != stage) continue;
      sw.member(slot.portName, sourceDoc(o->source));
      any = true;
    }
    if (any) w.member(stage, sw.finish());
  }
  return w.finish();
}

// The interface's outputs in file order (the order an instance's ports are listed in).
Doc interfaceDoc(const GraphInterface& itf) {
  ObjectWriter w;
  if (!itf.description.empty()) w.member("description", quote(itf.description));
  if (!itf.options.empty()) {
    ObjectWriter optw;
    for (const auto& o : itf.options) {
      ObjectWriter one;
      one.member("type", quote(interfaceOptionKindName(o.kind)));
      if (!o.choices.empty()) one.member("choices", jsonDoc(json(o.choices)));
      if (o.min) one.member("min", formatNumber(*o.min));
      if (o.max) one.member("max", formatNumber(*o.max));
      if (!o.defaultValue.is_null()) one.member("default", jsonDoc(o.defaultValue));
      if (!o.description.empty()) one.member("description", quote(o.description));
      optw.member(o.name, one.finish());
    }
    w.member("options", optw.finish());
  }
  ObjectWriter ow;
  for (const auto& o : itf.outputs) {
    ObjectWriter one;
    one.member("type", quote(typeName(o.type)));
    one.member("source", sourceDoc(o.source));
    if (!o.description.empty()) one.member("description", quote(o.description));
    ow.member(o.name, one.finish());
  }
  w.member("outputs", ow.finish());
  return w.finish();
}

// "editor": {"frames": {...}}: the canvas's layout, last in the file (compiling never reads
// it, so it sits after everything that is compiled). Frames in file order, the order they
// are drawn in; a frame's nodes in its order.
Doc editorLayoutDoc(const Graph& g) {
  ObjectWriter fw;
  for (const Frame& f : g.frames) {
    ObjectWriter one;
    if (!f.title.empty()) one.member("title", quote(f.title));
    if (!f.comment.empty()) one.member("comment", quote(f.comment));
    one.member("nodes", jsonDoc(json(f.nodes)));
    fw.member(f.id, one.finish());
  }
  ObjectWriter w;
  w.member("frames", fw.finish(true));
  return w.finish();
}

}  // namespace

std::string saveGraph(const Graph& graph) {
  ObjectWriter w;
  if (!graph.schema.empty()) w.member("$schema", quote(graph.schema));
  w.member("version", std::to_string(graph.version));
  w.member("name", quote(graph.name));
  if (!graph.description.empty()) w.member("description", quote(graph.description));
  if (graph.view) {
    ObjectWriter vw;
    vw.member("tonemap", quote(std::string(toneMapperName(graph.view->toneMapper))));
    vw.member("exposure", formatNumber(graph.view->exposureEv));
    w.member("view", vw.finish());
  }
  if (!graph.imports.empty()) {
    ObjectWriter iw;
    for (const auto& im : graph.imports) iw.member(im.name, quote(im.path));
    w.member("imports", iw.finish());
  }
  if (graph.interface) w.member("interface", interfaceDoc(*graph.interface));
  // The tables a reader scans (parameters, presets, nodes) keep one entry per line; each
  // entry is folded onto its line where it fits.
  if (!graph.parameters.empty()) {
    ObjectWriter pw;
    for (const auto& p : graph.parameters) pw.member(p.name, parameterDoc(p));
    w.member("parameters", pw.finish(true));
  }
  if (!graph.presets.empty()) {
    ObjectWriter pw;
    for (const auto& preset : graph.presets) pw.member(preset.name, presetDoc(preset));
    w.member("presets", pw.finish(true));
  }
  Doc nodes;
  nodes.kind = Doc::Kind::Array;
  nodes.neverFlat = !graph.nodes.empty();
  for (const auto& n : graph.nodes) nodes.items.push_back(nodeDoc(n));
  w.member("nodes", std::move(nodes));
  if (!graph.outputs.empty() || !graph.interface) w.member("outputs", outputsDoc(graph));
  if (!graph.frames.empty()) w.member("editor", editorLayoutDoc(graph));
  std::string out;
  write(out, w.finish(true), 0, 0);
  out += '\n';
  return out;
}

}  // namespace wg
