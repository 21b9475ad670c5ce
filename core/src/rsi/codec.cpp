// SPDX-License-Identifier: Apache-2.0
// Decoder and Encoder (codec.h): one parser and one writer for both datagrams (<Rob> and <Sen>).
// decode() copies the datagram into a fixed buffer and parses it in place with pugixml, whose
// memory comes from a fixed arena: pugixml's memory hooks are process-wide and take no context, so
// the arena in use is a thread-local pointer (initial-exec: reading it never allocates), set for the
// length of one parse. Everything else pugixml allocates (nothing else in RCI Studio uses it) goes
// to malloc as usual.
#include "rsi/codec.h"

#include <pugixml.hpp>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <mutex>

namespace xmate::rsi {

// A bump allocator for one parse: reset before it, never freed piecemeal.
struct Arena {
  static constexpr size_t kBytes = 256 * 1024;  // pugixml's pages are 32 KB: room for an 8 KB datagram
  static constexpr size_t kAlign = 16;
  std::unique_ptr<unsigned char[]> memory{new unsigned char[kBytes]};
  size_t used = 0;
  bool exhausted = false;
  bool owns(const void* p) const {
    const auto* b = static_cast<const unsigned char*>(p);
    return b >= memory.get() && b < memory.get() + kBytes;
  }
};

// The decoder's parse state, kept out of the header: the document and the in-place buffer.
struct Decoder::Parser {
  pugi::xml_document document;
  std::array<char, kMaxDatagramBytes + 1> buffer{};
};

namespace {

thread_local Arena* t_arena __attribute__((tls_model("initial-exec"))) = nullptr;

void* hookAllocate(size_t size) {
  Arena* a = t_arena;
  if (!a) return std::malloc(size);
  const size_t need = (size + Arena::kAlign - 1) / Arena::kAlign * Arena::kAlign;
  if (a->used + need > Arena::kBytes) {
    a->exhausted = true;
    return nullptr;  // pugixml reports status_out_of_memory
  }
  void* block = a->memory.get() + a->used;
  a->used += need;
  return block;
}

void hookDeallocate(void* p) {
  Arena* a = t_arena;
  if (a && a->owns(p)) return;  // the whole arena is reset before the next parse
  std::free(p);
}

void installHooks() {
  static std::once_flag once;
  std::call_once(once, [] { pugi::set_memory_management_functions(hookAllocate, hookDeallocate); });
}

// Sets the thread's arena for a scope.
struct ArenaScope {
  explicit ArenaScope(Arena* a) { t_arena = a; }
  ~ArenaScope() { t_arena = nullptr; }
};

bool equalsAnyCase(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i]))) return false;
  return true;
}

// XML's white space (the C locale's isspace also takes \v and \f; XML has none of those).
inline bool isXmlSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

inline std::string_view trim(std::string_view s) {
  while (!s.empty() && isXmlSpace(s.front())) s.remove_prefix(1);
  while (!s.empty() && isXmlSpace(s.back())) s.remove_suffix(1);
  return s;
}

// The common case of a KRC's numbers, "-35.250000": an optional minus, digits, and optionally a
// point and more digits, at most 15 digits in all. The digits form an integer below 2^53 and the
// divisor is an exact power of ten, so the one division is correctly rounded -- the same double
// from_chars gives, in a fraction of its time. False (and out untouched) for anything else.
inline bool parsePlainDecimal(std::string_view text, double& out) {
  static constexpr double kPowersOfTen[] = {1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7,
                                            1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15};
  const char* p = text.data();
  const char* const end = p + text.size();
  const bool negative = p != end && *p == '-';
  if (negative) ++p;
  uint64_t digits = 0;
  int count = 0;
  int decimals = -1;  // -1 before the point
  for (; p != end; ++p) {
    if (*p >= '0' && *p <= '9') {
      if (++count > 15) return false;
      digits = digits * 10 + uint64_t(*p - '0');
      if (decimals >= 0) ++decimals;
    } else if (*p == '.' && decimals < 0 && count > 0) {
      decimals = 0;
    } else {
      return false;
    }
  }
  if (count == 0 || decimals == 0) return false;  // "", "-", "5.": left to from_chars
  const double magnitude = double(digits) / kPowersOfTen[decimals < 0 ? 0 : decimals];
  out = negative ? -magnitude : magnitude;
  return true;
}

// A value of the config's type from datagram text: numbers in any of the C locale's forms
// (10.000000, -0.0, 1e-05, +3), BOOL as 0/1/TRUE/FALSE. False if it is none of those.
inline bool parseValue(std::string_view text, ValueType type, double& out) {
  text = trim(text);
  if (type == ValueType::kBool) {
    if (equalsAnyCase(text, "true")) return out = 1, true;
    if (equalsAnyCase(text, "false")) return out = 0, true;
  }
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  if (parsePlainDecimal(text, out)) return true;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
  return ec == std::errc() && end == text.data() + text.size() && std::isfinite(out);
}

int findSlot(const std::vector<Slot>& slots, std::string_view element, std::string_view attribute) {
  for (size_t i = 0; i < slots.size(); ++i)
    if (slots[i].element == element && slots[i].attribute == attribute) return int(i);
  return -1;
}

// The slots a config's channels make: a built-in value expands to its attributes.
std::vector<Slot> slotsOf(const std::vector<Channel>& channels) {
  std::vector<Slot> slots;
  for (const Channel& c : channels) {
    const std::vector<std::string> attributes = c.internal() ? builtInAttributes(c) : std::vector<std::string>{c.attribute};
    for (const std::string& a : attributes)
      if (findSlot(slots, c.element, a) < 0) slots.push_back({c.element, a, c.type});
  }
  return slots;
}

}  // namespace

std::vector<std::string> builtInAttributes(const Channel& c) {
  auto numbered = [](const std::string& prefix, int from, int to) {
    std::vector<std::string> out;
    for (int i = from; i <= to; ++i) out.push_back(prefix + std::to_string(i));
    return out;
  };
  if (c.element == "RIst" || c.element == "RSol") return {"X", "Y", "Z", "A", "B", "C"};
  if (c.element == "AIPos" || c.element == "ASPos" || c.element == "MACur") return numbered("A", 1, 6);
  if (c.element == "EIPos" || c.element == "ESPos" || c.element == "MECur") return numbered("E", 1, 6);
  if (c.element == "Delay") return {"D"};
  if (c.element == "Tech") return numbered(c.attribute.empty() ? "C1" : c.attribute, 1, 10);  // C11..C110
  return {""};  // EStr: a text element
}

// ---- Decoder ----------------------------------------------------------------------------------------

Decoder::Decoder(const EthernetConfig& config, Direction direction)
    : root_(direction == Direction::kRob ? "Rob" : "Sen"),
      not_root_reason_(direction == Direction::kRob ? "not a <Rob> datagram" : "not a <Sen> datagram"),
      slots_(slotsOf(direction == Direction::kRob ? config.send : config.receive)),
      values_(slots_.size(), 0.0),
      staged_(slots_.size(), 0.0),
      texts_(slots_.size()),
      seen_(slots_.size(), false),
      staged_seen_(slots_.size(), false),
      arena_(std::make_unique<Arena>()) {
  installHooks();
  parser_ = std::make_unique<Parser>();
  // Each element's slots, for the look-up per datagram.
  for (size_t i = 0; i < slots_.size(); ++i) {
    auto e = std::find_if(elements_.begin(), elements_.end(), [&](const ElementSlots& x) { return x.name == slots_[i].element; });
    if (e == elements_.end()) {
      elements_.push_back({slots_[i].element, -1, {}});
      e = elements_.end() - 1;
    }
    if (slots_[i].attribute.empty()) e->text_slot = int(i);
    else e->attributes.emplace_back(slots_[i].attribute, int(i));
  }
}

Decoder::~Decoder() {
  ArenaScope scope(arena_.get());  // the document's pages are in the arena
  parser_.reset();
}

int Decoder::slot(std::string_view element, std::string_view attribute) const {
  return findSlot(slots_, element, attribute);
}

std::string_view Decoder::text(int slot) const {
  return texts_[size_t(slot)].view();
}

bool Decoder::setType(std::string_view type) {
  if (type.size() >= kMaxText) return false;
  std::memcpy(type_.data(), type.data(), type.size());
  type_length_ = type.size();
  return true;
}

bool Decoder::stageIpoc(std::string_view text) {
  uint64_t v = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size() || text.size() >= kMaxText) return false;
  staged_ipoc_ = v;
  std::memcpy(staged_ipoc_text_.data(), text.data(), text.size());
  staged_ipoc_length_ = text.size();
  return true;
}

namespace {
// An element's text, trimmed (pugixml keeps it in place; with parse_minimal it is not trimmed).
std::string_view textOf(const pugi::xml_node& element) {
  for (pugi::xml_node child = element.first_child(); child; child = child.next_sibling())
    if (child.type() == pugi::node_pcdata || child.type() == pugi::node_cdata) return trim(child.value());
  return {};
}
}  // namespace

const Decoder::ElementSlots* Decoder::element(const char* name) const {
  for (const ElementSlots& e : elements_)
    if (std::strcmp(e.name.c_str(), name) == 0) return &e;
  return nullptr;
}

bool Decoder::store(int slot, std::string_view value) {
  const Slot& s = slots_[size_t(slot)];
  if (s.type == ValueType::kString) texts_[size_t(slot)].assign(value);
  else if (!parseValue(value, s.type, staged_[size_t(slot)])) return false;
  staged_seen_[size_t(slot)] = true;
  return true;
}

bool Decoder::decode(std::string_view datagram) {
  reason_ = "";
  unknown_ = 0;
  if (datagram.size() > kMaxDatagramBytes) {
    reason_ = "the datagram is longer than 8 KB";
    return false;
  }
  std::copy(values_.begin(), values_.end(), staged_.begin());
  staged_seen_ = seen_;  // same size: no allocation
  if (!datagram.empty()) std::memcpy(parser_->buffer.data(), datagram.data(), datagram.size());
  arena_->used = 0;
  arena_->exhausted = false;
  ArenaScope scope(arena_.get());
  const pugi::xml_parse_result parsed = parser_->document.load_buffer_inplace(
      parser_->buffer.data(), datagram.size(), pugi::parse_minimal | pugi::parse_escapes, pugi::encoding_utf8);
  if (!parsed) {
    reason_ = arena_->exhausted ? "the datagram is too complex to parse in the codec's memory" : parsed.description();
    return false;
  }
  const pugi::xml_node root = parser_->document.document_element();
  if (!root || std::strcmp(root.name(), root_) != 0) {
    reason_ = not_root_reason_;
    return false;
  }
  for (pugi::xml_attribute a = root.first_attribute(); a; a = a.next_attribute())
    if (equalsAnyCase(a.name(), "type") && !setType(a.value())) {
      reason_ = "the Type attribute is too long";
      return false;
    }
  bool have_ipoc = false;
  for (pugi::xml_node node = root.first_child(); node; node = node.next_sibling()) {
    if (node.type() != pugi::node_element) continue;
    if (std::strcmp(node.name(), "IPOC") == 0) {
      if (!stageIpoc(textOf(node))) {
        reason_ = "<IPOC> is not an unsigned 64-bit number";
        return false;
      }
      have_ipoc = true;
      continue;
    }
    const ElementSlots* e = element(node.name());
    if (!e) {
      ++unknown_;  // the element, and each of its attributes
      for (pugi::xml_attribute a = node.first_attribute(); a; a = a.next_attribute()) ++unknown_;
      continue;
    }
    if (e->text_slot >= 0) {
      const std::string_view text = textOf(node);
      if (text.size() >= kMaxText) {
        reason_ = "a value is longer than the codec keeps";
        return false;
      }
      if (!store(e->text_slot, text)) {
        reason_ = "a value is not a number of the type the Ethernet config gives it";
        return false;
      }
    }
    size_t expected = 0;  // attributes usually come in the config's order: try the next one first
    for (pugi::xml_attribute a = node.first_attribute(); a; a = a.next_attribute()) {
      int slot = -1;
      for (size_t k = 0; k < e->attributes.size() && slot < 0; ++k) {
        const auto& [name, index] = e->attributes[(expected + k) % e->attributes.size()];
        if (std::strcmp(name.c_str(), a.name()) == 0) {
          slot = index;
          expected = (expected + k + 1) % e->attributes.size();
        }
      }
      if (slot < 0) {
        ++unknown_;
        continue;
      }
      if (!store(slot, a.value())) {
        reason_ = "a value is not a number of the type the Ethernet config gives it";
        return false;
      }
    }
  }
  if (!have_ipoc) {
    reason_ = "the datagram has no <IPOC>";
    return false;
  }
  values_.swap(staged_);
  seen_.swap(staged_seen_);
  ipoc_ = staged_ipoc_;
  ipoc_text_ = staged_ipoc_text_;
  ipoc_length_ = staged_ipoc_length_;
  return true;
}

// ---- Encoder ----------------------------------------------------------------------------------------

Encoder::Encoder(const EthernetConfig& config, Direction direction, int precision)
    : root_(direction == Direction::kRob ? "Rob" : "Sen"),
      max_bytes_(direction == Direction::kRob ? kMaxDatagramBytes : kMaxSenBytes),
      sentype_(config.sentype),
      precision_(std::clamp(precision, 0, 9)),
      slots_(slotsOf(direction == Direction::kRob ? config.send : config.receive)) {
  values_.assign(slots_.size(), 0.0);
  texts_.resize(slots_.size());
  for (size_t i = 0; i < slots_.size(); ++i) {
    auto group = std::find_if(groups_.begin(), groups_.end(), [&](const Group& g) { return g.element == slots_[i].element; });
    if (group == groups_.end()) {
      groups_.push_back({slots_[i].element, slots_[i].attribute.empty(), {}});
      group = groups_.end() - 1;
    }
    group->members.push_back(int(i));
  }
}

int Encoder::slot(std::string_view element, std::string_view attribute) const {
  return findSlot(slots_, element, attribute);
}

void Encoder::setText(int slot, std::string_view text) { texts_[size_t(slot)].assign(text); }

void TextValue::assign(std::string_view text) {
  length = uint8_t(std::min(text.size(), kMaxText - 1));
  if (length > 0) std::memcpy(bytes.data(), text.data(), length);  // an empty view may have no data
}

// Appends to a fixed buffer; remembers when it ran out.
struct Encoder::Writer {
  char* out;
  size_t capacity;
  size_t length = 0;
  bool full = false;
  void put(std::string_view s) {
    if (length + s.size() > capacity) {
      full = true;
      return;
    }
    if (!s.empty()) std::memcpy(out + length, s.data(), s.size());
    length += s.size();
  }
  void putEscaped(std::string_view s) {
    for (char c : s) {
      switch (c) {
        case '&': put("&amp;"); break;
        case '<': put("&lt;"); break;
        case '>': put("&gt;"); break;
        case '"': put("&quot;"); break;
        default: put({&c, 1});
      }
    }
  }
  void putNumber(double v, ValueType type, int precision) {
    char buffer[64];
    if (!std::isfinite(v)) v = 0;
    std::to_chars_result r{};
    if (type == ValueType::kBool)
      r = std::to_chars(buffer, buffer + sizeof buffer, v != 0 ? 1 : 0);
    else if (type == ValueType::kLong)
      r = std::to_chars(buffer, buffer + sizeof buffer, std::llround(v));
    else
      r = std::to_chars(buffer, buffer + sizeof buffer, v, std::chars_format::fixed, precision);
    put({buffer, size_t(r.ptr - buffer)});
  }
};


void Encoder::putValue(Writer& w, int slot) const {
  if (slots_[size_t(slot)].type == ValueType::kString)
    w.putEscaped(texts_[size_t(slot)].view());
  else
    w.putNumber(values_[size_t(slot)], slots_[size_t(slot)].type, precision_);
}

size_t Encoder::encode(std::string_view ipoc_text, char* out, size_t capacity) const {
  Writer w{out, std::min(capacity, max_bytes_)};
  w.put("<");
  w.put(root_);
  w.put(" Type=\"");
  w.putEscaped(sentype_);
  w.put("\">");
  for (const Group& g : groups_) {
    w.put("<");
    w.put(g.element);
    if (g.text) {
      w.put(">");
      putValue(w, g.members.front());
      w.put("</");
      w.put(g.element);
      w.put(">");
      continue;
    }
    for (int s : g.members) {
      w.put(" ");
      w.put(slots_[size_t(s)].attribute);
      w.put("=\"");
      putValue(w, s);
      w.put("\"");
    }
    w.put(" />");
  }
  w.put("<IPOC>");
  w.put(ipoc_text);
  w.put("</IPOC></");
  w.put(root_);
  w.put(">");
  return w.full ? 0 : w.length;
}

}  // namespace xmate::rsi
