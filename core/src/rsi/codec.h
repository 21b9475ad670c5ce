// SPDX-License-Identifier: Apache-2.0
// The RSI datagrams, laid out by a loaded Ethernet config: RobDecoder parses the robot's <Rob>
// into a fixed record of values (one slot per SEND element attribute, the built-in DEF_ values
// expanded to their attributes), SenEncoder writes the PC's <Sen> from the RECEIVE elements with
// the IPOC echoed verbatim. Both are made once (set-up: they allocate) and are then allocation-free
// and lock-free: decode() parses with expat in a fixed arena (no malloc), encode() writes into the
// caller's buffer. One thread per object (the link's real-time thread). docs/rsi.md, "Datagrams".
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

class RobDecoder {
 public:
  explicit RobDecoder(const EthernetConfig& config);
  ~RobDecoder();
  RobDecoder(const RobDecoder&) = delete;
  RobDecoder& operator=(const RobDecoder&) = delete;

  // ---- Set-up ------------------------------------------------------------------------------------
  const std::vector<Slot>& layout() const { return slots_; }  // every slot, in config order
  // The slot of <element attribute=..> (attribute "" for a text element), or -1.
  int slot(std::string_view element, std::string_view attribute = {}) const;

  // ---- Per datagram (allocation-free) ------------------------------------------------------------
  // Parses one <Rob> datagram. Values not in this datagram keep their previous ones (seen()
  // tells). False (and reason() says why; the previous numbers, IPOC and seen() kept -- a STRING
  // value may already show the refused datagram's) for a datagram that is too
  // long, not well-formed, not <Rob>, without a valid <IPOC>, or with a value that is not a number
  // where the config says one.
  bool decode(std::string_view datagram);
  const char* reason() const { return reason_; }
  uint64_t ipoc() const { return ipoc_; }
  std::string_view ipocText() const { return {ipoc_text_.data(), ipoc_length_}; }  // verbatim, to echo
  std::string_view type() const { return {type_.data(), type_length_}; }          // the Type attribute
  double value(int slot) const { return values_[size_t(slot)]; }
  std::string_view text(int slot) const;  // STRING slots
  bool seen(int slot) const { return seen_[size_t(slot)]; }
  // Elements and attributes of the last datagram that the config does not name (ignored).
  uint32_t unknownCount() const { return unknown_; }

  struct Parse;  // expat's callbacks' view of this object (codec.cpp)
  // For the callbacks: the Rob's Type attribute and the IPOC text (false if unusable), and an
  // element or attribute the config does not name.
  bool onType(std::string_view type);
  bool onIpoc(std::string_view text);
  void countUnknown() { ++unknown_; }

 private:
  std::vector<Slot> slots_;
  std::vector<double> values_;
  std::vector<double> staged_;  // the datagram being parsed; swapped with values_ when it parsed
  std::vector<TextValue> texts_;
  std::vector<bool> seen_;
  std::vector<bool> staged_seen_;
  std::unique_ptr<struct Arena> arena_;
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

class SenEncoder {
 public:
  // `precision`: decimals of DOUBLE values (the context's ETHERNET Precision; 4 is common).
  explicit SenEncoder(const EthernetConfig& config, int precision = 4);

  // ---- Set-up ------------------------------------------------------------------------------------
  const std::vector<Slot>& layout() const { return slots_; }  // every slot, in config order
  int slot(std::string_view element, std::string_view attribute = {}) const;

  // ---- Per cycle (allocation-free) ---------------------------------------------------------------
  void set(int slot, double value) { values_[size_t(slot)] = value; }
  void setText(int slot, std::string_view text);  // STRING slots; cut at kMaxText - 1 bytes
  // Writes <Sen Type="SENTYPE">...<IPOC>ipoc</IPOC></Sen> into out; returns its length, or 0 if
  // it would not fit in `capacity` (at most kMaxSenBytes are ever written).
  size_t encode(std::string_view ipoc_text, char* out, size_t capacity) const;

 private:
  struct Writer;                               // the output buffer of encode() (codec.cpp)
  void putValue(Writer& w, int slot) const;   // a slot's value as datagram text
  struct Group {  // one datagram element and its slots, in config order
    std::string element;
    bool text = false;
    std::vector<int> members;
  };
  std::string sentype_;
  int precision_;
  std::vector<Slot> slots_;
  std::vector<Group> groups_;
  std::vector<double> values_;
  std::vector<TextValue> texts_;
};

}  // namespace xmate::rsi
