// SPDX-License-Identifier: Apache-2.0
// RobDecoder and SenEncoder (codec.h). decode() runs expat on memory from a fixed arena: expat's
// memory callbacks take no context, so the arena in use is a thread-local pointer (initial-exec:
// reading it never allocates), set for the length of one parse.
#include "rsi/codec.h"

#include <expat.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>

namespace xmate::rsi {

// A bump allocator for one parse: reset before it, never freed piecemeal. Each block is preceded
// by its size so that realloc can copy it.
struct Arena {
  static constexpr size_t kBytes = 256 * 1024;
  static constexpr size_t kAlign = 16;
  std::unique_ptr<unsigned char[]> memory{new unsigned char[kBytes]};
  size_t used = 0;
  bool exhausted = false;
};

namespace {

thread_local Arena* t_arena __attribute__((tls_model("initial-exec"))) = nullptr;

void* arenaMalloc(size_t size) {
  Arena* a = t_arena;
  const size_t need = Arena::kAlign + (size + Arena::kAlign - 1) / Arena::kAlign * Arena::kAlign;
  if (!a || a->used + need > Arena::kBytes) {
    if (a) a->exhausted = true;
    return nullptr;  // expat reports XML_ERROR_NO_MEMORY
  }
  unsigned char* block = a->memory.get() + a->used;
  a->used += need;
  std::memcpy(block, &size, sizeof size);
  return block + Arena::kAlign;
}

void* arenaRealloc(void* old, size_t size) {
  void* fresh = arenaMalloc(size);
  if (fresh && old) {
    size_t old_size = 0;
    std::memcpy(&old_size, static_cast<unsigned char*>(old) - Arena::kAlign, sizeof old_size);
    std::memcpy(fresh, old, std::min(old_size, size));
  }
  return fresh;
}

void arenaFree(void*) {}  // the whole arena is reset before the next parse

const XML_Memory_Handling_Suite kArenaSuite{arenaMalloc, arenaRealloc, arenaFree};

bool equalsAnyCase(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i]))) return false;
  return true;
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

// A value of the config's type from datagram text: numbers in any of the C locale's forms
// (10.000000, -0.0, 1e-05, +3), BOOL as 0/1/TRUE/FALSE. False if it is none of those.
bool parseValue(std::string_view text, ValueType type, double& out) {
  text = trim(text);
  if (type == ValueType::kBool) {
    if (equalsAnyCase(text, "true")) return out = 1, true;
    if (equalsAnyCase(text, "false")) return out = 0, true;
  }
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
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

// ---- RobDecoder -------------------------------------------------------------------------------------

struct RobDecoder::Parse {
  RobDecoder& d;
  XML_Parser parser;
  std::vector<double>& values;  // the staged values (committed when the whole datagram parsed)
  std::vector<bool>& seen;
  int depth = 0;
  int text_slot = -1;    // the slot collecting character data, -1 none, -2 IPOC
  std::array<char, kMaxText> text{};
  size_t text_length = 0;
  bool have_ipoc = false;

  void fail(const char* why) {
    if (*d.reason_ == '\0') d.reason_ = why;
    XML_StopParser(parser, XML_FALSE);
  }
  void store(int slot, std::string_view value) {
    const Slot& s = d.slots_[size_t(slot)];
    if (s.type == ValueType::kString)
      d.texts_[size_t(slot)].assign(value);
    else if (!parseValue(value, s.type, values[size_t(slot)]))
      return fail("a value is not a number of the type the Ethernet config gives it");
    seen[size_t(slot)] = true;
  }
};

namespace {

void XMLCALL robStart(void* data, const XML_Char* name, const XML_Char** attributes) {
  auto& p = *static_cast<RobDecoder::Parse*>(data);
  const int depth = p.depth++;
  if (depth == 0) {
    if (std::strcmp(name, "Rob") != 0) return p.fail("not a <Rob> datagram");
    for (const XML_Char** a = attributes; *a; a += 2)
      if (equalsAnyCase(a[0], "type") && !p.d.onType(a[1])) return p.fail("the Type attribute is too long");
    return;
  }
  if (depth > 1) return;  // nothing nests in a <Rob> element
  p.text_length = 0;
  p.text_slot = std::strcmp(name, "IPOC") == 0 ? -2 : p.d.slot(name, "");
  bool known = p.text_slot != -1;
  for (const XML_Char** a = attributes; *a; a += 2) {
    const int slot = p.d.slot(name, a[0]);
    if (slot < 0) {
      p.d.countUnknown();
      continue;
    }
    known = true;
    p.store(slot, a[1]);
  }
  if (!known) p.d.countUnknown();
}

void XMLCALL robEnd(void* data, const XML_Char*) {
  auto& p = *static_cast<RobDecoder::Parse*>(data);
  if (--p.depth != 1) return;
  const std::string_view text = trim({p.text.data(), p.text_length});
  if (p.text_slot == -2) {
    if (!p.d.onIpoc(text)) return p.fail("<IPOC> is not an unsigned 64-bit number");
    p.have_ipoc = true;
  } else if (p.text_slot >= 0) {
    p.store(p.text_slot, text);
  }
  p.text_slot = -1;
}

void XMLCALL robText(void* data, const XML_Char* s, int length) {
  auto& p = *static_cast<RobDecoder::Parse*>(data);
  if (p.text_slot == -1 || p.depth != 2) return;
  if (p.text_length + size_t(length) >= kMaxText) return p.fail("a value is longer than the codec keeps");
  std::memcpy(p.text.data() + p.text_length, s, size_t(length));
  p.text_length += size_t(length);
}

}  // namespace

RobDecoder::RobDecoder(const EthernetConfig& config)
    : slots_(slotsOf(config.send)),
      values_(slots_.size(), 0.0),
      staged_(slots_.size(), 0.0),
      texts_(slots_.size()),
      seen_(slots_.size(), false),
      staged_seen_(slots_.size(), false),
      arena_(std::make_unique<Arena>()) {}

RobDecoder::~RobDecoder() = default;

int RobDecoder::slot(std::string_view element, std::string_view attribute) const {
  return findSlot(slots_, element, attribute);
}

std::string_view RobDecoder::text(int slot) const {
  return texts_[size_t(slot)].view();
}

bool RobDecoder::onType(std::string_view type) {
  if (type.size() >= kMaxText) return false;
  std::memcpy(type_.data(), type.data(), type.size());
  type_length_ = type.size();
  return true;
}

bool RobDecoder::onIpoc(std::string_view text) {
  uint64_t v = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size() || text.size() >= kMaxText) return false;
  staged_ipoc_ = v;
  std::memcpy(staged_ipoc_text_.data(), text.data(), text.size());
  staged_ipoc_length_ = text.size();
  return true;
}

bool RobDecoder::decode(std::string_view datagram) {
  reason_ = "";
  unknown_ = 0;
  if (datagram.size() > kMaxDatagramBytes) {
    reason_ = "the datagram is longer than 8 KB";
    return false;
  }
  std::copy(values_.begin(), values_.end(), staged_.begin());
  staged_seen_ = seen_;  // same size: no allocation
  arena_->used = 0;
  arena_->exhausted = false;
  t_arena = arena_.get();
  XML_Parser parser = XML_ParserCreate_MM(nullptr, &kArenaSuite, nullptr);
  bool ok = false;
  if (!parser) {
    reason_ = "the XML parser could not start";
  } else {
    XML_SetHashSalt(parser, 0x52534931);  // fixed: no entropy read (a system call) per datagram
    Parse parse{*this, parser, staged_, staged_seen_};
    XML_SetUserData(parser, &parse);
    XML_SetElementHandler(parser, robStart, robEnd);
    XML_SetCharacterDataHandler(parser, robText);
    const bool parsed = XML_Parse(parser, datagram.data(), int(datagram.size()), XML_TRUE) == XML_STATUS_OK;
    if (!parsed && *reason_ == '\0')
      reason_ = arena_->exhausted ? "the datagram is too complex to parse in the codec's memory"
                                  : XML_ErrorString(XML_GetErrorCode(parser));
    ok = parsed && *reason_ == '\0';
    if (ok && !parse.have_ipoc) {
      reason_ = "the datagram has no <IPOC>";
      ok = false;
    }
    XML_ParserFree(parser);
  }
  t_arena = nullptr;
  if (!ok) return false;
  values_.swap(staged_);
  seen_.swap(staged_seen_);
  ipoc_ = staged_ipoc_;
  ipoc_text_ = staged_ipoc_text_;
  ipoc_length_ = staged_ipoc_length_;
  return true;
}

// ---- SenEncoder -------------------------------------------------------------------------------------

SenEncoder::SenEncoder(const EthernetConfig& config, int precision)
    : sentype_(config.sentype), precision_(std::clamp(precision, 0, 9)), slots_(slotsOf(config.receive)) {
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

int SenEncoder::slot(std::string_view element, std::string_view attribute) const {
  return findSlot(slots_, element, attribute);
}

void SenEncoder::setText(int slot, std::string_view text) { texts_[size_t(slot)].assign(text); }

void TextValue::assign(std::string_view text) {
  length = uint8_t(std::min(text.size(), kMaxText - 1));
  std::memcpy(bytes.data(), text.data(), length);
}

// Appends to a fixed buffer; remembers when it ran out.
struct SenEncoder::Writer {
  char* out;
  size_t capacity;
  size_t length = 0;
  bool full = false;
  void put(std::string_view s) {
    if (length + s.size() > capacity) {
      full = true;
      return;
    }
    std::memcpy(out + length, s.data(), s.size());
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


void SenEncoder::putValue(Writer& w, int slot) const {
  if (slots_[size_t(slot)].type == ValueType::kString)
    w.putEscaped(texts_[size_t(slot)].view());
  else
    w.putNumber(values_[size_t(slot)], slots_[size_t(slot)].type, precision_);
}

size_t SenEncoder::encode(std::string_view ipoc_text, char* out, size_t capacity) const {
  Writer w{out, std::min(capacity, kMaxSenBytes)};
  w.put("<Sen Type=\"");
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
  w.put("</IPOC></Sen>");
  return w.full ? 0 : w.length;
}

}  // namespace xmate::rsi
