// SPDX-License-Identifier: Apache-2.0
// Bounds-checked cursors over byte buffers in the RCI encoding: big-endian integers where the
// wire says so, little-endian IEEE-754 doubles, one-byte bools. Allocation-free.
#pragma once

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>

namespace xmate::protocol {

class ByteWriter {
 public:
  ByteWriter(uint8_t* data, size_t size) : data_(data), size_(size) {}

  void u8(uint8_t v) { put(&v, 1); }
  void boolean(bool v) { u8(v ? 1 : 0); }
  void be16(uint16_t v) { uint8_t b[2] = {uint8_t(v >> 8), uint8_t(v)}; put(b, 2); }
  void be32(uint32_t v) {
    uint8_t b[4] = {uint8_t(v >> 24), uint8_t(v >> 16), uint8_t(v >> 8), uint8_t(v)};
    put(b, 4);
  }
  void be64(uint64_t v) { be32(uint32_t(v >> 32)); be32(uint32_t(v)); }
  void f64(double v) {
    uint64_t bits = std::bit_cast<uint64_t>(v);
    uint8_t b[8];
    for (int i = 0; i < 8; ++i) b[i] = uint8_t(bits >> (8 * i));  // little-endian
    put(b, 8);
  }
  template <size_t N>
  void f64s(const std::array<double, N>& a) { for (double v : a) f64(v); }
  template <size_t N>
  void bools(const std::array<bool, N>& a) { for (bool v : a) boolean(v); }

  // False if any write ran past the end (nothing is written past it).
  bool ok() const { return ok_; }
  size_t written() const { return pos_; }

 private:
  void put(const uint8_t* b, size_t n) {
    if (!ok_ || pos_ + n > size_) { ok_ = false; return; }
    std::memcpy(data_ + pos_, b, n);
    pos_ += n;
  }
  uint8_t* data_;
  size_t size_;
  size_t pos_ = 0;
  bool ok_ = true;
};

class ByteReader {
 public:
  ByteReader(const uint8_t* data, size_t size) : data_(data), size_(size) {}

  uint8_t u8() { uint8_t v = 0; get(&v, 1); return v; }
  // Reads one byte that must be 0 or 1; anything else marks the reader bad.
  bool boolean() {
    uint8_t v = u8();
    if (v > 1) ok_ = false;
    return v == 1;
  }
  uint16_t be16() { uint8_t b[2] = {}; get(b, 2); return uint16_t(b[0] << 8 | b[1]); }
  uint32_t be32() {
    uint8_t b[4] = {};
    get(b, 4);
    return uint32_t(b[0]) << 24 | uint32_t(b[1]) << 16 | uint32_t(b[2]) << 8 | uint32_t(b[3]);
  }
  uint64_t be64() { uint64_t hi = be32(); return hi << 32 | be32(); }
  double f64() {
    uint8_t b[8] = {};
    get(b, 8);
    uint64_t bits = 0;
    for (int i = 7; i >= 0; --i) bits = bits << 8 | b[i];
    return std::bit_cast<double>(bits);
  }
  template <size_t N>
  void f64s(std::array<double, N>& a) { for (double& v : a) v = f64(); }
  template <size_t N>
  void bools(std::array<bool, N>& a) { for (bool& v : a) v = boolean(); }
  // Reads an enum stored as uint8 whose valid values are 0..max_value.
  template <class E>
  E enum8(uint8_t max_value) {
    uint8_t v = u8();
    if (v > max_value) ok_ = false;
    return static_cast<E>(v);
  }

  bool ok() const { return ok_; }
  size_t remaining() const { return size_ - pos_; }
  bool atEnd() const { return pos_ == size_; }

 private:
  void get(uint8_t* b, size_t n) {
    if (!ok_ || pos_ + n > size_) { ok_ = false; return; }
    std::memcpy(b, data_ + pos_, n);
    pos_ += n;
  }
  const uint8_t* data_;
  size_t size_;
  size_t pos_ = 0;
  bool ok_ = true;
};

}  // namespace xmate::protocol
