// SPDX-License-Identifier: Apache-2.0
// The RSI context and Ethernet config readers (config.h): the element trees of xml_tree.h checked
// one element at a time, each error at the element's line.
#include "rsi/config.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <map>

namespace xmate::rsi {
namespace {

std::string upper(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = char(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

// Attribute names are matched without regard to case (TYPE, Type): be liberal in what we read.
const std::string* attributeAnyCase(const XmlElement& e, std::string_view name) {
  for (const auto& [key, value] : e.attributes)
    if (upper(key) == upper(name)) return &value;
  return nullptr;
}

[[noreturn]] void fail(const std::string& file, int line, const std::string& what) {
  throw ConfigError(file + ":" + std::to_string(line) + ": " + what);
}

bool parseInt(std::string_view text, long& out) {
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
  return ec == std::errc() && end == text.data() + text.size();
}

bool isIpv4(const std::string& s) {
  int parts = 0;
  size_t start = 0;
  while (start <= s.size()) {
    const size_t dot = std::min(s.find('.', start), s.size());
    long v = 0;
    if (dot == start || dot - start > 3 || !parseInt(std::string_view(s).substr(start, dot - start), v) || v > 255)
      return false;
    ++parts;
    start = dot + 1;
    if (dot == s.size()) break;
  }
  return parts == 4;
}

// The text of a required child of CONFIG.
const XmlElement& required(const XmlElement& parent, const char* name, const std::string& file) {
  const XmlElement* e = parent.child(name);
  if (!e) fail(file, parent.line, std::string("<") + parent.name + "> has no <" + name + ">; add it (see docs/rsi.md)");
  return *e;
}

ValueType parseType(const std::string* text, const std::string& file, int line, const std::string& tag) {
  if (!text) fail(file, line, "ELEMENT " + tag + " has no TYPE; give BOOL, STRING, LONG or DOUBLE");
  const std::string t = upper(*text);
  if (t == "BOOL") return ValueType::kBool;
  if (t == "STRING") return ValueType::kString;
  if (t == "LONG") return ValueType::kLong;
  if (t == "DOUBLE") return ValueType::kDouble;
  fail(file, line, "ELEMENT " + tag + ": unknown TYPE \"" + *text + "\"; give BOOL, STRING, LONG or DOUBLE");
}

bool isBuiltIn(const std::string& base, bool send) {
  const auto& names = send ? std::vector<std::string>(std::begin(kBuiltInSend), std::end(kBuiltInSend))
                           : std::vector<std::string>(std::begin(kBuiltInReceive), std::end(kBuiltInReceive));
  return std::find(names.begin(), names.end(), base) != names.end();
}

std::string builtInList(bool send) {
  std::string list;
  if (send)
    for (const char* n : kBuiltInSend) list += (list.empty() ? "" : ", ") + std::string(n);
  else
    for (const char* n : kBuiltInReceive) list += (list.empty() ? "" : ", ") + std::string(n);
  return list;
}

Channel parseChannel(const XmlElement& e, bool send, const std::string& file) {
  Channel c;
  c.line = e.line;
  const std::string* tag = attributeAnyCase(e, "TAG");
  if (!tag || tag->empty()) fail(file, e.line, "ELEMENT without a TAG; every element needs one, e.g. TAG=\"AK.A1\"");
  c.tag = *tag;
  c.type = parseType(attributeAnyCase(e, "TYPE"), file, e.line, c.tag);
  const size_t dot = c.tag.find('.');
  const std::string base = c.tag.substr(0, dot);
  c.element = base;
  if (dot != std::string::npos) {
    c.attribute = c.tag.substr(dot + 1);
    if (c.attribute.empty() || base.empty() || c.attribute.find('.') != std::string::npos)
      fail(file, e.line, "ELEMENT " + c.tag + ": a TAG is Name or Name.Attribute");
  }
  const std::string* index = attributeAnyCase(e, "INDX");
  if (!index) fail(file, e.line, "ELEMENT " + c.tag + " has no INDX; give the channel 1 to 64, or INTERNAL");
  const bool builtin_tag = base.rfind("DEF_", 0) == 0;
  if (upper(*index) == "INTERNAL") {
    if (!builtin_tag || !isBuiltIn(base, send))
      fail(file, e.line, "ELEMENT " + c.tag + ": INDX=\"INTERNAL\" is for the built-in values (" + builtInList(send) +
                             "); give a channel 1 to 64 for other tags");
    c.index = 0;
    c.element = base.substr(4);
  } else {
    long v = 0;
    if (!parseInt(*index, v) || v < 1 || v > 64)
      fail(file, e.line, "ELEMENT " + c.tag + ": INDX=\"" + *index + "\" is not a channel 1 to 64 or INTERNAL");
    if (builtin_tag) fail(file, e.line, "ELEMENT " + c.tag + ": DEF_ values are built in; give INDX=\"INTERNAL\"");
    c.index = int(v);
  }
  if (const std::string* hold = attributeAnyCase(e, "HOLDON")) {
    if (*hold != "0" && *hold != "1") fail(file, e.line, "ELEMENT " + c.tag + ": HOLDON=\"" + *hold + "\" is not 0 or 1");
    c.hold_on = *hold == "1";
  }
  return c;
}

std::vector<Channel> parseChannels(const XmlElement& root, const char* section, bool send, const std::string& file) {
  std::vector<Channel> out;
  const XmlElement* s = root.child(section);
  if (!s) return out;  // a config may leave RECEIVE (or SEND) out
  const XmlElement* elements = s->child("ELEMENTS");
  if (!elements) return out;
  std::map<std::string, const Channel*> by_tag;
  for (const XmlElement& e : elements->children) {
    if (e.name != "ELEMENT") continue;
    out.push_back(parseChannel(e, send, file));
  }
  for (size_t i = 0; i < out.size(); ++i) {
    const Channel& c = out[i];
    for (size_t k = 0; k < i; ++k) {
      const Channel& before = out[k];
      if (before.tag == c.tag)
        fail(file, c.line, std::string(section) + " has the TAG " + c.tag + " twice (also at line " +
                               std::to_string(before.line) + "); remove one");
      if (before.element != c.element) continue;
      if (before.attribute.empty() != c.attribute.empty())
        fail(file, c.line, std::string(section) + ": <" + c.element + "> is both a text element and attributes (" +
                               before.tag + " at line " + std::to_string(before.line) + ", " + c.tag + ")");
      if (before.type != c.type)
        fail(file, c.line, std::string(section) + ": " + c.tag + " is " + toString(c.type) + " but " + before.tag +
                               " (line " + std::to_string(before.line) + ") is " + toString(before.type) +
                               "; the attributes of one element share a TYPE");
    }
  }
  return out;
}

}  // namespace

const char* toString(ValueType type) {
  switch (type) {
    case ValueType::kBool: return "BOOL";
    case ValueType::kString: return "STRING";
    case ValueType::kLong: return "LONG";
    case ValueType::kDouble: return "DOUBLE";
  }
  return "?";
}

EthernetConfig parseEthernetConfig(std::string_view text, const std::string& name) {
  const XmlElement root = parseXml(text, name);
  EthernetConfig c;
  c.path = name;
  const XmlElement* config = root.child("CONFIG");
  if (!config) fail(name, root.line, "no <CONFIG> in <" + root.name + ">; is this an RSI Ethernet config?");
  c.ip = required(*config, "IP_NUMBER", name).text;
  c.ip_is_placeholder = !isIpv4(c.ip);
  const XmlElement& port = required(*config, "PORT", name);
  long p = 0;
  if (!parseInt(port.text, p) || p < 1 || p > 65535)
    fail(name, port.line, "PORT \"" + port.text + "\" is not a port number 1 to 65535");
  c.port = uint16_t(p);
  c.sentype = required(*config, "SENTYPE", name).text;
  if (c.sentype.empty()) fail(name, config->line, "SENTYPE is empty; give the datagrams' Type, e.g. ImFree");
  if (const XmlElement* only = config->child("ONLYSEND")) {
    const std::string v = upper(only->text);
    if (v != "TRUE" && v != "FALSE") fail(name, only->line, "ONLYSEND \"" + only->text + "\" is not TRUE or FALSE");
    c.only_send = v == "TRUE";
  }
  c.send = parseChannels(root, "SEND", true, name);
  c.receive = parseChannels(root, "RECEIVE", false, name);
  return c;
}

EthernetConfig readEthernetConfig(const std::string& path) {
  return parseEthernetConfig(readTextFile(path, "Ethernet config"), path);
}

const std::string* Object::parameter(std::string_view name) const {
  for (const Parameter& p : parameters)
    if (p.name == name) return &p.value;
  return nullptr;
}

double numberParameter(const Context& context, const Object& object, std::string_view name, double fallback) {
  const std::string* text = object.parameter(name);
  if (!text) return fallback;
  double v = 0;
  std::string_view t = *text;
  if (!t.empty() && t.front() == '+') t.remove_prefix(1);
  const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
  if (t.empty() || ec != std::errc() || end != t.data() + t.size() || !std::isfinite(v))
    throw ConfigError(context.path + ":" + std::to_string(object.line) + ": " + object.id + " (" + object.type +
                      "): parameter " + std::string(name) + "=\"" + *text +
                      "\" is not a number; give a decimal number such as 5 or -2.5");
  return v;
}

const Object* Context::find(std::string_view object_id) const {
  for (const Object& o : objects)
    if (o.id == object_id) return &o;
  return nullptr;
}

const Object* Context::ethernet() const {
  for (const Object& o : objects)
    if (o.type == "ETHERNET") return &o;
  return nullptr;
}

std::string Context::ethernetConfigPath() const {
  const Object* e = ethernet();
  const std::string* file = e ? e->parameter("ConfigFile") : nullptr;
  if (!file) return {};
  return (std::filesystem::path(path).parent_path() / *file).string();
}

Context parseContext(std::string_view text, const std::string& name) {
  const XmlElement root = parseXml(text, name);
  Context c;
  c.path = name;
  for (const XmlElement& e : root.children) {
    if (e.name != "RSIObject") continue;
    Object o;
    o.line = e.line;
    const std::string* type = e.attribute("ObjType");
    const std::string* id = e.attribute("ObjID");
    if (!type || type->empty()) fail(name, e.line, "an RSIObject without ObjType");
    if (!id || id->empty()) fail(name, e.line, "the " + *type + " object has no ObjID");
    o.type = *type;
    o.id = *id;
    if (const std::string* type_id = e.attribute("ObjTypeID")) {
      long v = 0;
      if (parseInt(*type_id, v)) o.type_id = int(v);
    }
    if (const XmlElement* inputs = e.child("Inputs"))
      for (const XmlElement& in : inputs->children) {
        if (in.name != "Input") continue;
        Input input;
        long in_index = 0, out_index = 0;
        const std::string* in_text = in.attribute("InIdx");
        const std::string* out_object = in.attribute("OutObjID");
        const std::string* out_text = in.attribute("OutIdx");
        if (!in_text || !parseInt(*in_text, in_index) || in_index < 1 || !out_object || !out_text ||
            !parseInt(*out_text, out_index) || out_index < 1)
          fail(name, in.line, "an Input of " + o.id + " needs InIdx, OutObjID and OutIdx (indices from 1)");
        input.in_index = int(in_index);
        input.out_object = *out_object;
        input.out_index = int(out_index);
        o.inputs.push_back(input);
      }
    if (const XmlElement* parameters = e.child("Parameters"))
      for (const XmlElement& p : parameters->children) {
        if (p.name != "Parameter") continue;
        const std::string* pname = p.attribute("Name");
        if (!pname) fail(name, p.line, "a Parameter of " + o.id + " without Name");
        const std::string* pid = p.attribute("ParamID");
        const std::string* value = p.attribute("ParamValue");
        o.parameters.push_back({*pname, pid ? *pid : std::string(), value ? *value : std::string()});
      }
    if (c.find(o.id)) fail(name, e.line, "ObjID " + o.id + " is used twice (also at line " + std::to_string(c.find(o.id)->line) + ")");
    c.objects.push_back(std::move(o));
  }
  for (const Object& o : c.objects)
    for (const Input& in : o.inputs)
      if (!c.find(in.out_object))
        fail(name, o.line, "input " + std::to_string(in.in_index) + " of " + o.id + " is wired to " + in.out_object +
                               ", which is not an object of this context");
  const Object* ethernet = c.ethernet();
  if (!ethernet) fail(name, root.line, "no ETHERNET object: this context exchanges nothing with the PC");
  const std::string* file = ethernet->parameter("ConfigFile");
  if (!file || file->empty())
    fail(name, ethernet->line, ethernet->id + " has no ConfigFile parameter; name the Ethernet config file in it");
  return c;
}

Context readContext(const std::string& path) { return parseContext(readTextFile(path, "RSI context"), path); }

std::vector<std::string> contextsNaming(const std::string& ethernet_config_path) {
  namespace fs = std::filesystem;
  std::error_code error;
  const fs::path config = fs::weakly_canonical(ethernet_config_path, error);
  std::vector<std::string> found;
  for (const fs::directory_entry& entry : fs::directory_iterator(config.parent_path(), error)) {
    const std::string name = entry.path().filename().string();
    if (name.size() < 8 || name.compare(name.size() - 8, 8, ".rsi.xml") != 0) continue;
    try {
      if (fs::weakly_canonical(readContext(entry.path().string()).ethernetConfigPath()) == config)
        found.push_back(entry.path().string());
    } catch (const std::exception&) {
      // Not a context we can read: not the one.
    }
  }
  std::sort(found.begin(), found.end());
  return found;
}

}  // namespace xmate::rsi
