// The canonical graph text (`watergraph fmt`): fixed key order, 2-space indent, numbers via
// formatNumber, number arrays on one line, LF line endings, a final newline.
#include <algorithm>
#include <string>
#include <vector>

#include "core/graph_io.h"
#include "core/number_format.h"

namespace wg {

namespace {

using nlohmann::json;

std::string quote(std::string_view s) {
  return json(std::string(s)).dump(-1, ' ', false, json::error_handler_t::replace);
}

void indent(std::string& out, int level) { out.append(static_cast<std::size_t>(level) * 2, ' '); }

std::string numberArray(const std::vector<double>& xs) {
  std::string s = "[";
  for (std::size_t i = 0; i < xs.size(); ++i) {
    if (i) s += ", ";
    s += formatNumber(xs[i]);
  }
  return s + "]";
}

// Writes `v` at nesting `level` (the caller has already written any indent and key).
void writeJson(std::string& out, const json& v, int level) {
  switch (v.type()) {
    case json::value_t::null: out += "null"; return;
    case json::value_t::boolean: out += v.get<bool>() ? "true" : "false"; return;
    case json::value_t::number_integer: out += std::to_string(v.get<json::number_integer_t>()); return;
    case json::value_t::number_unsigned:
      out += std::to_string(v.get<json::number_unsigned_t>());
      return;
    case json::value_t::number_float: out += formatNumber(v.get<double>()); return;
    case json::value_t::string: out += quote(v.get_ref<const std::string&>()); return;
    case json::value_t::array: {
      if (v.empty()) {
        out += "[]";
        return;
      }
      bool allNumbers = std::all_of(v.begin(), v.end(), [](const json& e) { return e.is_number(); });
      if (allNumbers) {
        out += '[';
        for (std::size_t i = 0; i < v.size(); ++i) {
          if (i) out += ", ";
          writeJson(out, v[i], level);
        }
        out += ']';
        return;
      }
      out += "[\n";
      for (std::size_t i = 0; i < v.size(); ++i) {
        indent(out, level + 1);
        writeJson(out, v[i], level + 1);
        out += i + 1 < v.size() ? ",\n" : "\n";
      }
      indent(out, level);
      out += ']';
      return;
    }
    case json::value_t::object: {
      if (v.empty()) {
        out += "{}";
        return;
      }
      out += "{\n";
      std::size_t i = 0;
      for (auto it = v.begin(); it != v.end(); ++it, ++i) {  // nlohmann's objects are sorted
        indent(out, level + 1);
        out += quote(it.key());
        out += ": ";
        writeJson(out, it.value(), level + 1);
        out += i + 1 < v.size() ? ",\n" : "\n";
      }
      indent(out, level);
      out += '}';
      return;
    }
    default: out += "null"; return;  // binary/discarded never come from a graph file
  }
}

std::string sourceText(const InputSource& s) {
  switch (s.kind) {
    case InputSource::Kind::NodeOutput: return quote(s.name + "." + s.port);
    case InputSource::Kind::Parameter: return quote("$" + s.name);
    case InputSource::Kind::Literal:
      if (s.literal.size() == 1) return formatNumber(s.literal[0]);
      return numberArray(s.literal);
  }
  return "null";
}

// Collects "key": value members of one object and writes them with commas.
class ObjectWriter {
 public:
  ObjectWriter(std::string& out, int level) : out_(out), level_(level) {}
  // `text` is the already formatted value (may span lines, indented for level_ + 1).
  void member(std::string_view key, std::string text) {
    members_.emplace_back(quote(key), std::move(text));
  }
  void finish() {
    if (members_.empty()) {
      out_ += "{}";
      return;
    }
    out_ += "{\n";
    for (std::size_t i = 0; i < members_.size(); ++i) {
      indent(out_, level_ + 1);
      out_ += members_[i].first;
      out_ += ": ";
      out_ += members_[i].second;
      out_ += i + 1 < members_.size() ? ",\n" : "\n";
    }
    indent(out_, level_);
    out_ += '}';
  }

 private:
  std::string& out_;
  int level_;
  std::vector<std::pair<std::string, std::string>> members_;
};

std::string parameterText(const Parameter& p, int level) {
  std::string out;
  ObjectWriter w(out, level);
  w.member("type", quote(typeName(p.type)));
  w.member("default", p.defaultValue.size() == 1 ? formatNumber(p.defaultValue[0])
                                                 : numberArray(p.defaultValue));
  if (p.min) w.member("min", formatNumber(*p.min));
  if (p.max) w.member("max", formatNumber(*p.max));
  if (!p.hint.empty()) w.member("hint", quote(p.hint));
  if (!p.description.empty()) w.member("description", quote(p.description));
  if (p.isStatic) w.member("static", "true");
  w.finish();
  return out;
}

// A preset on one line per parameter, in file order (the author's grouping).
std::string presetText(const Preset& preset, int level) {
  std::string out;
  ObjectWriter w(out, level);
  for (const auto& v : preset.values) {
    if (v.isOption()) {
      std::string value;
      writeJson(value, v.optionValue, level + 1);
      w.member(v.node + "." + v.option, std::move(value));
      continue;
    }
    w.member(v.parameter, v.value.size() == 1 ? formatNumber(v.value[0]) : numberArray(v.value));
  }
  w.finish();
  return out;
}

std::string nodeText(const Node& n, int level) {
  std::string out;
  ObjectWriter w(out, level);
  w.member("id", quote(n.id));
  w.member("type", quote(n.type));
  if (!n.options.empty()) {
    std::vector<const NodeOption*> opts;
    for (const auto& o : n.options) opts.push_back(&o);
    std::stable_sort(opts.begin(), opts.end(),
                     [](const NodeOption* a, const NodeOption* b) { return a->name < b->name; });
    std::string text;
    ObjectWriter ow(text, level + 1);
    for (const auto* o : opts) {
      std::string value;
      writeJson(value, o->value, level + 2);
      ow.member(o->name, std::move(value));
    }
    ow.finish();
    w.member("options", std::move(text));
  }
  if (!n.inputs.empty()) {
    std::vector<const NodeInput*> ins;
    for (const auto& in : n.inputs) ins.push_back(&in);
    std::stable_sort(ins.begin(), ins.end(),
                     [](const NodeInput* a, const NodeInput* b) { return a->port < b->port; });
    std::string text;
    ObjectWriter iw(text, level + 1);
    for (const auto* in : ins) iw.member(in->port, sourceText(in->source));
    iw.finish();
    w.member("inputs", std::move(text));
  }
  if (n.editorPosition) {
    w.member("editor", "{\"x\": " + formatNumber((*n.editorPosition)[0]) +
                           ", \"y\": " + formatNumber((*n.editorPosition)[1]) + "}");
  }
  w.finish();
  return out;
}

std::string outputsText(const Graph& g, int level) {
  std::vector<const GraphOutput*> outs;
  for (const auto& o : g.outputs) outs.push_back(&o);
  std::stable_sort(outs.begin(), outs.end(),
                   [](const GraphOutput* a, const GraphOutput* b) { return a->slot < b->slot; });
  std::string out;
  ObjectWriter w(out, level);
  // One object per stage, in table order (the rows of a stage are adjacent).
  std::string_view stage;
  for (const auto& row : outputSlotTable()) {
    if (row.stageName == stage) continue;
    stage = row.stageName;
    std::string text;
    ObjectWriter sw(text, level + 1);
    bool any = false;
    for (const auto* o : outs) {
      const OutputSlotRow& slot = outputSlotRow(o->slot);
      if (slot.stageName != stage) continue;
      sw.member(slot.portName, sourceText(o->source));
      any = true;
    }
    if (!any) continue;
    sw.finish();
    w.member(stage, std::move(text));
  }
  w.finish();
  return out;
}

// The interface's outputs in file order (the order an instance's ports are listed in).
std::string interfaceText(const GraphInterface& itf, int level) {
  std::string out;
  ObjectWriter w(out, level);
  if (!itf.description.empty()) w.member("description", quote(itf.description));
  std::string outputs;
  ObjectWriter ow(outputs, level + 1);
  for (const auto& o : itf.outputs) {
    std::string text;
    ObjectWriter one(text, level + 2);
    one.member("type", quote(typeName(o.type)));
    one.member("source", sourceText(o.source));
    if (!o.description.empty()) one.member("description", quote(o.description));
    one.finish();
    ow.member(o.name, std::move(text));
  }
  ow.finish();
  w.member("outputs", std::move(outputs));
  w.finish();
  return out;
}

}  // namespace

std::string saveGraph(const Graph& graph) {
  std::string out;
  ObjectWriter w(out, 0);
  if (!graph.schema.empty()) w.member("$schema", quote(graph.schema));
  w.member("version", std::to_string(graph.version));
  w.member("name", quote(graph.name));
  if (!graph.description.empty()) w.member("description", quote(graph.description));
  if (graph.view) {
    std::string text;
    ObjectWriter vw(text, 1);
    vw.member("tonemap", quote(std::string(toneMapperName(graph.view->toneMapper))));
    vw.member("exposure", formatNumber(graph.view->exposureEv));
    vw.finish();
    w.member("view", std::move(text));
  }
  if (!graph.imports.empty()) {
    std::string text;
    ObjectWriter iw(text, 1);
    for (const auto& im : graph.imports) iw.member(im.name, quote(im.path));
    iw.finish();
    w.member("imports", std::move(text));
  }
  if (graph.interface) w.member("interface", interfaceText(*graph.interface, 1));
  if (!graph.parameters.empty()) {
    std::string text;
    ObjectWriter pw(text, 1);
    for (const auto& p : graph.parameters) pw.member(p.name, parameterText(p, 2));
    pw.finish();
    w.member("parameters", std::move(text));
  }
  if (!graph.presets.empty()) {
    std::string text;
    ObjectWriter pw(text, 1);
    for (const auto& preset : graph.presets) pw.member(preset.name, presetText(preset, 2));
    pw.finish();
    w.member("presets", std::move(text));
  }
  {
    std::string text;
    if (graph.nodes.empty()) {
      text = "[]";
    } else {
      text = "[\n";
      for (std::size_t i = 0; i < graph.nodes.size(); ++i) {
        indent(text, 2);
        text += nodeText(graph.nodes[i], 2);
        text += i + 1 < graph.nodes.size() ? ",\n" : "\n";
      }
      indent(text, 1);
      text += ']';
    }
    w.member("nodes", std::move(text));
  }
  if (!graph.outputs.empty() || !graph.interface) w.member("outputs", outputsText(graph, 1));
  w.finish();
  out += '\n';
  return out;
}

}  // namespace wg
