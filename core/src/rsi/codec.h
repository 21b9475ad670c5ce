// SPDX-License-Identifier: Apache-2.0
// The RSI datagrams, laid out by a loaded Ethernet config, in both directions with one machinery:
// a Decoder parses a datagram into a fixed record of values (one slot per element attribute, the
// built-in DEF_ values expanded to their attributes), an Encoder writes one from such a record.
// The PC side uses RobDecoder (the robot's <Rob>, SEND elements) and SenEncoder (its <Sen> answer,
// RECEIVE elements, IPOC echoed verbatim); the simulated KRC the mirror pair RobEncoder and
// SenDecoder. All are made once (set-up: they allocate) and are then allocation-free and lock-free:
// decode() parses with pugixml in a fixed arena (no malloc), encode() writes into the caller's
// buffer. One thread per object (the link's or the KRC's cycle thread). docs/rsi.md, "Datagrams".
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "rsi/config.h"

namespace xmate::rsi {

// Datagrams beyond this are refused unread (the robot's are well under 1 KB).
inline constexpr size_t kMaxDatagramBytes = 8192;
// What we send stays under this (public PC-side code reads 1024-byte buffers).
inline constexpr size_t kMaxSenBytes = 1024;
inline constexpr size_t kMaxText = 96;  // a STRING value or an IPOC token, bytes

// A STRING value, kept in place (no allocation): at most kMaxText - 1 bytes, longer text is cut.
struct TextValue {
  std::array<char, kMaxText> bytes{};
  uint8_t length = 0;
  void assign(std::string_view text);
  std::string_view view() const { return {bytes.data(), length}; }
};

// One value of a datagram: element <Name>, attribute Attr (empty: the element's text).
struct Slot {
  std::string element;
  std::string attribute;
  ValueType type = ValueType::kDouble;
};

// The attributes a built-in value has in the datagram: DEF_RIst -> X Y Z A B C, DEF_AIPos ->
// A1..A6, DEF_Delay -> D, DEF_Tech.C1 -> C11..C110, ... (empty for a text value such as DEF_EStr).
std::vector<std::string> builtInAttributes(const Channel& channel);

// Which datagram: <Rob> (robot -> PC) carries the SEND elements, <Sen> (PC -> robot) the RECEIVE ones.
enum class Direction { kRob, kSen };

class Decoder {
 public:
  Decoder(const EthernetConfig& config, Direction direction);
  ~Decoder();
  Decoder(const Decoder&) = delete;
  Decoder& operator=(const Decoder&) = delete;

  // ---- Set-up ------------------------------------------------------------------------------------
  const std::vector<Slot>& layout() const { return slots_; }  // every slot, in config order
  // The slot of <element attribute=..> (attribute "" for a text element), or -1.
  int slot(std::string_view element, std::string_view attribute = {}) const;

  // ---- Per datagram (allocation-free) ------------------------------------------------------------
  // Parses one datagram (<Rob> or <Sen>, as made). Values not in this datagram keep their previous
  // ones (seen() tells). False (and reason() says why; the previous numbers, IPOC and seen() kept --
  // a STRING value may already show the refused datagram's) for a datagram that is too long, not
  // well-formed, of the other root element, without a valid <IPOC>, or with a value that is not a
  // number where the config says one.
  bool decode(std::string_view datagram);
  const char* reason() const { return reason_; }
  uint64_t ipoc() const { return ipoc_; }
  std::string_view ipocText() const { return {ipoc_text_.data(), ipoc_length_}; }  // verbatim, to echo
  std::string_view type() const { return {type_.data(), type_length_}; }          // the Type attribute
  const char* root() const { return root_; }  // "Rob" or "Sen"
  double value(int slot) const { return values_[size_t(slot)]; }
  std::string_view text(int slot) const;  // STRING slots
  bool seen(int slot) const { return seen_[size_t(slot)]; }
  // Elements and attributes of the last datagram that the config does not name (ignored).
  uint32_t unknownCount() const { return unknown_; }

 private:
  struct Parser;  // pugixml's document and the in-place buffer (codec.cpp)
  struct ElementSlots {  // one datagram element's slots, built at set-up
    std::string name;
    int text_slot = -1;
    std::vector<std::pair<std::string, int>> attributes;  // in config order
  };
  const ElementSlots* element(const char* name) const;
  bool store(int slot, std::string_view value);  // into the staged values; false: not a number
  bool setType(std::string_view type);           // the root's Type attribute; false: too long
  bool stageIpoc(std::string_view text);         // false: not an unsigned 64-bit number

  const char* root_;              // "Rob" or "Sen"
  const char* not_root_reason_;   // "not a <Rob> datagram" / "not a <Sen> datagram"
  std::vector<Slot> slots_;
  std::vector<double> values_;
  std::vector<double> staged_;  // the datagram being parsed; swapped with values_ when it parsed
  std::vector<TextValue> texts_;
  std::vector<bool> seen_;
  std::vector<bool> staged_seen_;
  std::vector<ElementSlots> elements_;
  std::unique_ptr<struct Arena> arena_;
  std::unique_ptr<Parser> parser_;
  const char* reason_ = "";
  uint64_t ipoc_ = 0;
  std::array<char, kMaxText> ipoc_text_{};
  size_t ipoc_length_ = 0;
  uint64_t staged_ipoc_ = 0;
  std::array<char, kMaxText> staged_ipoc_text_{};
  size_t staged_ipoc_length_ = 0;
  std::array<char, kMaxText> type_{};
  size_t type_length_ = 0;
  uint32_t unknown_ = 0;
};

// The PC side's reader of the robot's <Rob> (SEND elements).
class RobDecoder : public Decoder {
 public:
  explicit RobDecoder(const EthernetConfig& config) : Decoder(config, Direction::kRob) {}
};

// The simulated KRC's reader of the PC's <Sen> answer (RECEIVE elements).
class SenDecoder : public Decoder {
 public:
  explicit SenDecoder(const EthernetConfig& config) : Decoder(config, Direction::kSen) {}
};

class Encoder {
 public:
  // `precision`: decimals of DOUBLE values (the context's ETHERNET Precision; 4 is common).
  Encoder(const EthernetConfig& config, Direction direction, int precision = 4);

  // ---- Set-up ------------------------------------------------------------------------------------
  const std::vector<Slot>& layout() const { return slots_; }  // every slot, in config order
  int slot(std::string_view element, std::string_view attribute = {}) const;

  // ---- Per cycle (allocation-free) ---------------------------------------------------------------
  void set(int slot, double value) { values_[size_t(slot)] = value; }
  void setText(int slot, std::string_view text);  // STRING slots; cut at kMaxText - 1 bytes
  // Writes <Sen Type="SENTYPE">...<IPOC>ipoc</IPOC></Sen> (or <Rob ...>) into out; returns its
  // length, or 0 if it would not fit in `capacity` (at most maxBytes() are ever written).
  size_t encode(std::string_view ipoc_text, char* out, size_t capacity) const;
  // kMaxSenBytes for <Sen> (public PC code reads 1024-byte buffers), kMaxDatagramBytes for <Rob>.
  size_t maxBytes() const { return max_bytes_; }

 private:
  struct Writer;                               // the output buffer of encode() (codec.cpp)
  void putValue(Writer& w, int slot) const;  // a slot's value as datagram text
  struct Group {  // one datagram element and its slots, in config order
    std::string element;
    bool text = false;
    std::vector<int> members;
  };
  const char* root_;  // "Rob" or "Sen"
  size_t max_bytes_;
  std::string sentype_;
  int precision_;
  std::vector<Slot> slots_;
  std::vector<Group> groups_;
  std::vector<double> values_;
  std::vector<TextValue> texts_;
};

// The PC side's writer of its <Sen> answer (RECEIVE elements).
class SenEncoder : public Encoder {
 public:
  explicit SenEncoder(const EthernetConfig& config, int precision = 4) : Encoder(config, Direction::kSen, precision) {}
};

// The simulated KRC's writer of its <Rob> (SEND elements).
class RobEncoder : public Encoder {
 public:
  explicit RobEncoder(const EthernetConfig& config, int precision = 4) : Encoder(config, Direction::kRob, precision) {}
};

}  // namespace xmate::rsi
